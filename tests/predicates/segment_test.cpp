// Derived exact tests: angle_kind, in_diametral_circle, locate_on_segment, intersect_segments,
// validate_coordinate — against the oracle and on hand-made degenerate cases.
#include <gtest/gtest.h>

#include <acute/predicates/predicates.h>

#include <cmath>
#include <limits>
#include <vector>

#include "predicates/test_inputs.h"
#include "support/exact_rational.h"

namespace acute::test {
namespace {

using predicates::angle_kind;
using predicates::in_diametral_circle;
using predicates::intersect_segments;
using predicates::locate_on_segment;
using predicates::SegmentIntersection;
using predicates::SegmentLocation;

AngleKind kind_of(Sign dot) {
  return dot == Sign::Positive ? AngleKind::Acute : (dot == Sign::Zero ? AngleKind::Right : AngleKind::Obtuse);
}

void expect_dot_tests_match(const Point2& apex, const Point2& p, const Point2& q, const char* what) {
  const Sign truth = oracle_dot(apex, p, q);
  EXPECT_EQ(angle_kind(apex, p, q), kind_of(truth)) << what << ": " << describe(apex, p, q);
  EXPECT_EQ(angle_kind(apex, q, p), kind_of(truth)) << what << " (swapped): " << describe(apex, p, q);
  EXPECT_EQ(predicates::detail::dot_sign_exact(apex, p, q), truth) << what << " (exact stage): " << describe(apex, p, q);
  EXPECT_EQ(in_diametral_circle(p, q, apex), -truth) << what << " (diametral): " << describe(p, q, apex);
}

// Reference classifications written independently of the library: oracle signs and exact dot
// products of differences instead of coordinate comparisons.
SegmentLocation reference_location(const Point2& p, const Point2& a, const Point2& b) {
  if (p == a || p == b) return SegmentLocation::OnEndpoint;
  if (oracle_orient2d(a, b, p) != Sign::Zero) return SegmentLocation::Outside;
  return oracle_dot(p, a, b) == Sign::Negative ? SegmentLocation::OnInterior : SegmentLocation::Outside;
}

SegmentIntersection reference_intersection(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  if (a == b || c == d) {
    const bool meet = a == b ? (c == d ? a == c : reference_location(a, c, d) != SegmentLocation::Outside)
                             : reference_location(c, a, b) != SegmentLocation::Outside;
    return meet ? SegmentIntersection::Touching : SegmentIntersection::None;
  }
  const Sign o1 = oracle_orient2d(a, b, c), o2 = oracle_orient2d(a, b, d);
  const Sign o3 = oracle_orient2d(c, d, a), o4 = oracle_orient2d(c, d, b);
  if (o1 == Sign::Zero && o2 == Sign::Zero) {
    // Parameters along u = b - a: a -> 0, b -> |u|^2, c -> (c-a).u, d -> (d-a).u, compared exactly.
    const auto t = [&](const Point2& p) {
      return (Dyadic(p.x()) - Dyadic(a.x())) * (Dyadic(b.x()) - Dyadic(a.x())) +
             (Dyadic(p.y()) - Dyadic(a.y())) * (Dyadic(b.y()) - Dyadic(a.y()));
    };
    const Dyadic ta = t(a), tb = t(b), tc = t(c), td = t(d);
    const Dyadic c_lo = (tc - td).sign() < 0 ? tc : td, c_hi = (tc - td).sign() < 0 ? td : tc;
    const Dyadic lo = (c_lo - ta).sign() > 0 ? c_lo : ta, hi = (c_hi - tb).sign() < 0 ? c_hi : tb;
    const int s = (hi - lo).sign();
    return s > 0 ? SegmentIntersection::Overlapping : (s == 0 ? SegmentIntersection::Touching : SegmentIntersection::None);
  }
  if (static_cast<int>(o1) * static_cast<int>(o2) > 0 || static_cast<int>(o3) * static_cast<int>(o4) > 0)
    return SegmentIntersection::None;
  if (o1 == Sign::Zero || o2 == Sign::Zero || o3 == Sign::Zero || o4 == Sign::Zero) return SegmentIntersection::Touching;
  return SegmentIntersection::Proper;
}

const char* name(SegmentIntersection s) {
  switch (s) {
    case SegmentIntersection::None: return "None";
    case SegmentIntersection::Proper: return "Proper";
    case SegmentIntersection::Touching: return "Touching";
    case SegmentIntersection::Overlapping: return "Overlapping";
  }
  return "?";
}

// Checks all 8 equivalent argument orders against the expected answer.
void expect_intersection(const Point2& a, const Point2& b, const Point2& c, const Point2& d, SegmentIntersection want,
                         const char* what) {
  const Point2* segs[4][2] = {{&a, &b}, {&b, &a}, {&c, &d}, {&d, &c}};
  for (int i = 0; i < 2; ++i)
    for (int j = 2; j < 4; ++j) {
      const Point2 &p0 = *segs[i][0], &p1 = *segs[i][1], &q0 = *segs[j][0], &q1 = *segs[j][1];
      EXPECT_EQ(name(intersect_segments(p0, p1, q0, q1)), name(want)) << what << ": " << describe(p0, p1, q0, q1);
      EXPECT_EQ(name(intersect_segments(q0, q1, p0, p1)), name(want)) << what << " (swapped): " << describe(q0, q1, p0, p1);
    }
}

TEST(AngleKind, random_points_match_exact_oracle) {
  Rng rng(21);
  for (int i = 0; i < 20000; ++i) {
    const Point2 apex = random_in_box(rng, -1, 1), p = random_in_box(rng, -1, 1), q = random_in_box(rng, -1, 1);
    expect_dot_tests_match(apex, p, q, "random");
  }
}

TEST(AngleKind, constructed_right_angles_are_exact_and_ulp_perturbations_match_oracle) {
  Rng rng(22);
  int rights = 0;
  for (int i = 0; i < 5000; ++i) {
    // Perpendicular integer vectors (u, v) and k (-v, u), scaled by a power of two: exactly right.
    const Point2 apex(uniform_int(rng, -1000, 1000), uniform_int(rng, -1000, 1000));
    const Point2 u(uniform_int(rng, -300, 300), uniform_int(rng, -300, 300));
    const Point2 w = uniform_int(rng, 1, 7) * Point2(-u.y(), u.x());
    const int s = uniform_int(rng, -120, 170);
    const Point2 o = scaled(apex, s), p = scaled(apex + u, s), q = scaled(apex + w, s);
    if (u != Point2(0, 0)) {
      EXPECT_EQ(angle_kind(o, p, q), AngleKind::Right) << "constructed right angle: " << describe(o, p, q);
      EXPECT_EQ(in_diametral_circle(p, q, o), Sign::Zero) << "Thales: " << describe(p, q, o);
      ++rights;
    }
    expect_dot_tests_match(o, p, q, "constructed right angle");
    expect_dot_tests_match(perturb(rng, o, 2), p, q, "right angle, apex perturbed");
    expect_dot_tests_match(o, perturb(rng, p, 3), perturb(rng, q, 3), "right angle, legs perturbed");
  }
  EXPECT_GT(rights, 4000) << "constructed right angles";
}

TEST(AngleKind, magnitudes_and_mixed_magnitudes_match_exact_oracle) {
  Rng rng(23);
  for (int i = 0; i < 20000; ++i) {
    const Point2 apex(random_magnitude(rng, -30, 30), random_magnitude(rng, -30, 30));
    const Point2 p(random_magnitude(rng, -30, 30), random_magnitude(rng, -30, 30));
    // q near the perpendicular through apex: apex + rotated (p - apex), rounded, then a few ulps off.
    const Point2 d = p - apex;
    const Point2 q = i % 2 == 0 ? perturb(rng, apex + Point2(-d.y(), d.x()), 2)
                                : Point2(random_magnitude(rng, -30, 30), random_magnitude(rng, -30, 30));
    expect_dot_tests_match(apex, p, q, "mixed magnitudes");
  }
}

TEST(InDiametralCircle, thales_circle_points) {
  // The circle with diameter (-5,0)-(5,0) holds the lattice points (3,4), (0,5), (4,-3)...
  const Point2 a(-5, 0), b(5, 0);
  for (const Point2& p : {Point2(3, 4), Point2(0, 5), Point2(4, -3), Point2(-3, -4)})
    EXPECT_EQ(in_diametral_circle(a, b, p), Sign::Zero) << "on circle: " << describe(p);
  EXPECT_EQ(in_diametral_circle(a, b, Point2(0, 0)), Sign::Positive) << "center";
  EXPECT_EQ(in_diametral_circle(a, b, Point2(3, ulps(4, -1))), Sign::Positive) << "one ulp inside";
  EXPECT_EQ(in_diametral_circle(a, b, Point2(3, ulps(4, 1))), Sign::Negative) << "one ulp outside";
  EXPECT_EQ(in_diametral_circle(a, b, Point2(6, 0)), Sign::Negative) << "beyond b on the line";
  EXPECT_EQ(in_diametral_circle(a, b, a), Sign::Zero) << "endpoint a";
}

TEST(LocateOnSegment, hand_made_cases) {
  const Point2 a(0, 0), b(4, 2);
  EXPECT_EQ(locate_on_segment(a, a, b), SegmentLocation::OnEndpoint) << "a";
  EXPECT_EQ(locate_on_segment(b, a, b), SegmentLocation::OnEndpoint) << "b";
  EXPECT_EQ(locate_on_segment({2, 1}, a, b), SegmentLocation::OnInterior) << "midpoint";
  EXPECT_EQ(locate_on_segment({6, 3}, a, b), SegmentLocation::Outside) << "beyond b, collinear";
  EXPECT_EQ(locate_on_segment({-2, -1}, a, b), SegmentLocation::Outside) << "before a, collinear";
  EXPECT_EQ(locate_on_segment({2, ulps(1, 1)}, a, b), SegmentLocation::Outside) << "one ulp above midpoint";
  EXPECT_EQ(locate_on_segment({0, 1}, {0, 0}, {0, 2}), SegmentLocation::OnInterior) << "vertical segment";
  EXPECT_EQ(locate_on_segment({0, 3}, {0, 0}, {0, 2}), SegmentLocation::Outside) << "vertical, beyond";
  EXPECT_EQ(locate_on_segment({1, 0}, {2, 0}, {0, 0}), SegmentLocation::OnInterior) << "reversed horizontal";
  // 0.1 + 0.2 != 0.3 in doubles: is (0.3, 0.3) on the segment (0.1,0.1)-(0.5,0.5)? Yes: y = x exactly.
  EXPECT_EQ(locate_on_segment({0.3, 0.3}, {0.1, 0.1}, {0.5, 0.5}), SegmentLocation::OnInterior) << "decimal diagonal";
}

TEST(LocateOnSegment, grid_points_match_exact_reference) {
  Rng rng(24);
  for (const double unit : {1.0, 0.1, 1e-20, 3e15}) {
    for (int i = 0; i < 5000; ++i) {
      // A small grid makes collinear and endpoint cases frequent.
      const auto g = [&]() { return Point2(uniform_int(rng, 0, 4) * unit, uniform_int(rng, 0, 4) * unit); };
      const Point2 a = g(), b = g(), p = g();
      if (a == b) continue;
      EXPECT_EQ(static_cast<int>(locate_on_segment(p, a, b)), static_cast<int>(reference_location(p, a, b)))
          << "unit " << unit << ": " << describe(p, a, b);
    }
  }
}

TEST(IntersectSegments, hand_made_cases) {
  using SI = SegmentIntersection;
  expect_intersection({0, 0}, {2, 2}, {0, 2}, {2, 0}, SI::Proper, "X cross");
  expect_intersection({0, 0}, {2, 0}, {1, 0}, {1, 5}, SI::Touching, "T: endpoint on interior");
  expect_intersection({0, 0}, {2, 0}, {2, 0}, {3, 4}, SI::Touching, "shared endpoint");
  expect_intersection({0, 0}, {2, 0}, {2, 0}, {5, 0}, SI::Touching, "collinear, touching at endpoint");
  expect_intersection({0, 0}, {2, 0}, {1, 0}, {5, 0}, SI::Overlapping, "collinear overlap");
  expect_intersection({0, 0}, {4, 0}, {1, 0}, {2, 0}, SI::Overlapping, "collinear containment");
  expect_intersection({0, 0}, {4, 4}, {0, 0}, {4, 4}, SI::Overlapping, "identical");
  expect_intersection({0, 0}, {2, 0}, {3, 0}, {5, 0}, SI::None, "collinear disjoint");
  expect_intersection({0, 0}, {2, 0}, {0, 1}, {2, 1}, SI::None, "parallel");
  expect_intersection({0, 0}, {2, 0}, {1, 1}, {1, 3}, SI::None, "T missing above");
  expect_intersection({0, 0}, {0, 3}, {0, 1}, {0, 2}, SI::Overlapping, "vertical containment");
  expect_intersection({0, 0}, {2, 0}, {1, 0}, {1, 0}, SI::Touching, "degenerate point on segment");
  expect_intersection({0, 0}, {2, 0}, {1, 1}, {1, 1}, SI::None, "degenerate point off segment");
  expect_intersection({1, 1}, {1, 1}, {1, 1}, {1, 1}, SI::Touching, "same point twice");
  expect_intersection({1, 1}, {1, 1}, {2, 1}, {2, 1}, SI::None, "two distinct points");
  // One ulp decides: c's endpoint just above, on, or just below the line y = 0.
  expect_intersection({0, 0}, {2, 0}, {1, 1}, {1, std::ldexp(1.0, -140)}, SI::None, "T one step above");
  expect_intersection({0, 0}, {2, 0}, {1, 1}, {1, -std::ldexp(1.0, -140)}, SI::Proper, "T one step below");
  // Decimal T: (0.3, 0.3) lies exactly on y = x, so this is a touch, not a crossing.
  expect_intersection({0.1, 0.1}, {0.5, 0.5}, {0.3, 0.3}, {0.3, 1.0}, SI::Touching, "decimal T");
}

TEST(IntersectSegments, grid_segments_match_exact_reference) {
  Rng rng(25);
  for (const double unit : {1.0, 0.1, 1e-25, 7e20}) {
    for (int i = 0; i < 10000; ++i) {
      const auto g = [&]() { return Point2(uniform_int(rng, 0, 3) * unit, uniform_int(rng, 0, 3) * unit); };
      const Point2 a = g(), b = g(), c = g(), d = g();
      EXPECT_EQ(name(intersect_segments(a, b, c, d)), name(reference_intersection(a, b, c, d)))
          << "unit " << unit << ": " << describe(a, b, c, d);
    }
  }
}

TEST(IntersectSegments, random_near_degenerate_segments_match_exact_reference) {
  Rng rng(26);
  for (int i = 0; i < 10000; ++i) {
    const Point2 a = random_in_box(rng, -1, 1), b = random_in_box(rng, -1, 1);
    // c near the line ab (on, or a few ulps off), d random or also near the line.
    const Point2 c = perturb(rng, a + uniform(rng, -0.5, 1.5) * (b - a), 1);
    const Point2 d = i % 3 == 0 ? perturb(rng, a + uniform(rng, -0.5, 1.5) * (b - a), 1) : random_in_box(rng, -1, 1);
    EXPECT_EQ(name(intersect_segments(a, b, c, d)), name(reference_intersection(a, b, c, d))) << describe(a, b, c, d);
  }
}

TEST(ValidateCoordinate, accepts_the_exact_range_and_rejects_the_rest) {
  using predicates::validate_coordinate;
  const double lo = std::ldexp(1.0, -142), hi = std::ldexp(1.0, 201);
  for (const double ok : {0.0, -0.0, lo, -lo, hi, -hi, 1.0, -1e30, 1e-30, 0.1})
    EXPECT_TRUE(validate_coordinate(ok)) << ok;
  for (const double bad : {ulps(lo, -1), -ulps(lo, -1), ulps(hi, 1), -ulps(hi, 1), 1e-300, 1e300,
                           std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
    EXPECT_FALSE(validate_coordinate(bad)) << bad;
}

}  // namespace
}  // namespace acute::test
