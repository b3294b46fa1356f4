// The CVT's site triangulation kept from one evaluation to the next: after the sites move it must
// again be a triangulation (every triangle counter-clockwise, every site in one) whose edges are
// all locally Delaunay, whether it was repaired by flips or rebuilt.
#include "cvt/site_delaunay.h"

#include <acute/predicates/predicates.h>

#include <gtest/gtest.h>

#include <algorithm>
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

}  // namespace
}  // namespace acute
