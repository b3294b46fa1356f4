#include <acute/mesh/geometry.h>
#include <acute/mesher.h>
#include <acute/ops/insert.h>
#include <acute/repair/angle_bounds.h>
#include <acute/repair/relocation.h>

#include "repair/hub_ring.h"
#include "repair/polar_fan.h"
#include "repair/region.h"
#include "support/region_verify.h"
#include "support/wedge_domains.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace acute {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStrip = 30 * kPi / 180;  // the min bound: sectors narrower are strips

using test::cvt_mesh;
using test::polar;
using test::vertex_at;

/// A hub on a straight boundary (as at la's (16.07, 0)): two interior segments leave the boundary
/// vertex (0, 0) at 5 and 6 degrees below it, so the vertex has two strips and a 169-degree sector.
Domain hub_on_a_wall() {
  Domain d;
  d.points = {Point2(-10, -6), Point2(10, -6), Point2(10, 0), Point2(0, 0), Point2(-10, 0), polar(8, -5), polar(8, 186)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 0}, {3, 5}, {3, 6}};
  return d;
}

/// The largest angle of every triangle at vh.
std::vector<double> max_angles_at(const Mesh& mesh, VertexHandle vh) {
  std::vector<double> out;
  for (auto fh : mesh.vf_range(vh)) {
    const auto p = face_points(mesh, fh);
    const auto a = angles_deg(p[0], p[1], p[2]);
    out.push_back(std::max({a[0], a[1], a[2]}));
  }
  return out;
}

/// The region copy around the hub at the origin that the repair's pre-pass takes.
struct HubRegion {
  Mesh mesh;
  detail::Region region;
  VertexHandle apex;  ///< in region.sub
  double area = 0;
};

HubRegion hub_region(std::size_t vertices) {
  HubRegion h;
  h.mesh = cvt_mesh(hub_on_a_wall(), vertices);
  h.area = test::total_area(h.mesh);
  const VertexHandle apex = vertex_at(h.mesh, Point2(0, 0));
  const auto forced = forced_corner_vertices(h.mesh, 30);
  const double reach = detail::hub_ring_reach(h.mesh, apex, kStrip);
  EXPECT_GT(reach, 0) << "the hub has a wide sector beside a strip";
  EXPECT_TRUE(detail::extract_region(h.mesh, vertices_near(h.mesh, apex, 1.6 * reach), forced, h.region));
  h.apex = vertex_at(h.region.sub, Point2(0, 0));
  return h;
}

TEST(HubRing, only_wide_sectors_beside_strips_get_one) {
  const Mesh hub = cvt_mesh(hub_on_a_wall(), 800);
  EXPECT_GT(detail::hub_ring_reach(hub, vertex_at(hub, Point2(0, 0)), kStrip), 0);
  // The sharp corner of a plain wedge has no wide sector; a 40-degree pair of sectors has no strip.
  const Mesh wedge = cvt_mesh(test::sharp_wedge(12), 400);
  EXPECT_EQ(detail::hub_ring_reach(wedge, vertex_at(wedge, Point2(0, 0)), kStrip), 0);
  const Mesh wide = cvt_mesh(test::wedge_between_segments(40), 600);
  EXPECT_EQ(detail::hub_ring_reach(wide, vertex_at(wide, Point2(0, 0)), kStrip), 0);
}

TEST(HubRing, strips_get_isosceles_apex_triangles_and_the_wide_sector_a_graded_ring) {
  for (std::size_t n : {800u, 4000u}) {
    SCOPED_TRACE(n);
    HubRegion h = hub_region(n);
    ASSERT_TRUE(h.apex.is_valid());
    Mesh sub = h.region.sub;
    ASSERT_TRUE(detail::rebuild_hub_ring(sub, h.apex, kStrip, kPi / 2));
    // Every triangle at the hub: no angle of 90 or more (the strips' apex triangles have base
    // angles of 87 and 87.5 degrees, the ring's are isosceles at least as wide).
    for (double a : max_angles_at(sub, h.apex)) EXPECT_LT(a, 90);
    // Next to each strip's wall the ring's first gap is a few strip angles, not the sector's spacing.
    const Point2 c = point2(sub, h.apex);
    std::vector<double> directions;
    for (auto w : sub.vv_range(h.apex)) directions.push_back(std::atan2(point2(sub, w).y() - c.y(), point2(sub, w).x() - c.x()) * 180 / kPi);
    std::sort(directions.begin(), directions.end());
    // Directions below the boundary, from -180 (the left wall) to 0: the left strip's wall at -174,
    // the right one's at -5, and the ring between.
    std::vector<double> below;
    for (double d : directions)
      if (d < 0 && d > -180 + 1e-9) below.push_back(d);
    ASSERT_GE(below.size(), 4u);
    EXPECT_NEAR(below.front(), -174, 1e-6);
    EXPECT_NEAR(below.back(), -5, 1e-6);
    EXPECT_LE(below[1] - below[0], 2.5 * 6);
    EXPECT_LE(below[below.size() - 1] - below[below.size() - 2], 2.5 * 5);
    // Back in the big mesh: valid, conforming, the same area.
    test::expect_commit_keeps_the_mesh(h.mesh, h.region, sub, h.area);
  }
}

