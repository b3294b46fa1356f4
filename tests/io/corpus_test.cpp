// Every real input we ship or share reads and validates.
#include "io/io_test_util.h"
#include "support/paths.h"

#include <acute/io/io.h>

#include <gtest/gtest.h>

#include <iostream>

using namespace acute;
using acute::test::files_in;

namespace {
const std::string kMeshes = acute::test::meshes_dir();

void expect_domains_load(const std::vector<std::string>& files) {
  for (const auto& path : files) {
    try {
      std::vector<std::string> warnings;
      const Domain d = io::read_domain(path, [&](const std::string& w) { warnings.push_back(w); });
      EXPECT_GT(d.points.size(), 0u) << path;
      EXPECT_GT(d.segments.size(), 0u) << path;
      EXPECT_NO_THROW(io::validate_domain(d)) << path;
      for (const auto& w : warnings) EXPECT_NE(w.find(path), std::string::npos) << path << ": warning without file: " << w;
    } catch (const std::exception& e) {
      ADD_FAILURE() << path << ": " << e.what();
    }
  }
}
}  // namespace

TEST(Corpus, bundled_poly_and_cgshop_domains_validate) {
  const auto polys = files_in(kMeshes, {".poly"});
  EXPECT_EQ(polys.size(), 28u) << "24 classic + 3 hand-made + 1 generated (zoo) domains in " << kMeshes;
  expect_domains_load(polys);
  const auto cgshop = files_in(kMeshes + "/cgshop", {".json"});
  EXPECT_EQ(cgshop.size(), 14u) << "one small instance per class and nine regression instances (meshes/SOURCES.md)";
  expect_domains_load(cgshop);
}

TEST(Corpus, bundled_meshes_read_and_their_domains_validate) {
  const auto meshes = files_in(kMeshes, {".off", ".obj"});
  EXPECT_EQ(meshes.size(), 9u) << kMeshes;
  for (const auto& path : meshes) {
    try {
      const Mesh m = io::read_mesh(path);
      EXPECT_GT(m.n_faces(), 0u) << path;
      for (auto vh : m.vertices()) EXPECT_EQ(m.point(vh)[2], 0.0) << path << ": vertex " << vh.idx();
    } catch (const std::exception& e) {
      ADD_FAILURE() << path << ": " << e.what();
    }
  }
  expect_domains_load(meshes);
}

TEST(Corpus, shared_classic_domains_validate) {
  const auto files = files_in(test::shared_path("domains/classic"), {".poly"});
  if (files.empty()) GTEST_SKIP() << "no shared domains at " << acute::test::shared_dir();
  EXPECT_EQ(files.size(), 24u);
  expect_domains_load(files);
}

TEST(Corpus, shared_cgshop_instances_validate) {
  auto files = files_in(test::shared_path("domains/cgshop2025/instances"), {".json"});
  if (files.empty()) GTEST_SKIP() << "no shared instances at " << acute::test::shared_dir();
  EXPECT_EQ(files.size(), 150u);
  const auto examples = files_in(test::shared_path("domains/cgshop2025/examples"), {".json"});
  files.insert(files.end(), examples.begin(), examples.end());
  expect_domains_load(files);
}

TEST(Corpus, shared_meshes_read) {
  auto files = files_in(test::shared_path("domains/meshes"), {".off", ".obj"});
  if (files.empty()) GTEST_SKIP() << "no shared meshes at " << acute::test::shared_dir();
  EXPECT_EQ(files.size(), 9u);
  const auto originals = files_in(test::shared_path("domains/meshes/originals"), {".node"});
  files.insert(files.end(), originals.begin(), originals.end());
  for (const auto& path : files) {
    try {
      const Mesh m = io::read_mesh(path);
      EXPECT_GT(m.n_faces(), 0u) << path;
    } catch (const std::exception& e) {
      ADD_FAILURE() << path << ": " << e.what();
    }
  }
}

// Not an assertion: tells the CDT engineer which inputs have points inside segments.
TEST(Corpus, report_points_on_segments) {
  std::vector<std::string> files = files_in(kMeshes, {".poly"});
  const auto cg = files_in(test::shared_path("domains/cgshop2025/instances"), {".json"});
  files.insert(files.end(), cg.begin(), cg.end());
  std::size_t n_files = 0, n_total = 0;
  for (const auto& path : files) {
    const auto found = io::find_points_on_segments(io::read_domain(path, [](const std::string&) {}));
    if (found.empty()) continue;
    ++n_files;
    n_total += found.size();
    std::cout << "[ points on segments ] " << path << ": " << found.size() << " (first: point " << found[0].point
              << " in segment " << found[0].segment << ")\n";
  }
  std::cout << "[ points on segments ] " << n_total << " in " << n_files << " of " << files.size() << " files\n";
}
