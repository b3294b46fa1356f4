// build_cdt with CrossingSegments::Split on the saved reproducers (tests/data/regressions/
// cdt_split_*.poly) and on random crossing segments: the result is a CDT of the domain with every
// crossing as a vertex (rounded), checked by the fuzzers' independent verifier.
#include "fuzz/fuzz_common.h"
#include "support/paths.h"

#include <acute/core/errors.h>
#include <acute/delaunay/cdt.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace fs = std::filesystem;

namespace {

using acute::CdtOptions;
using acute::CdtStats;
using acute::CrossingSegments;
using acute::Domain;
using acute::Mesh;

// The reproducers repeat segments on purpose and cross them, which read_poly rejects (and drops
// repeats): read the sections verbatim. Indices as written (the files are 0-based).
Domain read_raw_poly(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    line = line.substr(0, line.find('#'));
    std::istringstream ls(line);
    std::vector<double> row;
    for (double v; ls >> v;) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  Domain d;
  d.name = file.filename().string();
  std::size_t r = 0;
  const auto n = static_cast<std::size_t>(rows.at(r++).at(0));
  for (std::size_t i = 0; i < n; ++i, ++r) d.points.emplace_back(rows.at(r).at(1), rows.at(r).at(2));
  const auto m = static_cast<std::size_t>(rows.at(r++).at(0));
  for (std::size_t i = 0; i < m; ++i, ++r) d.segments.push_back({static_cast<int>(rows.at(r).at(1)), static_cast<int>(rows.at(r).at(2))});
  const auto h = static_cast<std::size_t>(rows.at(r++).at(0));
  for (std::size_t i = 0; i < h; ++i, ++r) d.holes.emplace_back(rows.at(r).at(1), rows.at(r).at(2));
  return d;
}

std::string split_and_verify(const Domain& d, CdtStats* stats = nullptr) {
  CdtOptions o;
  o.crossing = CrossingSegments::Split;
  const Mesh m = acute::build_cdt(d, o, stats);
  acute_fuzz::CdtCheckOptions check;
  check.convex_hull = d.convex_hull;
  return acute_fuzz::verify_cdt(m, d, check);
}

class SplitRegression : public ::testing::TestWithParam<const char*> {};

TEST_P(SplitRegression, is_a_valid_cdt_with_every_segment_a_chain) {
  const fs::path file = fs::path(acute::test::test_data_dir()) / "regressions" / GetParam();
  Domain d = read_raw_poly(file);
  // The not-Delaunay case came from the fuzzer with Triangle -c; the others without.
  d.convex_hull = std::string(GetParam()).find("not_delaunay") != std::string::npos;
  CdtStats st;
  EXPECT_EQ(split_and_verify(d, &st), "") << d.name;
  EXPECT_GE(st.crossings_split, 1u) << d.name;
  // The other region rule: a valid CDT, or (no closed loop without -c) a clean InvalidInput.
  d.convex_hull = !d.convex_hull;
  try {
    EXPECT_EQ(split_and_verify(d), "") << d.name << " convex_hull " << d.convex_hull;
  } catch (const acute::InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("encloses no area"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Files, SplitRegression,
                         ::testing::Values("cdt_split_point_on_segment_skipped.poly", "cdt_split_repeated_segment_assertion.poly",
                                           "cdt_split_repeated_segment_not_delaunay.poly"));

// The fuzzer's domains at larger size: random segments on a small grid cross one another (often
// three at one point, rounded apart), pass through points and overlap. Each run is a valid CDT or
// a clean InvalidInput (the code before the fix failed on many; 30,000 such domains passed after).
TEST(SplitCrossings, random_grid_segments_give_valid_cdts) {
  std::mt19937 rng(7);
  int built = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int grid = 4 << (2 * (trial % 3));  // 4, 16, 64: many collinear and concurrent segments
    std::uniform_int_distribution<int> coord(0, grid - 1);
    Domain d;
    d.name = "random grid " + std::to_string(trial);
    d.convex_hull = trial % 2 == 0;
    const int n = 4 + trial % 28;
    for (int i = 0; i < n; ++i) d.points.emplace_back(coord(rng), coord(rng));
    for (int i = 0; i < n; ++i) {
      const int a = std::uniform_int_distribution<int>(0, n - 1)(rng), b = std::uniform_int_distribution<int>(0, n - 1)(rng);
      if (a != b) d.segments.push_back({a, b});
    }
    try {
      EXPECT_EQ(split_and_verify(d), "") << d.name;
      ++built;
    } catch (const acute::InvalidInput&) {
    }
  }
  EXPECT_GT(built, 450) << "too many domains rejected";
}

}  // namespace
