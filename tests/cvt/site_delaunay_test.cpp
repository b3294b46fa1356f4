// The CVT's site triangulation kept from one evaluation to the next: after the sites move it must
// again be a triangulation (every triangle counter-clockwise, every site in one) whose edges are
// all locally Delaunay, whether it was repaired by flips or rebuilt.
#include "cvt/site_delaunay.h"

#include "cvt/cvt_domains.h"

#include <acute/delaunay/cdt.h>
#include <acute/mesh/geometry.h>

#include <acute/predicates/predicates.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace acute {
namespace {

void expect_locally_delaunay_triangulation(const detail::SiteDelaunay& dt, const std::vector<Point2>& p) {
  std::vector<int> has(p.size(), 0);
  const auto& tri = dt.triangles();
  const auto n = static_cast<int>(p.size());
  ASSERT_EQ(dt.num_sites(), p.size());
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const auto& v = tri[t];
    for (int i = 0; i < 3; ++i)
      if (v[i] < n) has[static_cast<std::size_t>(v[i])] = 1;
    if (std::max({v[0], v[1], v[2]}) >= n) continue;  // a frame triangle
    ASSERT_EQ(predicates::orient2d(p[v[0]], p[v[1]], p[v[2]]), Sign::Positive) << "triangle " << t;
    for (int i = 0; i < 3; ++i) {
      const int u = dt.across(static_cast<int>(t), i);
      if (u < 0) continue;
      const auto& w = tri[static_cast<std::size_t>(u)];
      if (std::max({w[0], w[1], w[2]}) >= n) continue;
      int j = 0;
      while (w[j] == v[(i + 1) % 3] || w[j] == v[(i + 2) % 3]) ++j;
      EXPECT_NE(predicates::incircle(p[v[0]], p[v[1]], p[v[2]], p[w[j]]), Sign::Positive) << "edge of triangle " << t;
    }
  }
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_TRUE(has[i]) << "site " << i << " is in no triangle";
}

// Sites along a slanted straight segment (rounded, so only nearly collinear) on the hull and a
// lattice above it; the segment's sites then slide along it, as the CVT moves them, and their
// slivers turn over.
TEST(SiteDelaunay, sites_sliding_along_a_slanted_hull_segment_keep_a_valid_triangulation) {
  const Point2 a(0.1, -0.629607), b(0.7, -0.41);
  const Point2 u = b - a;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  const int on_segment = 40;
  std::vector<Point2> points;
  std::vector<double> t0;
  for (int i = 0; i <= on_segment; ++i) {
    t0.push_back(static_cast<double>(i) / on_segment);
    points.push_back(a + t0.back() * u);
  }
  for (int r = 1; r <= 6; ++r)
    for (int i = 0; i <= 12; ++i) points.emplace_back(0.1 + 0.05 * i + 0.01 * r, -0.629607 + 0.06 * r + 0.3 * 0.05 * i);
  detail::SiteDelaunay dt;
  dt.update(points, false);
  expect_locally_delaunay_triangulation(dt, points);
  for (int trial = 0; trial < 200; ++trial) {
    // The inner sites of the segment slide by up to 0.3 of their spacing (never past each other).
    for (int i = 1; i < on_segment; ++i) points[static_cast<std::size_t>(i)] = a + (t0[static_cast<std::size_t>(i)] + jitter(rng) / on_segment) * u;
    dt.update(points, true);
    expect_locally_delaunay_triangulation(dt, points);
  }
  // Every move is repaired by flips: without the frame, the segment's hull slivers turn over and
  // force a rebuild.
  EXPECT_EQ(dt.rebuilds(), 1u);
}

