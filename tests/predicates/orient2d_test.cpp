// orient2d (filtered and exact stage) against the exact oracle on easy and adversarial inputs.
#include <gtest/gtest.h>

#include <acute/predicates/predicates.h>

#include <cmath>
#include <vector>

#include "predicates/test_inputs.h"
#include "support/exact_rational.h"

namespace acute::test {
namespace {

using predicates::orient2d;

// Checks orient2d and its exact stage against the oracle; returns the oracle's answer.
Sign expect_orient_matches(const Point2& a, const Point2& b, const Point2& c, const char* what) {
  const Sign truth = oracle_orient2d(a, b, c);
  EXPECT_EQ(orient2d(a, b, c), truth) << what << ": " << describe(a, b, c);
  EXPECT_EQ(predicates::detail::orient2d_exact(a, b, c), truth) << what << " (exact stage): " << describe(a, b, c);
  return truth;
}

// All six permutations: even ones keep the sign, odd ones flip it.
void expect_permutation_rules(const Point2& a, const Point2& b, const Point2& c, const char* what) {
  const Sign s = orient2d(a, b, c);
  EXPECT_EQ(orient2d(b, c, a), s) << what << " bca: " << describe(a, b, c);
  EXPECT_EQ(orient2d(c, a, b), s) << what << " cab: " << describe(a, b, c);
  EXPECT_EQ(orient2d(b, a, c), -s) << what << " bac: " << describe(a, b, c);
  EXPECT_EQ(orient2d(a, c, b), -s) << what << " acb: " << describe(a, b, c);
  EXPECT_EQ(orient2d(c, b, a), -s) << what << " cba: " << describe(a, b, c);
}

TEST(Orient2d, documented_sign_conventions) {
  EXPECT_EQ(orient2d({0, 0}, {1, 0}, {0, 1}), Sign::Positive) << "counter-clockwise";
  EXPECT_EQ(orient2d({0, 0}, {0, 1}, {1, 0}), Sign::Negative) << "clockwise";
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {2, 2}), Sign::Zero) << "collinear";
}

TEST(Orient2d, random_points_match_exact_oracle) {
  Rng rng(1);
  for (int i = 0; i < 20000; ++i) {
    const Point2 a = random_in_box(rng, -1, 1), b = random_in_box(rng, -1, 1), c = random_in_box(rng, -1, 1);
    expect_orient_matches(a, b, c, "random");
    expect_permutation_rules(a, b, c, "random");
  }
}

TEST(Orient2d, ulp_grid_matches_exact_oracle) {
  // The classic picture: a point walking a nextafter grid around the line y = x (naive arithmetic
  // gets a noisy band of wrong signs here).
  int zeros = 0, positives = 0, negatives = 0;
  for (const auto& [b, c] : {std::pair{Point2(12, 12), Point2(24, 24)}, std::pair{Point2(24, 24), Point2(12, 12)},
                             std::pair{Point2(0.1, 0.1), Point2(1e10, 1e10)}, std::pair{Point2(-3, -3), Point2(17.3, 17.3)}}) {
    for (int i = 0; i < 64; ++i)
      for (int j = 0; j < 64; ++j) {
        const Point2 a(ulps(0.5, i - 32), ulps(0.5, j - 32));
        const Sign s = expect_orient_matches(a, b, c, "ulp grid");
        zeros += s == Sign::Zero;
        positives += s == Sign::Positive;
        negatives += s == Sign::Negative;
      }
  }
  // The grid must actually straddle the line, or the test proves nothing.
  EXPECT_GT(zeros, 0) << "ulp grid";
  EXPECT_GT(positives, 0) << "ulp grid";
  EXPECT_GT(negatives, 0) << "ulp grid";
}

TEST(Orient2d, near_collinear_perturbed_points_match_exact_oracle) {
  Rng rng(2);
  for (int i = 0; i < 20000; ++i) {
    const double box = std::pow(10.0, uniform_int(rng, -5, 5));
    const Point2 a = random_in_box(rng, -box, box), b = random_in_box(rng, -box, box);
    const double t = uniform(rng, -2, 3);
    const Point2 c = perturb(rng, a + t * (b - a), 3);  // a rounded point near the line, moved a few ulps
    expect_orient_matches(a, b, c, "near collinear");
    expect_permutation_rules(a, b, c, "near collinear");
  }
}

// The estimate's error bound covers its distance to the exact value (orient2d_value, rounded once).
TEST(Orient2d, estimate_error_bound_covers_the_exact_value) {
  Rng rng(5);
  for (int i = 0; i < 20000; ++i) {
    const double box = std::pow(10.0, uniform_int(rng, -5, 5));
    const Point2 a = random_in_box(rng, -box, box), b = random_in_box(rng, -box, box);
    const Point2 c = i % 2 ? random_in_box(rng, -box, box) : perturb(rng, a + uniform(rng, -2, 3) * (b - a), 3);
    double error = -1;
    const double estimate = predicates::orient2d_estimate(a, b, c, error);
    const double exact = predicates::orient2d_value(a, b, c);
    EXPECT_GE(error, 0);
    EXPECT_LE(std::abs(estimate - exact), error + 0x1p-52 * std::abs(exact)) << describe(a, b, c);
  }
}

