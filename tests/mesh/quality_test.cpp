#include "mesh/builders.h"

#include <acute/mesh/quality.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace acute {
namespace {

constexpr double kTol = 1e-9;

double expected_q(const Point2& a, const Point2& b, const Point2& c) {
  const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
  const double s = 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  const double p = 0.5 * (la + lb + lc), h = std::max({la, lb, lc});
  return 2.0 * std::sqrt(3.0) * s / (p * h);
}

Mesh single(const Point2& a, const Point2& b, const Point2& c) {
  return test::make_mesh({{a.x(), a.y()}, {b.x(), b.y()}, {c.x(), c.y()}}, {{0, 1, 2}});
}

TEST(TriangleAngles, sum_to_180_and_are_at_the_named_vertices) {
  const auto a = triangle_angles_deg({0, 0}, {std::sqrt(3.0), 0}, {0, 1});
  EXPECT_NEAR(a[0], 90, kTol);
  EXPECT_NEAR(a[1], 30, kTol);
  EXPECT_NEAR(a[2], 60, kTol);
  EXPECT_NEAR(a[0] + a[1] + a[2], 180, 1e-12);
}

TEST(MeasureQuality, equilateral) {
  const Point2 a(0, 0), b(1, 0), c(0.5, std::sqrt(3.0) / 2);
  const auto r = measure_quality(single(a, b, c));
  EXPECT_EQ(r.n_triangles, 1u);
  EXPECT_EQ(r.n_vertices, 3u);
  EXPECT_NEAR(r.min_angle, 60, kTol);
  EXPECT_NEAR(r.max_angle, 60, kTol);
  EXPECT_NEAR(r.q_min, 1.0, 1e-12);
  EXPECT_NEAR(r.q_mean, 1.0, 1e-12);
  EXPECT_EQ(r.n_below_min + r.n_above_max + r.n_right + r.n_obtuse + r.n_at_max + r.n_max_violations, 0u);
  EXPECT_EQ(r.std_min_angle, 0.0);
  EXPECT_FALSE(r.n_steiner.has_value()) << "no domain, no Steiner count";
  ASSERT_TRUE(r.free_min_angle.has_value());
  EXPECT_EQ(*r.free_min_angle, r.min_angle);
}

TEST(MeasureQuality, right_triangle_is_right_not_obtuse) {
  const Point2 a(0, 0), b(1, 0), c(0, 1);
  const auto r = measure_quality(single(a, b, c));
  EXPECT_NEAR(r.max_angle, 90, kTol);
  EXPECT_NEAR(r.min_angle, 45, kTol);
  EXPECT_EQ(r.n_right, 1u);
  EXPECT_EQ(r.n_obtuse, 0u);
  EXPECT_EQ(r.n_above_max, 0u) << "90 is not above the default max bound 90";
  EXPECT_EQ(r.n_at_max, 1u);
  EXPECT_EQ(r.n_max_violations, 1u) << "a right angle is not strictly below 90";
  EXPECT_NEAR(r.q_min, expected_q(a, b, c), 1e-15);
  QualityOptions loose;
  loose.max_angle_deg = 90.000001;
  const auto r2 = measure_quality(single(a, b, c), loose);
  EXPECT_EQ(r2.n_max_violations, 0u);
  EXPECT_EQ(r2.n_at_max, 0u);
  EXPECT_DOUBLE_EQ(r2.pct(1), 100.0);
}

TEST(MeasureQuality, obtuse_triangle) {
  const Point2 a(0, 0), b(2, 0), c(1, 0.2);
  const auto r = measure_quality(single(a, b, c));
  const double apex = 2 * std::atan2(1.0, 0.2) * 180 / M_PI;
  EXPECT_NEAR(r.max_angle, apex, 1e-9);
  EXPECT_EQ(r.n_obtuse, 1u);
  EXPECT_EQ(r.n_right, 0u);
  EXPECT_EQ(r.n_above_max, 1u);
  EXPECT_EQ(r.n_below_min, 1u);
  EXPECT_NEAR(r.q_mean, expected_q(a, b, c), 1e-15);
}

TEST(MeasureQuality, thirty_sixty_ninety_sits_on_the_bounds) {
  const Point2 a(0, 0), b(std::sqrt(3.0), 0), c(0, 1);
  QualityOptions opt;
  opt.histogram = true;
  const auto r = measure_quality(single(a, b, c), opt);
  EXPECT_NEAR(r.min_angle, 30, kTol);
  EXPECT_EQ(r.n_below_min, 0u) << "30 within 1e-9 counts as 30, not below";
  EXPECT_EQ(r.n_right, 1u);
  ASSERT_TRUE(r.has_histogram);
  EXPECT_EQ(r.histogram[3], 1u) << "30 goes to [30,40)";
  EXPECT_EQ(r.histogram[6], 1u) << "60 goes to [60,70)";
  EXPECT_EQ(r.histogram_right, 1u);
  std::size_t sum = r.histogram_right;
  for (auto n : r.histogram) sum += n;
  EXPECT_EQ(sum, 3u);
}

TEST(MeasureQuality, histogram_bins_and_statistics_of_a_mixed_mesh) {
  // Right isosceles (45, 45, 90), obtuse (about 11.3, 11.3, 157.4) and equilateral.
  const double h = std::sqrt(3.0) / 2;
  const Mesh m = test::make_mesh({{0, 0}, {1, 0}, {0, 1}, {3, 0}, {5, 0}, {4, 0.2}, {6, 0}, {7, 0}, {6.5, h}},
                                 {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
  QualityOptions opt;
  opt.histogram = true;
  const auto r = measure_quality(m, opt);
  EXPECT_EQ(r.n_triangles, 3u);
  EXPECT_EQ(r.n_vertices, 9u);
  const std::array<std::size_t, 18> expected{0, 2, 0, 0, 2, 0, 3, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0};
  for (int i = 0; i < 18; ++i) EXPECT_EQ(r.histogram[i], expected[i]) << "bin " << i;
  EXPECT_EQ(r.histogram_right, 1u);
  EXPECT_EQ(r.n_right, 1u);
  EXPECT_EQ(r.n_obtuse, 1u);
  EXPECT_EQ(r.n_below_min, 1u);
  EXPECT_NEAR(r.pct(r.n_obtuse), 100.0 / 3, 1e-12);
  const double small = std::atan2(0.2, 1.0) * 180 / M_PI;
  const double mins[3] = {45, small, 60}, maxs[3] = {90, 180 - 2 * small, 60};
  double mm = 0, mx = 0;
  for (int i = 0; i < 3; ++i) mm += mins[i] / 3, mx += maxs[i] / 3;
  double vm = 0;
  for (int i = 0; i < 3; ++i) vm += (mins[i] - mm) * (mins[i] - mm) / 3;  // population variance, as meshcheck
  EXPECT_NEAR(r.mean_min_angle, mm, 1e-9);
  EXPECT_NEAR(r.mean_max_angle, mx, 1e-9);
  EXPECT_NEAR(r.std_min_angle, std::sqrt(vm), 1e-9);
}

TEST(MeasureQuality, empty_mesh_has_zero_counts) {
  const auto r = measure_quality(Mesh());
  EXPECT_EQ(r.n_triangles, 0u);
  EXPECT_EQ(r.n_vertices, 0u);
  EXPECT_FALSE(r.free_min_angle.has_value());
}

// A 20-degree wedge (apex a) meshed with two Steiner points m (interior) and d (on segment bc).
struct Wedge {
  Domain domain;
  Mesh mesh;
  Wedge() {
    const double y = 10 * std::tan(10 * M_PI / 180);
    domain.points = {{0, 0}, {10, -y}, {10, y}};
    domain.segments = {{0, 1}, {1, 2}, {2, 0}};
    mesh = test::make_mesh({{0, 0}, {10, -y}, {10, y}, {5, 0}, {10, 0}}, {{0, 1, 3}, {0, 3, 2}, {3, 1, 4}, {3, 4, 2}});
  }
};

TEST(MeasureQuality, steiner_points_and_forced_corner_of_a_wedge) {
  const Wedge w;
  const auto r = measure_quality(w.mesh, {}, &w.domain);
  ASSERT_TRUE(r.n_steiner.has_value());
  EXPECT_EQ(*r.n_steiner, 2u);
  ASSERT_EQ(r.forced_corners.size(), 1u);
  EXPECT_EQ(r.forced_corners[0].point, 0);
  EXPECT_NEAR(r.forced_corners[0].angle_deg, 20, 1e-9);
  EXPECT_EQ(r.n_free_triangles, 2u);
  ASSERT_TRUE(r.free_min_angle.has_value());
  EXPECT_GT(*r.free_min_angle, r.min_angle) << "the 10-degree corners at the apex are excluded";
  EXPECT_EQ(r.n_below_min, 4u) << "10 degrees at the apex twice, about 19.4 at m twice";
  EXPECT_EQ(r.n_below_min_free, 2u);
}

TEST(ForcedCorners, mesh_based_and_domain_based_agree_on_a_wedge) {
  const Wedge w;
  for (double bound : {10.0, 20.0, 21.0, 30.0, 90.0}) {
    const auto a = forced_corners(w.domain, bound), b = forced_corners(w.domain, bound, w.mesh);
    ASSERT_EQ(a.size(), b.size()) << "bound " << bound;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].point, b[i].point) << "bound " << bound << " corner " << i;
      EXPECT_EQ(a[i].angle_deg, b[i].angle_deg) << "bound " << bound << " corner " << i;
    }
  }
  EXPECT_EQ(forced_corners(w.domain, 20.0).size(), 0u) << "20 within 1e-9 is not below 20";
  EXPECT_EQ(forced_corners(w.domain, 90.0).size(), 3u) << "20, 80, 80";
}