TEST(HubRing, no_planned_gap_narrower_than_a_max_bound_below_90_allows) {
  // A 10.5-degree strip across one wall of a 41-degree sector (none across the other): 15.75 from
  // the strip's wall, 25.2 next to it, 28.6 from the far wall, scaled into 41 degrees: 9.3, 14.9
  // and 16.9. At max 90 that is the ring; at max 85 an apex gap of 9.3 leaves base angles of
  // 85.4, so the last gap planned goes: 15.8 and 25.2.
  const double deg = kPi / 180;
  const std::vector<double> at_90 = detail::plan_ring_gaps(41 * deg, 10.5 * deg, 0, detail::apex_gap_floor(90 * deg));
  ASSERT_EQ(at_90.size(), 3u);
  EXPECT_NEAR(at_90[0] / deg, 15.75 * 41 / 69.55, 1e-2);
  const std::vector<double> at_85 = detail::plan_ring_gaps(41 * deg, 10.5 * deg, 0, detail::apex_gap_floor(85 * deg));
  ASSERT_EQ(at_85.size(), 2u);
  for (double g : at_85) EXPECT_GE(g, 10.5 * deg);
  double sum = 0;
  for (double g : at_85) sum += g;
  EXPECT_NEAR(sum, 41 * deg, 1e-12);
  // The floor: 180 - 2 max with a 5% margin; nothing at 90.
  EXPECT_NEAR(detail::apex_gap_floor(85 * deg) / deg, 10.5, 1e-9);
  EXPECT_EQ(detail::apex_gap_floor(kPi / 2), 0);
  // At max 80 the floor is 21 degrees: a 30-degree sector keeps one gap, no ring.
  EXPECT_LT(detail::plan_ring_gaps(30 * deg, 10.5 * deg, 0, detail::apex_gap_floor(80 * deg)).size(), 2u);
}

/// A convex boundary corner at the origin (walls at -80 and -161 degrees) split by interior
/// segments at -81 and -116 degrees: a 1-degree strip along the boundary, a 35-degree sector
/// beside it (ringed) and a 45-degree one (it holds one triangle at the apex), as at a CG:SHOP
/// instance's 0.25-degree strip (exterior_150_fb998503).
Domain strip_beside_one_triangle_sectors() {
  Domain d;
  d.points = {Point2(0, 0), polar(10, -161), Point2(polar(10, -161).x(), -12), Point2(polar(10, -80).x(), -12), polar(10, -80),
              polar(8, -81), polar(8, -116)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 0}, {0, 5}, {0, 6}};
  return d;
}