TEST(Orient2d, constructed_collinear_points_are_exactly_zero) {
  Rng rng(3);
  for (int i = 0; i < 5000; ++i) {
    // Small integers times a power of two: the construction is exact, so the points are collinear.
    const Point2 base(uniform_int(rng, -1000, 1000), uniform_int(rng, -1000, 1000));
    const Point2 dir(uniform_int(rng, -50, 50), uniform_int(rng, -50, 50));
    const int s = uniform_int(rng, -130, 180);
    const Point2 a = scaled(base, s), b = scaled(base + uniform_int(rng, 1, 9) * dir, s);
    const Point2 c = scaled(base + uniform_int(rng, -9, 9) * dir, s);
    EXPECT_EQ(orient2d(a, b, c), Sign::Zero) << "collinear: " << describe(a, b, c);
    expect_orient_matches(a, b, c, "collinear");
  }
  // Also collinear but not representable on a short grid: equal coordinates in one axis.
  EXPECT_EQ(orient2d({0.1, 0.3}, {0.7, 0.3}, {1e-30, 0.3}), Sign::Zero) << "horizontal line y = 0.3";
  EXPECT_EQ(orient2d({0.1, 0.1}, {0.3, 0.3}, {1e20, 1e20}), Sign::Zero) << "diagonal y = x";
  EXPECT_EQ(orient2d({1, 2}, {1, 2}, {5, 7}), Sign::Zero) << "repeated point";
}

TEST(Orient2d, magnitudes_from_1e_minus30_to_1e30_match_exact_oracle) {
  Rng rng(4);
  for (int e = -30; e <= 30; ++e) {
    const double scale = std::pow(10.0, e);
    for (int i = 0; i < 300; ++i) {
      const Point2 a = scale * random_in_box(rng, -1, 1), b = scale * random_in_box(rng, -1, 1);
      const Point2 c = perturb(rng, a + uniform(rng, -1, 2) * (b - a), 2);
      expect_orient_matches(a, b, c, "same magnitude near collinear");
      // A tiny triangle far from the origin: huge coordinates, tiny differences.
      const Point2 far = scale * random_in_box(rng, 1, 2);
      expect_orient_matches(far, perturb(rng, far, 4), perturb(rng, far, 4), "tiny triangle far away");
    }
  }
}

TEST(Orient2d, mixed_magnitudes_in_one_call_match_exact_oracle) {
  Rng rng(5);
  for (int i = 0; i < 20000; ++i) {
    const Point2 a(random_magnitude(rng, -30, 30), random_magnitude(rng, -30, 30));
    const Point2 b(random_magnitude(rng, -30, 30), random_magnitude(rng, -30, 30));
    Point2 c(random_magnitude(rng, -30, 30), random_magnitude(rng, -30, 30));
    if (i % 2 == 0) c = perturb(rng, a + uniform(rng, -1, 2) * (b - a), 2);
    expect_orient_matches(a, b, c, "mixed magnitudes");
    expect_permutation_rules(a, b, c, "mixed magnitudes");
  }
}

TEST(Orient2d, extremes_of_the_valid_range_match_exact_oracle) {
  Rng rng(6);
  const double lo = std::ldexp(1.0, -142), hi = std::ldexp(1.0, 201);
  const std::vector<double> values = {0.0, lo, -lo, ulps(lo, 1), ulps(lo, 3), -ulps(lo, 2), hi, -hi, ulps(hi, -1),
                                      -ulps(hi, -2), ulps(hi, -7), 1.0, -1.0};
  const auto pick = [&]() { return values[static_cast<std::size_t>(uniform_int(rng, 0, int(values.size()) - 1))]; };
  for (int i = 0; i < 20000; ++i) {
    const Point2 a(pick(), pick()), b(pick(), pick()), c(pick(), pick());
    expect_orient_matches(a, b, c, "range extremes");
  }
}

TEST(Orient2d, exact_stage_matches_oracle_on_inexact_differences) {
  // Random points in unrelated boxes make every subtraction inexact: this drives the two-component
  // differences and full expansion products through the exact stage.
  Rng rng(8);
  for (int i = 0; i < 5000; ++i) {
    const Point2 a = random_in_box(rng, -1e-3, 1e-3), b = random_in_box(rng, 1e3, 1e5);
    const Point2 c = perturb(rng, a + uniform(rng, -1, 2) * (b - a), 1);
    EXPECT_EQ(predicates::detail::orient2d_exact(a, b, c), oracle_orient2d(a, b, c)) << describe(a, b, c);
  }
}

}  // namespace
}  // namespace acute::test