Domain square_with_wedge_loop(bool hole) {
  Domain d;
  const double y = 6 * std::tan(10 * M_PI / 180);
  d.points = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 5}, {8, 5 - y}, {8, 5 + y}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 4}};
  if (hole) d.holes = {{7, 5}};
  return d;
}

TEST(ForcedCorners, sector_inside_a_hole_is_not_forced) {
  EXPECT_EQ(forced_corners(square_with_wedge_loop(true), 30).size(), 0u);
}

TEST(ForcedCorners, filled_loop_without_hole_seed_forces_its_corner) {
  const auto f = forced_corners(square_with_wedge_loop(false), 30);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].point, 4);
  EXPECT_NEAR(f[0].angle_deg, 20, 1e-9);
}

TEST(ForcedCorners, open_segments_enclose_nothing) {
  Domain d;
  d.points = {{0, 0}, {10, 1}, {10, -1}};
  d.segments = {{0, 1}, {0, 2}};
  EXPECT_EQ(forced_corners(d, 30).size(), 0u);
}

TEST(UnsatisfiableSectors, none_at_the_default_bounds_and_a_narrow_corner_against_a_low_max) {
  const Wedge w;  // corners of 20, 80 and 80 degrees
  EXPECT_TRUE(unsatisfiable_sectors(w.domain, 30, 90).empty());
  EXPECT_TRUE(unsatisfiable_sectors(w.domain, 30, 85).empty()) << "20 > 180 - 2 * 85";
  // Max 79: the 20-degree corner's triangle keeps 160 degrees for two angles below 79; the
  // 80-degree corners are cut in two.
  const auto f = unsatisfiable_sectors(w.domain, 30, 79);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].point, 0);
  EXPECT_NEAR(f[0].angle_deg, 20, 1e-9);
  EXPECT_EQ(unsatisfiable_sectors(w.domain, 30, 80).size(), 1u) << "base angles of exactly 80 are not below 80";
  EXPECT_EQ(unsatisfiable_sectors(w.domain, 30, 80.001).size(), 0u);
}