TEST(HubRing, the_walls_of_narrow_sectors_beside_the_ring_start_at_the_strips_radius) {
  // The ring's thin apex triangles are Delaunay, as every triangle of a non-obtuse mesh is, only
  // when no vertex lies in their circumcircles (disks about as wide as the strip's apex radius):
  // the first vertices of the 35- and 45-degree sectors' walls move out to the strip's radius.
  for (std::size_t n : {800u, 4000u}) {
    SCOPED_TRACE(n);
    Mesh mesh = cvt_mesh(strip_beside_one_triangle_sectors(), n);
    const double area = test::total_area(mesh);
    const VertexHandle apex_big = vertex_at(mesh, Point2(0, 0));
    ASSERT_TRUE(apex_big.is_valid());
    const double reach = detail::hub_ring_reach(mesh, apex_big, kStrip);
    ASSERT_GT(reach, 0);
    detail::Region region;
    ASSERT_TRUE(detail::extract_region(mesh, vertices_near(mesh, apex_big, 1.6 * reach), forced_corner_vertices(mesh, 30), region));
    Mesh sub = region.sub;
    const VertexHandle apex = vertex_at(sub, Point2(0, 0));
    ASSERT_TRUE(apex.is_valid());
    ASSERT_TRUE(detail::rebuild_hub_ring(sub, apex, kStrip, kPi / 2));
    auto first_radius_towards = [&](double deg) {
      for (auto h : sub.voh_range(apex))
        if (is_constrained(sub, sub.edge_handle(h)) && point2(sub, sub.to_vertex_handle(h)).normalized().dot(polar(1, deg)) > 1 - 1e-9)
          return point2(sub, sub.to_vertex_handle(h)).norm();
      return 0.0;
    };
    const double r_strip = first_radius_towards(-81);
    ASSERT_GT(r_strip, 0);
    for (double deg : {-80.0, -116.0, -161.0}) EXPECT_GE(first_radius_towards(deg), 0.95 * r_strip) << deg;
    // No Steiner point left inside the strip nearer than its walls' first vertices.
    for (auto vh : sub.vertices()) {
      if (sub.status(vh).deleted() || sub.data(vh).kind != VertexKind::Free) continue;
      const Point2 p = point2(sub, vh);
      const double deg = std::atan2(p.y(), p.x()) * 180 / kPi;
      EXPECT_FALSE(deg > -81 && deg < -80 && p.norm() < r_strip) << p.transpose();
    }
    // The strip's apex triangle and the ring's: no angle of 90 or more. (The 45-degree sector may
    // keep a point just beyond its walls' radius, which the repair's relocation then moves.)
    for (auto fh : sub.vf_range(apex)) {
      const auto p = face_points(sub, fh);
      const Point2 centroid = (p[0] + p[1] + p[2]) / 3;
      if (std::atan2(centroid.y(), centroid.x()) * 180 / kPi < -116) continue;
      const auto a = angles_deg(p[0], p[1], p[2]);
      EXPECT_LT(std::max({a[0], a[1], a[2]}), 90) << p[0].transpose() << " | " << p[1].transpose() << " | " << p[2].transpose();
    }
    test::expect_commit_keeps_the_mesh(mesh, region, sub, area);
  }
}

TEST(EqualiseStripApexes, the_apex_triangles_become_isosceles_and_their_wall_vertices_stay) {
  HubRegion h = hub_region(2000);
  ASSERT_TRUE(h.apex.is_valid());
  Mesh sub = h.region.sub;
  detail::equalise_strip_apexes(sub, h.apex, kStrip);
  const auto forced = forced_corner_vertices(sub, 30);
  int strips = 0;
  std::vector<std::pair<VertexHandle, VertexHandle>> bases;  // of the strips' apex triangles
  for (auto fh : sub.vf_range(h.apex)) {
    const auto p = face_points(sub, fh);
    const auto a = angles_deg(p[0], p[1], p[2]);
    int walls = 0;  // of the face's two edges at the apex: both for a strip's apex triangle
    for (auto heh : sub.fh_range(fh))
      if (sub.from_vertex_handle(heh) == h.apex || sub.to_vertex_handle(heh) == h.apex) walls += is_constrained(sub, sub.edge_handle(heh));
    if (walls < 2) continue;
    ++strips;
    EXPECT_LT(std::max({a[0], a[1], a[2]}), 90);
    std::vector<VertexHandle> base;
    for (auto vh : sub.fv_range(fh)) {
      if (vh != h.apex) {
        EXPECT_TRUE(closes_strip_apex(sub, vh, forced, 30)) << "relocation leaves it where it is";
        base.push_back(vh);
      }
    }
    bases.push_back({base[0], base[1]});
  }
  EXPECT_EQ(strips, 2);
  // Still pinned once an edit has split the apex triangle's base (the strip is then a fan of two
  // triangles at the apex): la's apex triangle went obtuse that way.
  {
    Mesh split = sub;
    for (const auto& [b0, b1] : bases) {
      const auto heh = split.find_halfedge(b0, b1);
      ASSERT_TRUE(heh.is_valid());
      ASSERT_TRUE(split_edge(split, split.edge_handle(heh), 0.5 * (point2(split, b0) + point2(split, b1))).is_valid());
    }
    const auto split_forced = forced_corner_vertices(split, 30);
    for (const auto& [b0, b1] : bases)
      for (VertexHandle vh : {b0, b1}) {
        EXPECT_TRUE(closes_strip_apex(split, vh, split_forced, 30));
        const Point2 before = point2(split, vh);
        EXPECT_FALSE(relocate_for_angles(split, vh, AngleBounds{}, split_forced));
        EXPECT_EQ(point2(split, vh), before);
      }
  }
  // A wall vertex not at the hub moves freely.
  for (auto vh : sub.vertices()) {
    if (!sub.status(vh).deleted() && sub.data(vh).kind == VertexKind::OnSegment && !sub.find_halfedge(vh, h.apex).is_valid()) {
      EXPECT_FALSE(closes_strip_apex(sub, vh, forced, 30));
    }
  }
  test::expect_commit_keeps_the_mesh(h.mesh, h.region, sub, h.area);
}

