#include "io/io_test_util.h"
#include "support/paths.h"

#include <acute/io/io.h>
#include <acute/predicates/predicates.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace acute;
using acute::test::bad;
using acute::test::data;
using acute::test::expect_error;

namespace {
std::vector<std::string> collect_warnings(const std::function<void(const io::WarningSink&)>& f) {
  std::vector<std::string> warnings;
  f([&](const std::string& w) { warnings.push_back(w); });
  return warnings;
}
bool any_contains(const std::vector<std::string>& v, const std::string& piece) {
  for (const auto& s : v)
    if (s.find(piece) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST(ReadPoly, zero_based_with_comments_markers_attributes_and_regions) {
  Domain d;
  const auto warnings = collect_warnings([&](const io::WarningSink& w) { d = io::read_poly(data("zero_based.poly"), w); });
  ASSERT_EQ(d.points.size(), 4u);
  EXPECT_EQ(d.points[2], Point2(4, 4));
  EXPECT_EQ(d.point_markers, (std::vector<int>{1, 1, 2, 2}));
  ASSERT_EQ(d.segments.size(), 5u);
  EXPECT_EQ(d.segments[4], (std::array<int, 2>{0, 2})) << "0-based indices kept";
  EXPECT_EQ(d.segment_markers, (std::vector<int>{1, 1, 2, 2, 0}));
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_EQ(d.holes[0], Point2(3, 1));
  EXPECT_EQ(d.name, "zero_based");
  EXPECT_EQ(d.source_path, data("zero_based.poly"));
  EXPECT_FALSE(d.convex_hull);
  EXPECT_TRUE(any_contains(warnings, "2 regional attributes")) << "regions must be reported as ignored";
}

TEST(ReadPoly, one_based_classic_A) {
  const Domain d = io::read_poly(std::string(acute::test::meshes_dir()) + "/A.poly");
  EXPECT_EQ(d.points.size(), 29u);
  EXPECT_EQ(d.segments.size(), 29u);
  EXPECT_EQ(d.holes.size(), 1u);
  EXPECT_EQ(d.points[0], Point2(0.2, -0.7764)) << "vertex 1 of A.poly";
  EXPECT_EQ(d.segments[0], (std::array<int, 2>{28, 0})) << "segment 1 of A.poly is 29 1";
  EXPECT_EQ(d.name, "A");
}

TEST(ReadPoly, vertex_count_zero_reads_sibling_node) {
  const Domain d = io::read_poly(data("node_sibling.poly"));
  ASSERT_EQ(d.points.size(), 3u);
  EXPECT_EQ(d.points[1], Point2(2, 0));
  EXPECT_EQ(d.point_markers, (std::vector<int>{4, 4, 4}));
  EXPECT_EQ(d.segment_markers, (std::vector<int>{5, 5, 5}));
  EXPECT_EQ(d.segments[2], (std::array<int, 2>{2, 0}));
}

TEST(ReadPoly, missing_hole_section_warns) {
  // Written to the output dir: a triangle without the hole-count line (as fish.poly was published).
  const std::string path = test::output("no_holes_line.poly");
  std::ofstream(path) << "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n";
  Domain d;
  const auto warnings = collect_warnings([&](const io::WarningSink& w) { d = io::read_poly(path, w); });
  EXPECT_EQ(d.segments.size(), 3u);
  EXPECT_TRUE(any_contains(warnings, "no hole section")) << path;
}

TEST(ReadPoly, repeated_segment_dropped_with_warning) {
  const std::string path = test::output("repeated_segment.poly");
  std::ofstream(path) << "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 0\n1 1 2\n2 2 3\n3 3 1\n4 2 1\n0\n";
  Domain d;
  const auto warnings = collect_warnings([&](const io::WarningSink& w) { d = io::read_poly(path, w); });
  EXPECT_EQ(d.segments.size(), 3u);
  EXPECT_TRUE(any_contains(warnings, "segment 4 repeats segment 1")) << path;
}

TEST(ReadPoly, bad_inputs_name_file_line_and_problem) {
  struct Case {
    const char* file;
    std::vector<std::string> pieces;
  };
  const std::vector<Case> cases = {
      {"nan_coordinate.poly", {"nan_coordinate.poly:5:", "vertex 3 y", "not finite"}},
      {"huge_coordinate.poly", {"huge_coordinate.poly:3:", "point 2", "outside the exact range"}},
      {"bad_number.poly", {"bad_number.poly:3:", "'1.2.3' is not a number"}},
      {"index_out_of_range.poly", {"index_out_of_range.poly:13:", "segment 4 uses vertex 7", "6 vertices"}},
      {"crossing_segments.poly", {"crossing_segments.poly:11:", "segment 4 (points 4-1) crosses segment 2 (points 2-3)"}},
      {"overlapping_segments.poly", {"overlapping_segments.poly:13:", "segment 5 (points 5-2) overlaps segment 1"}},
      {"duplicate_points.poly", {"duplicate_points.poly:7:", "point 5 duplicates point 2", "(1, 0)"}},
      {"zero_length_segment.poly", {"zero_length_segment.poly:12:", "segment 5 has zero length", "point 3"}},
      {"truncated_segments.poly", {"truncated_segments.poly:", "expected 3 segments, file ends after 2"}},
  };
  for (const auto& c : cases) {
    try {
      io::read_poly(bad(c.file));
      ADD_FAILURE() << c.file << ": no exception";
    } catch (const InvalidInput& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << c.file;
      for (const auto& piece : c.pieces)
        EXPECT_NE(message.find(piece), std::string::npos) << c.file << ": '" << message << "' lacks '" << piece << "'";
    }
  }
}

TEST(ReadPoly, missing_sibling_node_is_an_io_error) {
  expect_error<IoError>([] { io::read_poly(bad("missing_node_file.poly")); }, {"missing_node_file.node", "cannot open"},
                        "missing_node_file.poly");
  expect_error<IoError>([] { io::read_poly(bad("does_not_exist.poly")); }, {"does_not_exist.poly"}, "does_not_exist.poly");
}

TEST(ReadCgshop, instance_fields_and_fractions) {
  const Domain d = io::read_cgshop(data("fractions.json"));
  EXPECT_EQ(d.instance_uid, "fractions");
  EXPECT_EQ(d.name, "fractions");
  ASSERT_EQ(d.points.size(), 5u);
  EXPECT_EQ(d.points[1].x(), 3.5);
  EXPECT_EQ(d.points[2].x(), 10.0 / 3.0) << "correctly rounded";
  EXPECT_EQ(d.points[3].x(), -1.0 / 3.0);
  EXPECT_EQ(d.points[3].y(), 1.0);
  // p/q with 200-bit p: the nearest double (checked with Python's Fraction), not float(p)/float(q).
  EXPECT_EQ(d.points[2].y(), 6.835549266092317e+23);
  EXPECT_EQ(d.points[4].x(), 9007199254740992.0) << "2^53+1 rounds to even";
  EXPECT_EQ(d.points[4].y(), -9007199254740996.0) << "-(2^53+3) rounds to even";
  ASSERT_EQ(d.segments.size(), 4u);
  EXPECT_EQ(d.segments[3], (std::array<int, 2>{3, 0})) << "region boundary closes";
}

TEST(ReadCgshop, bad_inputs) {
  expect_error<InvalidInput>([] { io::read_cgshop(bad("region_index_out_of_range.json")); },
                             {"region_index_out_of_range.json", "region_boundary[2] = 3 is out of range"},
                             "region_index_out_of_range.json");
  expect_error<InvalidInput>([] { io::read_cgshop(bad("not_json.json")); }, {"not_json.json", "not valid JSON"},
                             "not_json.json");
  expect_error<InvalidInput>([] { io::read_cgshop(bad("crossing_constraint.json")); },
                             {"crossing_constraint.json", "segment 5 (points 0-2) crosses segment 4 (points 4-5)"},
                             "crossing_constraint.json");
}

TEST(ReadDomain, dispatches_by_extension) {
  EXPECT_EQ(io::read_domain(data("zero_based.poly")).segments.size(), 5u);
  EXPECT_EQ(io::read_domain(data("fractions.json")).instance_uid, "fractions");
  expect_error<IoError>([] { io::read_domain(data("x.unknown")); }, {"x.unknown", "unknown domain format"}, "x.unknown");
  EXPECT_TRUE(io::is_mesh_path("a/b.OFF"));
  EXPECT_TRUE(io::is_mesh_path("b.1.ele"));
  EXPECT_FALSE(io::is_mesh_path("b.poly"));
  EXPECT_FALSE(io::is_mesh_path("dir.off/b"));
}

TEST(ReadDomain, mesh_boundary_becomes_segments_and_holes_get_seeds) {
  // square_circle_hole.1.off: the square with a polygonal circular hole, 135 boundary edges.
  const std::string path = std::string(acute::test::meshes_dir()) + "/square_circle_hole.1.off";
  const Domain d = io::read_domain(path);
  EXPECT_EQ(d.segments.size(), 135u) << path;
  EXPECT_EQ(d.points.size(), 135u) << path << ": boundary vertices only";
  ASSERT_EQ(d.holes.size(), 1u) << path;
  // The seed is strictly inside the hole: no mesh triangle contains it.
  const Mesh mesh = io::read_mesh(path);
  for (auto fh : mesh.faces()) {
    Point2 p[3];
    int k = 0;
    for (auto fv : mesh.fv_range(fh)) p[k++] = point2(mesh, fv);
    auto side = [&](int i) {
      const Point2 &a = p[i], &b = p[(i + 1) % 3];
      return (b - a).x() * (d.holes[0] - a).y() - (b - a).y() * (d.holes[0] - a).x();
    };
    EXPECT_FALSE(side(0) >= 0 && side(1) >= 0 && side(2) >= 0) << path << ": face " << fh.idx() << " holds the seed";
  }
}

TEST(ReadDomain, obj_polylines_become_interior_segments) {
  // tagged_polyline.obj: the 3 x 3 grid of [0,3]^2 with the polyline (1,1) - (2,2) - (1,2) tagged.
  const Domain d = io::read_domain(data("tagged_polyline.obj"));
  ASSERT_EQ(d.points.size(), 15u) << "12 boundary vertices and the polyline's 3 interior ones";
  ASSERT_EQ(d.segments.size(), 14u) << "12 boundary edges and 2 polyline edges";
  ASSERT_EQ(d.segment_markers.size(), d.segments.size());
  auto has_segment = [&](const Point2& a, const Point2& b) {
    for (const auto& s : d.segments)
      if ((d.points[s[0]] == a && d.points[s[1]] == b) || (d.points[s[0]] == b && d.points[s[1]] == a)) return true;
    return false;
  };
  EXPECT_TRUE(has_segment(Point2(1, 1), Point2(2, 2)));
  EXPECT_TRUE(has_segment(Point2(2, 2), Point2(1, 2)));
  // A tagged boundary edge is not a second segment (validate_domain would refuse a repeated one).
  const std::string path = test::output("tagged_boundary.obj");
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4\nf 1 4 3\nl 1 2\nl 1 4\n";
  const Domain e = io::read_domain(path);
  EXPECT_EQ(e.points.size(), 4u);
  EXPECT_EQ(e.segments.size(), 5u) << "4 boundary edges and the diagonal";
}

TEST(ReadDomain, point_set_node_file_means_convex_hull) {
  const std::string path = test::output("points_only.node");
  std::ofstream(path) << "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n";
  const Domain d = io::read_domain(path);
  EXPECT_EQ(d.points.size(), 3u);
  EXPECT_TRUE(d.segments.empty());
  EXPECT_TRUE(d.convex_hull) << path;
}

TEST(ReadDomain, hole_seed_avoids_an_island_inside_the_hole) {
  // A square ring [0,6]^2 minus [1,5]^2 with a triangular island in the hole, close to the corner
  // (1,1) where the seed search starts.
  const std::string path = test::output("ring_with_island.off");
  std::ofstream(path) << "OFF\n11 9 0\n0 0 0\n6 0 0\n6 6 0\n0 6 0\n1 1 0\n5 1 0\n5 5 0\n1 5 0\n"
                         "1.5 1.2 0\n3 1.5 0\n1.8 3 0\n"
                         "3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n3 8 9 10\n";
  const Domain d = io::read_domain(path);
  EXPECT_EQ(d.points.size(), 11u);
  EXPECT_EQ(d.segments.size(), 11u);
  ASSERT_EQ(d.holes.size(), 1u) << path << ": the island's outer loop is not a hole";
  const Point2 s = d.holes[0];
  EXPECT_TRUE(s.x() > 1 && s.x() < 5 && s.y() > 1 && s.y() < 5) << path << ": seed " << s.transpose();
  const Point2 tri[3] = {Point2(1.5, 1.2), Point2(3, 1.5), Point2(1.8, 3)};
  int inside = 0;
  for (int i = 0; i < 3; ++i)
    inside += predicates::orient2d(tri[i], tri[(i + 1) % 3], s) != Sign::Negative;
  EXPECT_LT(inside, 3) << path << ": seed " << s.transpose() << " is in the island";
}

// --split-crossings must be reachable from a file: the reader lets crossing segments through
// when asked (the CDT splits them), and rejects them otherwise.
TEST(ReadDomain, crossing_segments_pass_only_when_allowed) {
  const std::string path = acute::test::output("crossing_x.poly");
  {
    std::ofstream f(path);
    f << "4 2 0 0\n1 0 0\n2 2 2\n3 0 2\n4 2 0\n2 0\n1 1 2\n2 3 4\n0\n";
  }
  EXPECT_THROW(io::read_domain(path), InvalidInput);
  io::ReadOptions options;
  options.allow_crossing_segments = true;
  const Domain d = io::read_domain(path, {}, options);
  EXPECT_EQ(d.segments.size(), 2u);
}
