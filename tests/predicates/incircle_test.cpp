// incircle (filtered and exact stage) against the exact oracle on easy and adversarial inputs.
#include <gtest/gtest.h>

#include <acute/predicates/predicates.h>

#include <cmath>
#include <vector>

#include "predicates/test_inputs.h"
#include "support/exact_rational.h"

namespace acute::test {
namespace {

using predicates::incircle;

Sign expect_incircle_matches(const Point2& a, const Point2& b, const Point2& c, const Point2& d, const char* what) {
  const Sign truth = oracle_incircle(a, b, c, d);
  EXPECT_EQ(incircle(a, b, c, d), truth) << what << ": " << describe(a, b, c, d);
  EXPECT_EQ(predicates::detail::incircle_exact(a, b, c, d), truth) << what << " (exact stage): " << describe(a, b, c, d);
  return truth;
}

// The lifted 4x4 determinant is alternating: any transposition of the arguments flips the sign.
void expect_permutation_rules(const Point2& a, const Point2& b, const Point2& c, const Point2& d, const char* what) {
  const Sign s = incircle(a, b, c, d);
  EXPECT_EQ(incircle(b, c, a, d), s) << what << " bcad: " << describe(a, b, c, d);
  EXPECT_EQ(incircle(b, a, c, d), -s) << what << " bacd: " << describe(a, b, c, d);
  EXPECT_EQ(incircle(a, b, d, c), -s) << what << " abdc: " << describe(a, b, c, d);
  EXPECT_EQ(incircle(d, b, c, a), -s) << what << " dbca: " << describe(a, b, c, d);
  EXPECT_EQ(incircle(b, a, d, c), s) << what << " badc: " << describe(a, b, c, d);
}

// Integer points on the circle x^2 + y^2 = r^2.
std::vector<Point2> lattice_circle(int r) {
  std::vector<Point2> pts;
  for (int x = -r; x <= r; ++x) {
    const long long y2 = static_cast<long long>(r) * r - static_cast<long long>(x) * x;
    const auto y = static_cast<long long>(std::llround(std::sqrt(static_cast<double>(y2))));
    if (y * y != y2) continue;
    pts.emplace_back(x, y);
    if (y != 0) pts.emplace_back(x, -y);
  }
  return pts;
}

TEST(Incircle, documented_sign_conventions) {
  const Point2 a(1, 0), b(0, 1), c(-1, 0);  // counter-clockwise, unit circle
  EXPECT_EQ(incircle(a, b, c, {0, 0}), Sign::Positive) << "center of a ccw triangle's circle";
  EXPECT_EQ(incircle(a, b, c, {3, 3}), Sign::Negative) << "far outside";
  EXPECT_EQ(incircle(a, b, c, {0, -1}), Sign::Zero) << "on the circle";
  EXPECT_EQ(incircle(b, a, c, {0, 0}), Sign::Negative) << "clockwise triangle reverses the sign";
}

TEST(Incircle, random_points_match_exact_oracle) {
  Rng rng(11);
  for (int i = 0; i < 10000; ++i) {
    const Point2 a = random_in_box(rng, -1, 1), b = random_in_box(rng, -1, 1);
    const Point2 c = random_in_box(rng, -1, 1), d = random_in_box(rng, -1, 1);
    expect_incircle_matches(a, b, c, d, "random");
    expect_permutation_rules(a, b, c, d, "random");
  }
}

TEST(Incircle, cocircular_integer_points_are_exactly_zero) {
  Rng rng(12);
  for (const int r : {5, 25, 65, 325, 1105, 5525}) {
    const std::vector<Point2> circle = lattice_circle(r);
    ASSERT_GE(circle.size(), 12u) << "radius " << r;
    const auto pick = [&]() { return circle[static_cast<std::size_t>(uniform_int(rng, 0, int(circle.size()) - 1))]; };
    for (int i = 0; i < 400; ++i) {
      const Point2 center(uniform_int(rng, -100000, 100000), uniform_int(rng, -100000, 100000));
      const int s = uniform_int(rng, -140, 170);  // keeps every coordinate inside [2^-142, 2^201]
      const Point2 a = scaled(center + pick(), s), b = scaled(center + pick(), s);
      const Point2 c = scaled(center + pick(), s), d = scaled(center + pick(), s);
      EXPECT_EQ(incircle(a, b, c, d), Sign::Zero) << "radius " << r << ", 2^" << s << ": " << describe(a, b, c, d);
      expect_incircle_matches(a, b, c, d, "cocircular");
      // A few ulps off the circle: the sign now depends on the last bits.
      const Point2 moved = perturb(rng, d, 2);
      expect_incircle_matches(a, b, c, moved, "cocircular perturbed");
      expect_permutation_rules(a, b, c, moved, "cocircular perturbed");
    }
  }
}

TEST(Incircle, decimal_circle_points_match_exact_oracle) {
  // The lattice circle times 0.1: rounding makes the points almost, but not exactly, cocircular.
  Rng rng(13);
  const std::vector<Point2> circle = lattice_circle(1105);
  const auto pick = [&]() { return 0.1 * circle[static_cast<std::size_t>(uniform_int(rng, 0, int(circle.size()) - 1))]; };
  for (int i = 0; i < 5000; ++i) {
    const Point2 shift(uniform(rng, -1e3, 1e3), uniform(rng, -1e3, 1e3));
    expect_incircle_matches(pick() + shift, pick() + shift, pick() + shift, pick() + shift, "decimal circle");
  }
}

TEST(Incircle, ulp_grid_matches_exact_oracle) {
  // d walks a nextafter grid across the circle through (5,0), (0,5), (-5,0): around the lattice
  // points (3,4), (4,-3) (exactly on it) and around rounded, almost-on-circle points.
  int zeros = 0, positives = 0, negatives = 0;
  const Point2 a(5, 0), b(0, 5), c(-5, 0);
  for (const Point2& base : {Point2(3, 4), Point2(4, -3), Point2(std::sqrt(12.5), -std::sqrt(12.5)), Point2(3.3 / 1.1, 4.4 / 1.1),
                             Point2(1.4, -4.8)})
    for (int i = 0; i < 48; ++i)
      for (int j = 0; j < 48; ++j) {
        const Point2 d(ulps(base.x(), i - 24), ulps(base.y(), j - 24));
        const Sign s = expect_incircle_matches(a, b, c, d, "ulp grid");
        zeros += s == Sign::Zero;
        positives += s == Sign::Positive;
        negatives += s == Sign::Negative;
      }
  EXPECT_GT(zeros, 0) << "ulp grid";
  EXPECT_GT(positives, 0) << "ulp grid";
  EXPECT_GT(negatives, 0) << "ulp grid";
}

TEST(Incircle, magnitudes_from_1e_minus30_to_1e30_match_exact_oracle) {
  Rng rng(14);
  const std::vector<Point2> circle = lattice_circle(65);
  const auto pick = [&]() { return circle[static_cast<std::size_t>(uniform_int(rng, 0, int(circle.size()) - 1))]; };
  for (int e = -30; e <= 30; ++e) {
    const double scale = std::pow(10.0, e);
    for (int i = 0; i < 100; ++i) {
      const Point2 a = scale * random_in_box(rng, -1, 1), b = scale * random_in_box(rng, -1, 1);
      const Point2 c = scale * random_in_box(rng, -1, 1), d = scale * random_in_box(rng, -1, 1);
      expect_incircle_matches(a, b, c, d, "same magnitude random");
      // Nearly cocircular after decimal scaling, and far from the origin.
      const Point2 center = scale * random_in_box(rng, 1e3, 2e3);
      const double r = scale * 1e-3;
      expect_incircle_matches(center + r * pick(), center + r * pick(), center + r * pick(), center + r * pick(),
                              "near cocircular far away");
    }
  }
}

TEST(Incircle, mixed_magnitudes_in_one_call_match_exact_oracle) {
  Rng rng(15);
  for (int i = 0; i < 10000; ++i) {
    Point2 p[4];
    for (Point2& q : p) q = Point2(random_magnitude(rng, -30, 30), random_magnitude(rng, -30, 30));
    if (i % 2 == 0) p[3] = perturb(rng, p[0], 3);
    expect_incircle_matches(p[0], p[1], p[2], p[3], "mixed magnitudes");
    expect_permutation_rules(p[0], p[1], p[2], p[3], "mixed magnitudes");
  }
}

TEST(Incircle, extremes_of_the_valid_range_match_exact_oracle) {
  Rng rng(16);
  const double lo = std::ldexp(1.0, -142), hi = std::ldexp(1.0, 201);
  const std::vector<double> values = {0.0, lo, -lo, ulps(lo, 1), ulps(lo, 3), -ulps(lo, 2), hi, -hi, ulps(hi, -1),
                                      -ulps(hi, -2), ulps(hi, -7), 1.0, -1.0};
  const auto pick = [&]() { return values[static_cast<std::size_t>(uniform_int(rng, 0, int(values.size()) - 1))]; };
  for (int i = 0; i < 10000; ++i) {
    const Point2 a(pick(), pick()), b(pick(), pick()), c(pick(), pick()), d(pick(), pick());
    expect_incircle_matches(a, b, c, d, "range extremes");
  }
}

TEST(Incircle, degenerate_triangles_match_exact_oracle) {
  // Collinear or repeated a, b, c: the "circle" is a line; the determinant is still well defined.
  EXPECT_EQ(incircle({0, 0}, {1, 1}, {2, 2}, {3, 3}), Sign::Zero) << "four collinear points";
  EXPECT_EQ(incircle({0, 0}, {0, 0}, {1, 5}, {7, 2}), Sign::Zero) << "a == b";
  expect_incircle_matches({0, 0}, {1, 1}, {2, 2}, {0, 1}, "collinear abc");
  expect_incircle_matches({0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}, {0.4, 0.4}, "decimal collinear");
}

}  // namespace
}  // namespace acute::test
