#include "io/io_test_util.h"
#include "support/paths.h"

#include <acute/io/io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

using namespace acute;
using acute::test::output;

namespace {
// A small jittered grid mesh: coordinates with full 53-bit mantissas.
Mesh awkward_mesh() {
  Mesh m;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  const int n = 6;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) m.add_vertex(Mesh::Point((i + jitter(rng)) / 3.0, (j + jitter(rng)) / 7.0, 0.0));
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      m.add_face(VertexHandle(a), VertexHandle(b), VertexHandle(d));
      m.add_face(VertexHandle(a), VertexHandle(d), VertexHandle(c));
    }
  m.data(VertexHandle(7)).marker = 3;
  return m;
}

std::vector<Mesh::Point> live_points(const Mesh& m) {
  std::vector<Mesh::Point> out;
  for (auto vh : m.vertices()) out.push_back(m.point(vh));
  return out;
}
std::vector<std::array<Mesh::Point, 3>> live_faces(const Mesh& m) {
  std::vector<std::array<Mesh::Point, 3>> out;
  for (auto fh : m.faces()) {
    std::array<Mesh::Point, 3> f;
    int k = 0;
    for (auto fv : m.fv_range(fh)) f[k++] = m.point(fv);
    // rotate so the smallest point comes first (the start vertex of a face is not kept)
    const auto lo = std::min_element(f.begin(), f.end(), [](const auto& a, const auto& b) {
      return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
    });
    std::rotate(f.begin(), lo, f.end());
    out.push_back(f);
  }
  return out;
}

bool no_temp_files_left(const std::string& dir) {
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos) return false;
  return true;
}
}  // namespace

TEST(WriteMesh, round_trip_is_bit_exact_for_off_obj_and_node_ele) {
  const Mesh m = awkward_mesh();
  for (const char* name : {"round_trip.off", "round_trip.obj", "round_trip.node", "round_trip2.ele"}) {
    const std::string path = output(name);
    io::write_mesh(m, path);
    const Mesh back = io::read_mesh(path);
    EXPECT_EQ(live_points(back), live_points(m)) << name << ": coordinates must survive bit-exactly";
    EXPECT_EQ(live_faces(back), live_faces(m)) << name;
  }
  EXPECT_EQ(io::read_mesh(output("round_trip.ele")).data(VertexHandle(7)).marker, 3) << "node markers written";
  EXPECT_TRUE(std::ifstream(output("round_trip2.node")).good()) << "writing .ele also writes .node";
}

TEST(WriteMesh, extreme_magnitudes_round_trip) {
  Mesh m;
  const double xs[] = {1e-40, 3.0e40, -0.1, 2.0 / 3.0, std::nextafter(1.0, 2.0), 123456789.123456789};
  for (int i = 0; i < 6; ++i) m.add_vertex(Mesh::Point(xs[i], xs[5 - i] * (i % 2 ? -1 : 1), 0));
  for (const char* name : {"extreme.off", "extreme.obj", "extreme.node"}) {
    io::write_mesh(m, output(name));
    // A mesh of isolated vertices is read with a warning.
    const Mesh back = io::read_mesh(output(name), [](const std::string&) {});
    EXPECT_EQ(live_points(back), live_points(m)) << name;
  }
}

TEST(WriteMesh, skips_deleted_elements_and_renumbers) {
  Mesh m = awkward_mesh();
  m.delete_face(FaceHandle(0), true);  // also deletes vertex 0 (isolated afterwards)
  std::size_t live = 0;
  for (auto fh : m.faces()) live += fh.is_valid();
  io::write_mesh(m, output("deleted.off"));
  const Mesh back = io::read_mesh(output("deleted.off"));
  EXPECT_EQ(back.n_faces(), live);
  EXPECT_EQ(live_points(back), live_points(m));
  EXPECT_EQ(live_faces(back), live_faces(m));
}

TEST(WriteMesh, atomic_write_leaves_no_temp_file_and_replaces_target) {
  const std::string dir = output("atomic");
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/mesh.off";
  std::ofstream(path) << "old content\n";
  io::write_mesh(awkward_mesh(), path);
  EXPECT_TRUE(no_temp_files_left(dir)) << dir;
  std::ifstream in(path);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "OFF") << path;
  // A write that cannot happen throws IoError and leaves nothing behind.
  EXPECT_THROW(io::write_mesh(awkward_mesh(), dir + "/missing_dir/x.off"), IoError);
  EXPECT_THROW(io::write_mesh(awkward_mesh(), dir + "/x.stl"), IoError);
  EXPECT_TRUE(no_temp_files_left(dir)) << dir;
}