// Two long straight rows of sites (the walls of a strip, every site on the hull): the frame
// vertices then neighbour tens of thousands of sites. The triangulation is valid and each triangle's
// neighbour across an edge holds that edge (the adjacency search looked through the frame vertex's
// whole list for every hull edge: quadratic, minutes at this size).
TEST(SiteDelaunay, long_straight_hull_rows_link_every_edge_to_its_twin) {
  std::vector<Point2> points;
  const int n = 20000;
  for (int i = 0; i < n; ++i) points.emplace_back(5.0, 2.0 + 6.0 * i / n);
  for (int i = 0; i < n; ++i) points.emplace_back(5.00001, 2.0 + 6.0 * (i + 0.5) / n);
  detail::SiteDelaunay dt;
  dt.update(points, false);
  expect_locally_delaunay_triangulation(dt, points);
  const auto& tri = dt.triangles();
  for (std::size_t t = 0; t < tri.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int u = dt.across(static_cast<int>(t), i);
      if (u < 0) continue;
      const auto& w = tri[static_cast<std::size_t>(u)];
      const int a = tri[t][(i + 1) % 3], b = tri[t][(i + 2) % 3];
      int j = 0;
      while (j < 3 && w[j] != b) ++j;
      ASSERT_LT(j, 3) << "triangle " << t;
      ASSERT_EQ(w[(j + 1) % 3], a) << "triangle " << t;
    }
}

/// A constrained Delaunay mesh of the wedge with a hole and random interior points: its sites (in
/// vertex order) and its faces and border as a seed.
struct SeededWedge {
  std::vector<Point2> sites;
  detail::SiteDelaunay::Seed seed;
};

SeededWedge seeded_wedge() {
  Domain d = test::wedge_with_hole();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 400; ++k) {
    // Uniform in the 40-degree wedge of radius 4, outside the square hole.
    const double r = 4 * std::sqrt(u(rng)) * 0.98, a = 0.698131700797732 * (0.01 + 0.98 * u(rng));
    const Point2 p(r * std::cos(a), r * std::sin(a));
    if (p.x() > 2.35 && p.x() < 2.85 && p.y() > 0.45 && p.y() < 0.95) continue;
    d.points.push_back(p);
  }
  const Mesh mesh = build_cdt(d);
  SeededWedge w;
  for (auto vh : mesh.vertices()) w.sites.push_back(point2(mesh, vh));
  for (auto fh : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (auto h : mesh.fh_range(fh)) {
      t[static_cast<std::size_t>(k++)] = mesh.from_vertex_handle(h).idx();
      if (mesh.is_boundary(mesh.opposite_halfedge_handle(h))) w.seed.border.push_back({mesh.from_vertex_handle(h).idx(), mesh.to_vertex_handle(h).idx()});
    }
    w.seed.triangles.push_back(t);
  }
  return w;
}

// A mesh region (here a whole domain with a hole and a concave corner) seeds the triangulation:
// its border is triangulated out to the frame and the whole flipped Delaunay, the same
// triangulation as one built from scratch (as many triangles, every edge locally Delaunay).
TEST(SiteDelaunay, a_constrained_mesh_seeds_the_delaunay_triangulation_of_its_vertices) {
  const SeededWedge w = seeded_wedge();
  detail::SiteDelaunay seeded, scratch;
  seeded.update(w.sites, false, &w.seed);
  scratch.update(w.sites, false);
  EXPECT_EQ(seeded.seeded_builds(), 1u);
  EXPECT_EQ(scratch.seeded_builds(), 0u);
  expect_locally_delaunay_triangulation(seeded, w.sites);
  EXPECT_EQ(seeded.triangles().size(), scratch.triangles().size());
}

// A seed that is no region's border (an edge missing, a triangle missing, an edge crossing
// others) is refused: the triangulation is built from scratch, as Delaunay as ever.
TEST(SiteDelaunay, an_inconsistent_seed_falls_back_to_a_build_from_scratch) {
  for (int defect = 0; defect < 3; ++defect) {
    SeededWedge w = seeded_wedge();
    if (defect == 0) w.seed.border.pop_back();
    if (defect == 1) w.seed.triangles.pop_back();
    if (defect == 2) w.seed.border.push_back({w.seed.border.front()[0], w.seed.border[w.seed.border.size() / 2][0]});
    detail::SiteDelaunay dt;
    dt.update(w.sites, false, &w.seed);
    EXPECT_EQ(dt.seeded_builds(), 0u) << "defect " << defect;
    EXPECT_EQ(dt.rebuilds(), 1u);
    expect_locally_delaunay_triangulation(dt, w.sites);
  }
}

}  // namespace
}  // namespace acute