/// The CVT start of a domain with a corner at the origin, and the region copy of every vertex
/// within `radius` of it (corners narrower than min_deg forced), as a cluster's search takes it.
struct OriginRegion {
  Mesh mesh;
  detail::Region region;
  Mesh sub;          ///< a working copy of region.sub
  VertexHandle apex;  ///< the origin in sub (invalid when something failed)
  double area = 0;
};

OriginRegion origin_region(const Domain& domain, std::size_t vertices, double radius, double min_deg = 30) {
  OriginRegion o;
  o.mesh = cvt_mesh(domain, vertices);
  o.area = test::total_area(o.mesh);
  const VertexHandle apex = vertex_at(o.mesh, Point2(0, 0));
  EXPECT_TRUE(apex.is_valid());
  if (!apex.is_valid()) return o;
  const bool extracted = detail::extract_region(o.mesh, vertices_near(o.mesh, apex, radius), forced_corner_vertices(o.mesh, min_deg), o.region);
  EXPECT_TRUE(extracted);
  if (!extracted) return o;
  o.sub = o.region.sub;
  o.apex = vertex_at(o.sub, Point2(0, 0));
  return o;
}

TEST(EqualiseStripApexes, outward_moves_the_nearer_wall_vertex_to_the_farther_radius) {
  // A 45-degree corner holds one triangle at its apex. Outward, the nearer of its walls' first
  // vertices is replaced by one at the farther's radius (inward, the farther would move in).
  OriginRegion o = origin_region(test::sharp_wedge(45), 400, 4.0);
  ASSERT_TRUE(o.apex.is_valid());
  Mesh& sub = o.sub;
  const VertexHandle apex = o.apex;
  auto first_radius_towards = [&](double deg) -> std::pair<HalfedgeHandle, double> {
    for (auto h : sub.voh_range(apex))
      if (is_constrained(sub, sub.edge_handle(h)) && point2(sub, sub.to_vertex_handle(h)).normalized().dot(polar(1, deg)) > 1 - 1e-9)
        return {h, point2(sub, sub.to_vertex_handle(h)).norm()};
    return {HalfedgeHandle(), 0.0};
  };
  // The 45-degree wall's first vertex made the nearer: cut at 0.9 of the smaller radius.
  const double r0 = first_radius_towards(0).second, r45 = first_radius_towards(45).second;
  ASSERT_GT(r0, 0);
  ASSERT_GT(r45, 0);
  ASSERT_TRUE(split_edge(sub, sub.edge_handle(first_radius_towards(45).first), polar(0.9 * std::min(r0, r45), 45)).is_valid());
  ASSERT_TRUE(detail::equalise_strip_apexes(sub, apex, 2 * kStrip, /*outward=*/true));
  EXPECT_NEAR(first_radius_towards(0).second, r0, 1e-12 * r0) << "the farther stays";
  EXPECT_NEAR(first_radius_towards(45).second, r0, 1e-12 * r0) << "the nearer moved out to its radius";
  test::expect_commit_keeps_the_mesh(o.mesh, o.region, sub, o.area);
}