TEST(UnsatisfiableSectors, close_bounds_leave_sectors_no_count_of_corners_fits) {
  // Bounds [50, 65): a triangle corner in (50, 65); 90 and 80 degrees are neither one corner nor
  // two; 340 and 280 are six and five; 20 is below 50 and not above 180 - 130.
  const auto f = unsatisfiable_sectors(square_with_wedge_loop(false), 50, 65);
  std::vector<int> points;
  for (const auto& c : f) points.push_back(c.point);
  std::sort(points.begin(), points.end());
  EXPECT_EQ(points, (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_TRUE(unsatisfiable_sectors(square_with_wedge_loop(true), 30, 90).empty());
}

TEST(ForcedCorners, repeated_points_and_split_segments) {
  // The wedge again, with the apex repeated and the long side given as one segment through a point.
  Domain d;
  const double y = 10 * std::tan(10 * M_PI / 180);
  d.points = {{0, 0}, {10, -y}, {10, y}, {0, 0}, {10, 0}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}};
  const auto f = forced_corners(d, 30);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].point, 0) << "the first of the repeated points";
  // Point 4 on segment 1-2 splits it: two 180-degree sectors, one inside.
  EXPECT_EQ(forced_corners(d, 180.5).size(), 4u) << "20, 80, 80 and the inside half-turn at point 4";
}

}  // namespace
}  // namespace acute