TEST(WriteSvg, legend_counts_and_fills) {
  // Two triangles: a right isosceles one (max angle 90 = violation of [30, 90)) and an acute needle.
  Mesh m;
  const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0}),
             d = m.add_vertex({3, 3, 0});  // apex angle 22.6 degrees, acute
  m.add_face(a, b, c);
  m.add_face(b, d, c);
  m.data(m.edge_handle(m.find_halfedge(a, b))).segment = 0;
  io::WriteOptions options;
  options.title = "two <triangles>";
  const std::string path = output("two.svg");
  io::write_mesh(m, path, options);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string svg = text.str();
  EXPECT_NE(svg.find("4 vertices, 2 triangles"), std::string::npos) << svg;
  EXPECT_NE(svg.find("two &lt;triangles&gt;"), std::string::npos) << "title escaped";
  EXPECT_NE(svg.find("\u2265 90.0\u00b0: 1 triangles"), std::string::npos) << "right triangle counted as a max violation";
  EXPECT_NE(svg.find("&lt; 30.0\u00b0: 1 triangles"), std::string::npos) << "needle counted below min";
  EXPECT_NE(svg.find("stroke=\"black\""), std::string::npos) << "constrained edge drawn bold";
  EXPECT_NE(svg.find("angles from "), std::string::npos);
}

namespace {
// The two triangles of legend_counts_and_fills: right isosceles (90, 45, 45) and an acute needle
// (22.6 at its apex, 78.7 twice).
Mesh right_and_needle() {
  Mesh m;
  const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0}),
             d = m.add_vertex({3, 3, 0});
  m.add_face(a, b, c);
  m.add_face(b, d, c);
  return m;
}

std::string slurp_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Sum of data-count over the bars of one kind ("" for all).
std::size_t bar_sum(const std::string& svg, const std::string& kind) {
  std::size_t sum = 0;
  const std::string key = "data-kind=\"";
  for (std::size_t at = svg.find("class=\"bar\""); at != std::string::npos; at = svg.find("class=\"bar\"", at + 1)) {
    const std::size_t k = svg.find(key, at) + key.size();
    const std::size_t n = svg.find("data-count=\"", at) + 12;
    if (kind.empty() || svg.compare(k, kind.size() + 1, kind + "\"") == 0) sum += std::stoul(svg.substr(n));
  }
  return sum;
}
}  // namespace

TEST(WriteHistogramSvg, bars_count_every_angle_by_kind) {
  const Mesh m = right_and_needle();
  io::WriteOptions options;
  options.title = "two & more";
  for (double bin : {5.0, 7.0, 180.0}) {
    options.histogram_bin_deg = bin;
    const std::string path = output("two_histogram.svg");
    io::write_angle_histogram_svg(m, path, options);
    const std::string svg = slurp_file(path);
    EXPECT_EQ(bar_sum(svg, ""), 6u) << "bin " << bin;
    EXPECT_EQ(bar_sum(svg, "large"), 1u) << "the exact right angle";
    EXPECT_EQ(bar_sum(svg, "small"), 1u) << "the needle's apex";
    EXPECT_EQ(bar_sum(svg, "ok"), 4u);
    EXPECT_NE(svg.find("two &amp; more"), std::string::npos) << "title escaped";
    EXPECT_EQ(std::count(svg.begin(), svg.end(), '<'), std::count(svg.begin(), svg.end(), '>')) << "balanced tags";
  }
  options.histogram_bin_deg = 0;
  EXPECT_THROW(io::write_angle_histogram_svg(m, output("bad_bin.svg"), options), InvalidInput);
  EXPECT_FALSE(std::filesystem::exists(output("bad_bin.svg")));
}

TEST(WriteSvg, vertex_labels_name_every_vertex) {
  const Mesh m = right_and_needle();
  io::WriteOptions options;
  options.vertex_labels = true;
  io::write_svg(m, output("two_labels.svg"), options);
  const std::string svg = slurp_file(output("two_labels.svg"));
  std::size_t circles = 0;
  for (std::size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(circles, 4u);
  for (const char* label : {">0</text>", ">1</text>", ">2</text>", ">3</text>"}) EXPECT_NE(svg.find(label), std::string::npos) << label;
  io::write_svg(m, output("two_nolabels.svg"));
  EXPECT_EQ(slurp_file(output("two_nolabels.svg")).find("<circle"), std::string::npos);
}

TEST(WriteSvg, large_mesh_stays_small) {
  const std::string path = std::string(acute::test::meshes_dir()) + "/greenland.off";
  const Mesh m = io::read_mesh(path);
  io::write_svg(m, output("greenland.svg"));
  const auto bytes = std::filesystem::file_size(output("greenland.svg"));
  EXPECT_LT(bytes, 200u * m.n_faces()) << "SVG of " << m.n_faces() << " triangles has " << bytes << " bytes";
}