TEST(ApexWithMiddlePoint, a_one_triangle_corner_between_interior_segments_gets_an_isosceles_apex_and_a_point_beyond) {
  // A 34-degree wedge between two interior segments holds one triangle at its apex. Beyond it, the
  // base vertices each need a third triangle on their straight side: a point on the bisector past
  // the apex triangle's base, joined to both. (Outward, first radii 1.5 times apart or more are
  // not equalised, and the candidate declines: here the CVT start's are 0.87 and 1.74.)
  for (bool outward : {false, true}) {
    SCOPED_TRACE(outward);
    OriginRegion o = origin_region(test::wedge_between_segments(34), 400, 4.0);
    ASSERT_TRUE(o.apex.is_valid());
    Mesh& sub = o.sub;
    const VertexHandle apex = o.apex;
    const std::size_t vertices_before = sub.n_vertices();
    if (!detail::apex_with_middle_point(sub, apex, kStrip, 2 * kStrip, outward)) {
      EXPECT_TRUE(outward) << "inward, the first radii are always equalised";
      continue;
    }
    // The wedge's one triangle at the apex: the face between the 0- and 34-degree spokes.
    FaceHandle apex_face;
    for (auto fh : sub.vf_range(apex)) {
      Point2 centre(0, 0);
      for (auto vh : sub.fv_range(fh)) centre += point2(sub, vh) / 3.0;
      const double deg = std::atan2(centre.y(), centre.x()) * 180 / kPi;
      if (deg > 0 && deg < 34) {
        EXPECT_FALSE(apex_face.is_valid()) << "one triangle in the wedge";
        apex_face = fh;
      }
    }
    ASSERT_TRUE(apex_face.is_valid());
    std::vector<VertexHandle> base;
    for (auto vh : sub.fv_range(apex_face))
      if (vh != apex) base.push_back(vh);
    ASSERT_EQ(base.size(), 2u);
    const double r = point2(sub, base[0]).norm();
    EXPECT_NEAR(point2(sub, base[1]).norm(), r, 1e-12 * r) << "isosceles";
    // The new point: on the bisector, joined to both base vertices.
    ASSERT_GT(sub.n_vertices(), vertices_before);
    const VertexHandle middle(static_cast<int>(sub.n_vertices()) - 1);
    const Point2 q = point2(sub, middle);
    EXPECT_NEAR(std::atan2(q.y(), q.x()) * 180 / kPi, 17.0, 1e-9);
    EXPECT_GT(q.norm(), r);
    for (auto vh : base) EXPECT_TRUE(sub.find_halfedge(middle, vh).is_valid());
    test::expect_commit_keeps_the_mesh(o.mesh, o.region, sub, o.area);
  }
}

TEST(EqualiseStripApexes, strips_side_by_side_sharing_a_wall_all_end_isosceles) {
  // Three interior segments from the centre of a square at 0, 10 and 22 degrees: two strips share
  // the 10-degree wall (as in clusters.poly under a 35-degree bound). Removing one strip's far wall
  // vertex re-triangulates the apex's star, so the other strip's spokes must be found afresh.
  for (double strip_deg : {30.0, 35.0}) {
    for (std::size_t n : {600u, 2500u}) {
      SCOPED_TRACE(testing::Message() << strip_deg << " degrees, " << n << " vertices");
      Domain d = test::wedge_between_segments(10);
      d.points.push_back(polar(8, 22));
      d.segments.push_back({4, 7});
      OriginRegion o = origin_region(d, n, 3.0, strip_deg);
      ASSERT_TRUE(o.apex.is_valid());
      Mesh& sub = o.sub;
      const VertexHandle apex = o.apex;
      // The shared wall's first vertex made the far one of both strips (the other two walls cut at
      // 0.8 of its radius): each strip then removes it, and the second must not use the first's spokes.
      auto spoke_towards = [&](double deg) -> HalfedgeHandle {
        for (auto h : sub.voh_range(apex))
          if (is_constrained(sub, sub.edge_handle(h)) && point2(sub, sub.to_vertex_handle(h)).normalized().dot(polar(1, deg)) > 1 - 1e-9) return h;
        return HalfedgeHandle();
      };
      ASSERT_TRUE(spoke_towards(10).is_valid());
      const double r10 = point2(sub, sub.to_vertex_handle(spoke_towards(10))).norm();
      for (double deg : {0.0, 22.0}) {
        const HalfedgeHandle h = spoke_towards(deg);
        ASSERT_TRUE(h.is_valid());
        if (point2(sub, sub.to_vertex_handle(h)).norm() > 0.8 * r10) split_edge(sub, sub.edge_handle(h), 0.8 * r10 * polar(1, deg));
        ASSERT_NEAR(point2(sub, sub.to_vertex_handle(spoke_towards(deg))).norm(), 0.8 * r10, 1e-12 * r10);
      }
      EXPECT_TRUE(detail::equalise_strip_apexes(sub, apex, strip_deg * kPi / 180));
      int strips = 0;
      for (auto fh : sub.vf_range(apex)) {
        int walls = 0;
        for (auto heh : sub.fh_range(fh))
          if (sub.from_vertex_handle(heh) == apex || sub.to_vertex_handle(heh) == apex) walls += is_constrained(sub, sub.edge_handle(heh));
        if (walls < 2) continue;
        ++strips;
        const auto p = face_points(sub, fh);
        const auto a = angles_deg(p[0], p[1], p[2]);
        EXPECT_LT(std::max({a[0], a[1], a[2]}), 90);
      }
      EXPECT_EQ(strips, 2);
      test::expect_commit_keeps_the_mesh(o.mesh, o.region, sub, o.area);
    }
  }
}

}  // namespace
}  // namespace acute
