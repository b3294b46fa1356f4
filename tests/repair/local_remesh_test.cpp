#include <acute/mesh/geometry.h>
#include <acute/mesher.h>
#include <acute/repair/angle_bounds.h>

#include "repair/local_remesh.h"
#include "repair/region.h"
#include "support/mesh_verify.h"
#include "support/region_verify.h"
#include "support/wedge_domains.h"

#include <gtest/gtest.h>

#include <cmath>

namespace acute {
namespace {

using test::expect_commit_keeps_the_mesh;

constexpr double kPi = 3.14159265358979323846;

using test::cvt_mesh;
using test::polar;
using test::sharp_wedge;
using test::vertex_at;
using test::wedge_between_segments;

/// The square [0, 4]^2.
Domain square4() {
  Domain d;
  d.points = {Point2(0, 0), Point2(4, 0), Point2(4, 4), Point2(0, 4)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return d;
}

/// The region of every vertex closer than r to p.
detail::Region region_near(const Mesh& mesh, const Point2& p, double r) {
  std::vector<VertexHandle> movable;
  for (auto vh : mesh.vertices())
    if ((point2(mesh, vh) - p).norm() < r) movable.push_back(vh);
  detail::Region region;
  EXPECT_TRUE(detail::extract_region(mesh, movable, forced_corner_vertices(mesh, 30), region));
  return region;
}

std::size_t triangles_at(const Mesh& mesh, VertexHandle vh) {
  std::size_t n = 0;
  for (auto fh : mesh.vf_range(vh)) n += fh.is_valid();
  return n;
}

TEST(RebuildWedge, sharp_apex_gets_an_isosceles_triangle_and_three_triangles_at_its_base) {
  for (double apex_deg : {12.0, 20.0, 45.0}) {
    SCOPED_TRACE(apex_deg);
    Mesh mesh = cvt_mesh(sharp_wedge(apex_deg), 300);
    const double area = test::total_area(mesh);
    detail::Region region = region_near(mesh, Point2(0, 0), 3.0);
    Mesh sub = region.sub;
    const VertexHandle apex = vertex_at(sub, Point2(0, 0));
    ASSERT_TRUE(apex.is_valid());
    ASSERT_TRUE(detail::rebuild_wedge(sub, apex, 3));
    // One triangle at the apex; its base vertices are equally far and each has three triangles.
    ASSERT_EQ(triangles_at(sub, apex), 1u);
    const FaceHandle apex_face = *sub.vf_range(apex).begin();
    std::vector<VertexHandle> base;
    for (auto vh : sub.fv_range(apex_face))
      if (vh != apex) base.push_back(vh);
    ASSERT_EQ(base.size(), 2u);
    const double r0 = point2(sub, base[0]).norm(), r1 = point2(sub, base[1]).norm();
    EXPECT_NEAR(r0, r1, 1e-12 * r0);
    for (auto vh : base) EXPECT_EQ(triangles_at(sub, vh), 3u);
    expect_commit_keeps_the_mesh(mesh, region, sub, area);
  }
}

TEST(RebuildWedge, wide_corner_is_left_alone) {
  Mesh mesh = cvt_mesh(square4(), 200);
  detail::Region region = region_near(mesh, Point2(0, 0), 1.5);
  Mesh sub = region.sub;
  const VertexHandle corner = vertex_at(sub, Point2(0, 0));
  ASSERT_TRUE(corner.is_valid());
  EXPECT_FALSE(detail::rebuild_wedge(sub, corner, 3));
}

TEST(RebuildHub, wedge_between_interior_segments_gets_an_isosceles_apex) {
  for (double apex_deg : {8.0, 15.0}) {
    SCOPED_TRACE(apex_deg);
    Mesh mesh = cvt_mesh(wedge_between_segments(apex_deg), 400);
    const double area = test::total_area(mesh);
    detail::Region region = region_near(mesh, Point2(0, 0), 9.5);
    Mesh sub = region.sub;
    const VertexHandle apex = vertex_at(sub, Point2(0, 0));
    ASSERT_TRUE(apex.is_valid());
    ASSERT_TRUE(detail::rebuild_hub(sub, apex, 3));
    // The apex triangle inside the wedge (its base vertices on the two segments) is isosceles.
    std::size_t isosceles = 0;
    for (auto fh : sub.vf_range(apex)) {
      std::vector<Point2> base;
      for (auto vh : sub.fv_range(fh))
        if (vh != apex) base.push_back(point2(sub, vh));
      const double a0 = std::atan2(base[0].y(), base[0].x()) * 180 / kPi, a1 = std::atan2(base[1].y(), base[1].x()) * 180 / kPi;
      const bool in_wedge = std::abs(std::min(a0, a1)) < 1e-9 && std::abs(std::max(a0, a1) - apex_deg) < 1e-9;
      if (in_wedge) {
        ++isosceles;
        EXPECT_NEAR(base[0].norm(), base[1].norm(), 1e-12 * base[0].norm());
      }
    }
    EXPECT_EQ(isosceles, 1u) << "one triangle at the apex inside the wedge";
    expect_commit_keeps_the_mesh(mesh, region, sub, area);
  }
}

TEST(RemeshRegion, resampled_region_stays_valid_and_conforming) {
  Domain d;
  d.points = {Point2(0, 0), Point2(4, 0), Point2(4, 4), Point2(0, 4), Point2(1, 2), Point2(3, 2.5)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}};  // an interior segment crosses the region
  Mesh mesh = cvt_mesh(d, 400);
  const double area = test::total_area(mesh);
  detail::Region region = region_near(mesh, Point2(2, 2.25), 1.2);
  for (double scale : {1.0, 0.65}) {
    Mesh sub = region.sub;
    const double h = detail::movable_edge_median(sub);
    ASSERT_GT(h, 0);
    ASSERT_TRUE(detail::remesh_region(sub, scale * h, 7));
    Mesh big = mesh;
    expect_commit_keeps_the_mesh(big, region, sub, area);
    // Re-sampled at about the same spacing: the vertex count stays in proportion.
    EXPECT_LT(big.n_vertices(), mesh.n_vertices() * 3 / 2);
  }
}

TEST(RemeshRegion, spacing_far_below_the_region_is_refused_and_leaves_it_unchanged) {
  // The median edge of a cluster around a feature 1e-6 of its size: re-sampling the whole region
  // at that spacing meant millions of darts, each checked against every point (stress seed 158:
  // one repair iteration of 55 s under a 5 s time limit).
  Mesh mesh = cvt_mesh(square4(), 400);
  detail::Region region = region_near(mesh, Point2(2, 2), 1.2);
  Mesh sub = region.sub;
  const double h = detail::movable_edge_median(sub);
  ASSERT_GT(h, 0);
  EXPECT_FALSE(detail::remesh_region(sub, 1e-3 * h, 7));
  EXPECT_EQ(sub.n_vertices(), region.sub.n_vertices());
  EXPECT_TRUE(detail::remesh_region(sub, h, 7)) << "at its own spacing the region is re-sampled";
}

TEST(RemeshRegion, spacing_grades_down_to_an_input_point_close_to_a_segment) {
  // An input point 0.005 above the bottom side, in a region of spacing about 0.05: re-sampled at one
  // spacing, the side below it was divided at 0.05 and the point's triangles were flat (CG:SHOP
  // point-set_60_27bc003d: a point 1.5 above a wall, a remeshed region at spacing 110, one
  // 178-degree triangle). Graded, the point's edges are a few times its distance to the side.
  Domain d = square4();
  d.points.push_back(Point2(2, 0.005));
  Mesh mesh = cvt_mesh(d, 400);
  const double area = test::total_area(mesh);
  detail::Region region = region_near(mesh, Point2(2, 0.3), 0.6);
  Mesh sub = region.sub;
  const double h = detail::movable_edge_median(sub);
  ASSERT_GT(h, 0.04);
  ASSERT_TRUE(detail::remesh_region(sub, h, 7));
  const VertexHandle point = vertex_at(sub, Point2(2, 0.005));
  ASSERT_TRUE(point.is_valid());
  double longest = 0;
  for (auto w : sub.vv_range(point)) longest = std::max(longest, (point2(sub, w) - Point2(2, 0.005)).norm());
  EXPECT_LT(longest, 0.3 * h) << "spacing " << h;
  Mesh big = mesh;
  expect_commit_keeps_the_mesh(big, region, sub, area);
}

TEST(RepairAcute, sharp_wedges_meet_the_bounds) {
  for (double apex_deg : {8.0, 15.0, 25.0}) {
    SCOPED_TRACE(apex_deg);
    MeshOptions options;
    options.target_vertices = 400;
    // No clock: the result must not depend on the machine (sanitizer builds are ~50x slower).
    const MeshResult result = generate_mesh(sharp_wedge(apex_deg), options);
    EXPECT_EQ(result.status, MeshStatus::Ok);
    EXPECT_MESH_VALID(result.mesh);
  }
}

}  // namespace
}  // namespace acute
