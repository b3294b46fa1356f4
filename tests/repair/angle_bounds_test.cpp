#include <acute/mesher.h>
#include <acute/repair/angle_bounds.h>
#include <acute/repair/clusters.h>

#include <gtest/gtest.h>

#include <cmath>

namespace acute {
namespace {

Domain wedge(double angle_deg) {
  Domain d;
  const double a = angle_deg * 3.14159265358979323846 / 180.0;
  d.points = {Point2(0, 0), Point2(10, 0), Point2(10 * std::cos(a), 10 * std::sin(a))};
  d.segments = {{0, 1}, {1, 2}, {2, 0}};
  return d;
}

TEST(AngleBounds, angles_of_a_30_60_90_triangle) {
  const auto a = angles_deg(Point2(0, 0), Point2(std::sqrt(3.0), 0), Point2(0, 1));
  EXPECT_NEAR(a[0], 90.0, 1e-12);
  EXPECT_NEAR(a[1], 30.0, 1e-12);
  EXPECT_NEAR(a[2], 60.0, 1e-12);
}

TEST(AngleBounds, narrow_input_corner_is_forced_and_wide_one_is_not) {
  const Mesh narrow = build_domain_cdt(wedge(20));
  const auto forced = forced_corner_vertices(narrow, 30);
  int n_forced = 0;
  for (auto vh : narrow.vertices())
    if (forced[static_cast<std::size_t>(vh.idx())]) {
      ++n_forced;
      EXPECT_EQ(point2(narrow, vh), Point2(0, 0)) << "vertex " << vh.idx();
    }
  EXPECT_EQ(n_forced, 1);
  const Mesh wide = build_domain_cdt(wedge(60));
  for (bool f : forced_corner_vertices(wide, 30)) EXPECT_FALSE(f);
}

/// The one triangle of a domain: the corner at the origin between legs of lengths 10 and `other`.
Mesh one_triangle(double angle_deg, double other = 10) {
  const double a = angle_deg * 3.14159265358979323846 / 180.0;
  Domain d;
  d.points = {Point2(0, 0), Point2(10, 0), Point2(other * std::cos(a), other * std::sin(a))};
  d.segments = {{0, 1}, {1, 2}, {2, 0}};
  return build_domain_cdt(d);
}

TEST(AngleBounds, an_input_corner_at_the_min_bound_to_rounding_is_not_asked_for_the_margin) {
  // 30 degrees from cos and sin (a few ulps off): the triangle's angle there is the input's.
  for (double other : {10.0, 9.0}) {  // angles 30, 75, 75 and 30, 63.9, 86.1
    const Mesh m = one_triangle(30, other);
    const auto forced = forced_corner_vertices(m, 30);
    EXPECT_FALSE(is_bad_triangle(m, *m.faces().begin(), AngleBounds{}, forced)) << other;
  }
}

TEST(AngleBounds, the_apex_triangle_of_an_unsatisfiable_sector_is_good_to_working_bounds_only_while_nearly_isosceles) {
  // An 8-degree corner under a max of 85: its triangle's base angles are at least 86 degrees.
  AngleBounds asked;
  asked.min_deg = 35, asked.max_deg = 85;
  AngleBounds working = asked;
  working.unsatisfiable_apex_slack_deg = 0.5;
  const Mesh isosceles = one_triangle(8), lopsided = one_triangle(8, 7);  // base angles 86 / 86; 80.6 / 91.4
  const auto forced = forced_corner_vertices(isosceles, asked.min_deg);
  EXPECT_TRUE(is_bad_triangle(isosceles, *isosceles.faces().begin(), asked, forced));
  EXPECT_FALSE(is_bad_triangle(isosceles, *isosceles.faces().begin(), working, forced));
  EXPECT_TRUE(is_bad_triangle(lopsided, *lopsided.faces().begin(), working, forced_corner_vertices(lopsided, asked.min_deg)));
  // A sector the bounds allow gets no slack: a 12-degree corner's base angles can be 84.
  const Mesh satisfiable = one_triangle(12, 9);
  EXPECT_TRUE(is_bad_triangle(satisfiable, *satisfiable.faces().begin(), working, forced_corner_vertices(satisfiable, asked.min_deg)));
}

TEST(AngleBounds, right_triangle_is_bad_for_strict_90) {
  Domain d;
  d.points = {Point2(0, 0), Point2(1, 0), Point2(0, 1)};
  d.segments = {{0, 1}, {1, 2}, {2, 0}};
  const Mesh mesh = build_domain_cdt(d);
  AngleBounds strict;
  strict.min_deg = 30;
  strict.max_deg = 90;
  const std::vector<bool> none(mesh.n_vertices(), false);
  ASSERT_EQ(mesh.n_faces(), 1u);
  EXPECT_TRUE(is_bad_triangle(mesh, *mesh.faces().begin(), strict, none));
  AngleBounds loose = strict;
  loose.max_deg = 90.001;
  EXPECT_FALSE(is_bad_triangle(mesh, *mesh.faces().begin(), loose, none));
  const auto clusters = find_clusters(mesh, strict, none);
  ASSERT_EQ(clusters.size(), 1u);
  EXPECT_EQ(clusters[0].vertices.size(), 3u);
}

}  // namespace
}  // namespace acute
