// Convex-hull domains (Triangle -c): the hull edges that are no input segment bound the mesh as
// segments do. Regressions of issue #9, fuzz_mesher's hull_area_grows (offset 2^40) and
// hull_area_tiny_scale (scale 2^-20), as the readable .poly files of tests/fuzz/readable. Both
// have crossing segments (split), which the CVT start refuses, so the Delaunay refinement start
// is used; its Steiner points on the hull edges were free vertices at rounded midpoints that the
// repair then moved off the hull (mesh area 1.8 % and 0.16 % over the hull's).
#include <acute/io/io.h>
#include <acute/mesh/segments.h>
#include <acute/mesher.h>

#include "fuzz/fuzz_common.h"
#include "support/paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace acute {
namespace {

Domain read_readable(const std::string& name) {
  io::ReadOptions read;
  read.allow_crossing_segments = true;
  Domain d = io::read_poly(std::string(acute::test::test_data_dir()) + "/../fuzz/readable/" + name + ".poly", {}, read);
  d.convex_hull = true;
  return d;
}

/// Every boundary edge is constrained, and every vertex on it lies within kMaxSegmentDeviation
/// of its segment's exact line (the hull edge for the ids after the input segments).
std::string boundary_on_segments(const Mesh& mesh) {
  const SegmentTable& table = segment_table(mesh);
  for (auto eh : mesh.edges()) {
    if (!mesh.is_boundary(eh)) continue;
    const auto h = mesh.halfedge_handle(eh, 0);
    const Point2 p = point2(mesh, mesh.from_vertex_handle(h)), q = point2(mesh, mesh.to_vertex_handle(h));
    const int s = mesh.data(eh).segment;
    if (s < 0 || static_cast<std::size_t>(s) >= table.size())
      return "boundary edge " + acute_fuzz::str(p) + "-" + acute_fuzz::str(q) + " has segment id " + std::to_string(s);
    const auto& ends = table[static_cast<std::size_t>(s)];
    if (!close_enough_to_line(ends, p) || !close_enough_to_line(ends, q))
      return "boundary edge " + acute_fuzz::str(p) + "-" + acute_fuzz::str(q) + " off its segment's line (deviation " +
             acute_fuzz::num(std::max(line_deviation(ends, p), line_deviation(ends, q))) + ")";
  }
  return {};
}

/// As fuzz_mesher runs the pipeline (method acute, [30, 90), <= 4,000 vertices; the time limit is
/// only a safety net: the properties are asserted whatever stopped the run).
void expect_hull_kept(const std::string& name, std::size_t target) {
  const Domain d = read_readable(name);
  MeshOptions options;
  options.target_vertices = target;
  options.max_vertices = 4000;
  options.time_limit_s = 2;
  options.cdt.crossing = CrossingSegments::Split;
  const MeshResult r = generate_mesh(d, options);
  acute_fuzz::CdtCheckOptions check;
  check.convex_hull = true;
  check.delaunay = false;
  EXPECT_EQ(acute_fuzz::verify_cdt(r.mesh, d, check), "") << name;  // includes area = hull area (area_slack)
  EXPECT_EQ(boundary_on_segments(r.mesh), "") << name;
  const double want = 0.5 * acute_fuzz::hull_area2(d.points), got = mesh_area(r.mesh);
  EXPECT_LE(std::abs(got - want), acute_fuzz::area_slack(r.mesh, want)) << name << ": area " << got << " for a hull of " << want;
}

TEST(ConvexHull, hull_area_grows_far_from_origin_keeps_the_hull) { expect_hull_kept("hull_area_grows", 39); }

TEST(ConvexHull, hull_area_tiny_scale_keeps_the_hull) { expect_hull_kept("hull_area_tiny_scale", 115); }

// The layer where it went wrong: the CDT handed to refinement and repair has its hull edges as
// segments of their own (ids after the input segments, ends at input points).
TEST(ConvexHull, domain_cdt_constrains_the_hull_edges) {
  const Domain d = read_readable("hull_area_grows");
  CdtOptions o;
  o.crossing = CrossingSegments::Split;
  const Mesh cdt = build_domain_cdt(d, o);
  const SegmentTable& table = segment_table(cdt);
  std::size_t hull_segments = 0;
  for (auto eh : cdt.edges()) {
    if (!cdt.is_boundary(eh)) continue;
    const int s = cdt.data(eh).segment;
    ASSERT_GE(s, 0);
    ASSERT_LT(static_cast<std::size_t>(s), table.size());
    if (static_cast<std::size_t>(s) < d.segments.size()) continue;
    ++hull_segments;
    const auto h = cdt.halfedge_handle(eh, 0);
    EXPECT_EQ(table[static_cast<std::size_t>(s)][0], point2(cdt, cdt.from_vertex_handle(h)));
    EXPECT_EQ(table[static_cast<std::size_t>(s)][1], point2(cdt, cdt.to_vertex_handle(h)));
    EXPECT_TRUE(is_input(cdt, cdt.from_vertex_handle(h)) && is_input(cdt, cdt.to_vertex_handle(h)));
  }
  EXPECT_EQ(hull_segments, 5u);  // of the six hull sides only (6, 1)-(13, 1) is an input segment
  EXPECT_EQ(table.size(), d.segments.size() + hull_segments);
}

// The plain refinement method on a -c point set at 2^40 (no crossings, so nothing else is odd):
// its hull edge splits land on the hull edges' exact lines, and the area is the hull's exactly.
TEST(ConvexHull, refinement_of_a_point_set_far_from_origin_keeps_the_hull) {
  Domain d;
  d.name = "hull_points";
  d.convex_hull = true;
  const double o = 0x1p40;
  for (auto [x, y] : {std::pair{4, 9}, {14, 14}, {5, 2}, {13, 1}, {6, 1}, {11, 14}, {9, 11}, {7, 6}, {0, 2}, {13, 10}, {1, 2}})
    d.points.emplace_back(o + x, o + y);
  MeshOptions options;
  options.method = Method::Refine;
  options.target_vertices = 400;
  const MeshResult r = generate_mesh(d, options);
  EXPECT_GT(r.mesh.n_vertices(), d.points.size());
  EXPECT_EQ(boundary_on_segments(r.mesh), "");
  acute_fuzz::CdtCheckOptions check;
  check.convex_hull = true;
  check.delaunay = false;
  EXPECT_EQ(acute_fuzz::verify_cdt(r.mesh, d, check), "");
}

}  // namespace
}  // namespace acute
