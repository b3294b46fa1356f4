#include <acute/mesh/segments.h>
#include <acute/predicates/predicates.h>

#include <gtest/gtest.h>

#include <cstdint>

#include <limits>

#include <cmath>

namespace acute {
namespace {

// A side of the tiny hole of tests/data/regressions/tiny_slanted_hole_far_from_origin.poly.
const std::array<Point2, 2> kTinyFar{Point2(-999.8643391292297, -1000.5686505468435), Point2(-999.8643396596642, -1000.5686942271435)};

TEST(SnapToLine, points_of_a_tiny_segment_far_from_origin_stay_within_1e_10_of_its_length) {
  const auto& [a, b] = kTinyFar;
  double worst_rounded = 0, worst_snapped = 0;
  for (int i = 1; i < 64; ++i) {
    const double t = i / 64.0;
    const Point2 rounded = a + t * (b - a);
    const Point2 snapped = project_on_line(kTinyFar, rounded);
    worst_rounded = std::max(worst_rounded, line_deviation(kTinyFar, rounded));
    worst_snapped = std::max(worst_snapped, line_deviation(kTinyFar, snapped));
    EXPECT_LE((snapped - rounded).norm(), (b - a).norm() / 64) << "t " << t;  // still about there
  }
  EXPECT_GT(worst_rounded, 1e-10);  // the rounded interpolation is visibly off the segment
  EXPECT_LT(worst_snapped, 1e-10);
}

// The most exact of the 3 doubles nearest the line in each of the `columns` columns on either side
// of q along the dominant axis, inside the bracket (brute force).
double brute_force_best_deviation(const std::array<Point2, 2>& ends, const Point2& q, const Point2& lo, const Point2& hi, int columns) {
  const auto& [a, b] = ends;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const int k = std::fabs(b.x() - a.x()) >= std::fabs(b.y() - a.y()) ? 0 : 1, j = 1 - k;
  double best = inf, up = q[k], down = q[k];
  for (int step = 0; step < columns; ++step) {
    up = std::nextafter(up, inf), down = std::nextafter(down, -inf);
    for (const double xk : {up, down}) {
      const double yj = a[j] + (xk - a[k]) * ((b[j] - a[j]) / (b[k] - a[k]));
      for (const double y : {std::nextafter(yj, -inf), yj, std::nextafter(yj, inf)}) {
        Point2 c;
        c[k] = xk, c[j] = y;
        if (strictly_between_along(ends, lo, c, hi)) best = std::min(best, line_deviation(ends, c));
      }
    }
  }
  return best;
}

// Far from the origin (UTM-like coordinates) no double lies within 2^-42 of a short segment's
// length from it, so every snap searches: the lattice search by residues and the window walk. Where
// brute force finds a double within kMaxSegmentDeviation among the 3 nearest the line in each of
// the 128 columns on either side of the request, the snap finds one too, inside the bracket.
TEST(SnapToLine, far_from_the_origin_finds_a_near_double_wherever_brute_force_does) {
  std::uint64_t state = 12345;
  auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1p-53;
  };
  int found = 0, near = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Point2 a(1e6 + 1000 * uniform(), -3e6 + 1000 * uniform());
    const double length = std::pow(10.0, -2 + 2 * uniform()), angle = 6.283185307179586 * uniform();
    const Point2 b = a + length * Point2(std::cos(angle), std::sin(angle));
    const std::array<Point2, 2> ends{a, b};
    const Point2 lo = a + 0.25 * (b - a), hi = a + 0.75 * (b - a);
    const Point2 q = a + uniform() * (b - a);
    const Point2 s = snap_to_line(ends, q, &lo, &hi);
    const bool exists = brute_force_best_deviation(ends, q, lo, hi, 128) <= kMaxSegmentDeviation;
    const bool ok = strictly_between_along(ends, lo, s, hi) && close_enough_to_line(ends, s);
    near += exists;
    found += ok;
    if (exists) {
      EXPECT_TRUE(ok) << "trial " << trial;
    }
  }
  EXPECT_GT(near, 0);
  EXPECT_GE(found, near);
}

// A slope near a small fraction (13 / 8 in grid units, a side of A.poly moved to (1e6, -3e6)): the
// lines' offsets drift by a few every 8 columns, so no double near q is within 2^-36 of the
// length. The snap is still at least as exact as the best of the 4,096 columns on either side,
// within kMaxSegmentDeviation, and within 1/64 of the segment from q.
TEST(SnapToLine, a_slope_near_a_small_fraction_far_from_the_origin_gets_the_most_exact_nearby_double) {
  const std::array<Point2, 2> ends{Point2(1000000.3608, -3000000.6044000001), Point2(1000000.3192, -3000000.7067999998)};
  const Point2 lo = ends[1], hi = ends[0];
  for (const double t : {0.05, 0.2, 0.37, 0.5, 0.81, 0.96}) {
    const Point2 q = ends[0] + t * (ends[1] - ends[0]);
    const Point2 s = snap_to_line(ends, q, &lo, &hi);
    const double best = brute_force_best_deviation(ends, q, lo, hi, 4096);
    EXPECT_TRUE(strictly_between_along(ends, lo, s, hi)) << "t " << t;
    EXPECT_LE(line_deviation(ends, s), best) << "t " << t;
    EXPECT_LE(line_deviation(ends, s), kMaxSegmentDeviation) << "t " << t;
    EXPECT_LE((s - q).norm(), (ends[1] - ends[0]).norm() / 64) << "t " << t;
  }
}

// Random short segments far from the origin: where brute force finds a double within 2^-36 of the
// length among the 4,096 columns on either side of q, the snap is that exact too; elsewhere it is
// at least as exact as brute force's best, and inside the bracket.
TEST(SnapToLine, far_from_the_origin_is_at_least_as_exact_as_brute_force_over_the_walks_columns) {
  std::uint64_t state = 777;
  auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1p-53;
  };
  int weak = 0;  // trials where no double within 2^-36 of the length lies near q
  for (int trial = 0; trial < 40; ++trial) {
    const Point2 a(1e6 + 1000 * uniform(), -3e6 + 1000 * uniform());
    const double length = std::pow(10.0, -2 + 2 * uniform()), angle = 6.283185307179586 * uniform();
    // Half the trials on a slope near a small fraction (p / q with q <= 8 in the grid units).
    Point2 dir(std::cos(angle), std::sin(angle));
    if (trial % 2 == 1) dir = Point2(1 + static_cast<int>(8 * uniform()), 1 + static_cast<int>(8 * uniform())).normalized() + Point2(1e-9, 0);
    const Point2 b = a + length * dir;
    const std::array<Point2, 2> ends{a, b};
    const Point2 lo = a + 0.25 * (b - a), hi = a + 0.75 * (b - a);
    const Point2 q = lo + uniform() * (hi - lo);
    const Point2 s = snap_to_line(ends, q, &lo, &hi);
    const double best = brute_force_best_deviation(ends, q, lo, hi, 4096);
    weak += best > 0x1p-36;
    EXPECT_LE(line_deviation(ends, s), std::max(best, 0x1p-36)) << "trial " << trial;
    EXPECT_TRUE(strictly_between_along(ends, lo, s, hi)) << "trial " << trial;
  }
  EXPECT_GT(weak, 0);  // the case the exact search is for occurs
}

// The filtered test agrees with the exact deviation on points from 2^-40 to 2^-28 off a line.
TEST(CloseEnoughToLine, agrees_with_the_exact_deviation) {
  const std::array<Point2, 2> lines[] = {{Point2(0, 0), Point2(4, 2)}, kTinyFar, {Point2(1e6, -3e5), Point2(1e6 + 3.3, -3e5 + 7.1)}};
  int near = 0, far = 0;
  for (const auto& ends : lines) {
    const Point2 d = ends[1] - ends[0], normal = Point2(-d.y(), d.x()) / d.norm();
    for (int i = 0; i < 2000; ++i) {
      const double t = (i % 97) / 97.0, off = std::ldexp(1.0 + (i % 13) / 13.0, -40 + (i % 12)) * d.norm();
      const Point2 p = ends[0] + t * d + ((i % 2) ? off : -off) * normal;
      const bool exact = line_deviation(ends, p) <= kMaxSegmentDeviation;
      EXPECT_EQ(close_enough_to_line(ends, p), exact) << "deviation " << line_deviation(ends, p);
      (exact ? near : far) += 1;
    }
  }
  EXPECT_GT(near, 0);
  EXPECT_GT(far, 0);
}

// A 7e-3 long slanted wall at -1000 (stress seed 245): a rounded point is ~1e-11 of its length off
// the line, and exact points recur every few 1e-5 along it. A snap that went for the most exact
// point within reach moved a split back onto the vertex it replaced (a strip apex triangle that
// could never be made isosceles); the snap must stay where it was asked to be.
TEST(SnapToLine, stays_within_a_few_ulps_of_the_request_when_a_nearby_double_is_close_enough) {
  const std::array<Point2, 2> ends{Point2(-998.12655105786746, -998.81185777629014), Point2(-998.12313157974916, -998.8180326445206)};
  const double len = (ends[1] - ends[0]).norm(), ulp = std::nextafter(998.0, 1024.0) - 998.0;  // the ulp of both coordinates
  double worst_move = 0;
  for (int i = 1; i < 200; ++i) {
    const Point2 q = ends[0] + (i / 200.0) * (ends[1] - ends[0]);
    const Point2 snapped = project_on_line(ends, q);
    EXPECT_LE(line_deviation(ends, snapped), kMaxSegmentDeviation);
    worst_move = std::max(worst_move, (snapped - q).norm());
  }
  EXPECT_LE(worst_move, 512 * ulp) << "of a segment " << len << " long";
}

TEST(SnapToLine, keeps_a_point_already_on_the_line) {
  const std::array<Point2, 2> ends{Point2(0, 0), Point2(4, 2)};
  EXPECT_EQ(snap_to_line(ends, Point2(1, 0.5)), Point2(1, 0.5));
  EXPECT_EQ(predicates::orient2d(ends[0], ends[1], project_on_line(ends, Point2(3, 0))), Sign::Zero);
}

TEST(SnapToLine, respects_the_bracket_and_finds_nothing_in_an_empty_one) {
  // Nearly vertical, 5 ulps wide in x: only 4 doubles lie strictly between the ends in x.
  const std::array<Point2, 2> ends{Point2(2.0, 0.6666666666666666), Point2(2.000000000000002, 1.3333333333333333)};
  const Point2 lo = ends[0], hi = ends[1];
  const Point2 mid = project_on_line(ends, 0.5 * (lo + hi), &lo, &hi);
  EXPECT_TRUE(strictly_between_along(ends, lo, mid, hi));
  const Point2 level(std::nextafter(2.0, 3.0), 0.8), above(std::nextafter(2.0, 3.0), 0.9);
  EXPECT_FALSE(strictly_between_along(ends, level, project_on_line(ends, 0.5 * (level + above), &level, &above), above));
}

TEST(StrictlyBetweenAlong, ignores_the_coordinate_a_segment_is_constant_in) {
  const std::array<Point2, 2> horizontal{Point2(0, 1), Point2(4, 1)};
  EXPECT_TRUE(strictly_between_along(horizontal, Point2(1, 1), Point2(2, 1), Point2(3, 1)));
  EXPECT_FALSE(strictly_between_along(horizontal, Point2(1, 1), Point2(3, 1), Point2(3, 1)));
  // A steep segment: both coordinates advance strictly (x for a referee's walk, y as the dominant one).
  const std::array<Point2, 2> steep{Point2(0, 0), Point2(1, 4)};
  EXPECT_FALSE(strictly_between_along(steep, Point2(0.25, 1), Point2(0.25, 2), Point2(0.5, 3)));
  EXPECT_FALSE(strictly_between_along(steep, Point2(0.25, 1), Point2(0.5, 2), Point2(0.5, 3)));
  EXPECT_TRUE(strictly_between_along(steep, Point2(0.25, 1), Point2(0.375, 2), Point2(0.5, 3)));
}

TEST(StrictlyBetweenAlong, lets_a_nearly_level_chain_repeat_its_minor_coordinate_but_never_x) {
  // 2e-15 out of level over a third (stress seed 32's wall): about 18 doubles of y between its
  // ends, so a chain strict in y could carry no more Steiner points than that.
  const std::array<Point2, 2> wall{Point2(1.000001, 0.5), Point2(1.3333333333333335, 0.499999999999998)};
  const Point2 lo(1.1, 0.5), hi(1.2, 0.5);
  EXPECT_TRUE(strictly_between_along(wall, lo, Point2(1.15, 0.5), hi));
  EXPECT_FALSE(strictly_between_along(wall, lo, Point2(1.2, 0.5), hi));                   // x must advance
  EXPECT_FALSE(strictly_between_along(wall, lo, Point2(1.15, 0.49999999999999994), hi));  // y stays between
  // So a thousand Steiner points fit, each on the line to within kMaxSegmentDeviation.
  Point2 prev = wall[0];
  int fitted = 0;
  for (int i = 1; i < 1000; ++i) {
    const Point2 q = wall[0] + (i / 1000.0) * (wall[1] - wall[0]);
    const Point2 p = project_on_line(wall, q, &prev, &wall[1]);
    if (!strictly_between_along(wall, prev, p, wall[1])) continue;
    EXPECT_LE(line_deviation(wall, p), kMaxSegmentDeviation);
    prev = p;
    ++fitted;
  }
  EXPECT_EQ(fitted, 999);
}

TEST(ChainCapacity, counts_the_doubles_strictly_between_in_the_coordinates_that_advance_strictly) {
  // Nearly vertical: x advances strictly, so the doubles strictly between the ends' x count.
  const Point2 a(2.0, 0.6666666666666666), b(2.000000000000002, 1.3333333333333333);
  std::uint64_t between = 0;
  for (double x = std::nextafter(a.x(), 3.0); x < b.x(); x = std::nextafter(x, 3.0)) ++between;
  EXPECT_EQ(chain_capacity(a, b), between);
  EXPECT_EQ(chain_capacity(b, a), between);
  // A nearly level wall is limited by x only, which spans many doubles; so is an exact vertical by y.
  EXPECT_GT(chain_capacity(Point2(1.000001, 0.5), Point2(1.3333333333333335, 0.499999999999998)), 1u << 30);
  EXPECT_GT(chain_capacity(Point2(2, 0), Point2(2, 1)), 1u << 30);
  // Across zero the count goes on: -tiny, 0 and +tiny lie strictly between -2 tiny and 2 tiny.
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(chain_capacity(Point2(-2 * tiny, 0), Point2(2 * tiny, 1)), 3u);
}

TEST(SnapToLine, uses_any_free_double_of_a_wall_few_doubles_wide_where_it_is_needed) {
  // Nearly vertical, its ends 4 doubles apart in x: three points fit near its lower end, each on
  // the next x double, where the line's own x is the end's (the walk near the line found only it).
  double x4 = 2.0;
  for (int k = 0; k < 4; ++k) x4 = std::nextafter(x4, 3.0);
  const std::array<Point2, 2> ends{Point2(2.0, 0.0), Point2(x4, 1.0)};
  ASSERT_EQ(chain_capacity(ends[0], ends[1]), 3u);
  Point2 prev = ends[0];
  for (int k = 1; k <= 3; ++k) {
    const Point2 q(2.0, 0.001 * k);
    const Point2 p = project_on_line(ends, q, &prev, &ends[1]);
    ASSERT_TRUE(strictly_between_along(ends, prev, p, ends[1])) << k;
    EXPECT_NEAR(p.y(), q.y(), 1e-12) << "kept where it was asked for";
    EXPECT_LE(line_deviation(ends, p), kMaxSegmentDeviation);
    prev = p;
  }
  EXPECT_FALSE(strictly_between_along(ends, prev, project_on_line(ends, Point2(2.0, 0.004), &prev, &ends[1]), ends[1])) << "full";
}

TEST(InChainOrder, equals_the_neighbours_where_they_agree) {
  EXPECT_TRUE(in_chain_order(Point2(2, 0), Point2(1, 1), Point2(2, 1), Point2(3, 1)));
  EXPECT_FALSE(in_chain_order(Point2(2, 0), Point2(1, 1), Point2(2, 1.0000000000000002), Point2(3, 1)));
  EXPECT_FALSE(in_chain_order(Point2(0, 2), Point2(1, 1), Point2(1, 1), Point2(1, 3)));  // y must advance on a vertical
  EXPECT_TRUE(in_chain_order(Point2(2, 1e-15), Point2(1, 1), Point2(2, 1), Point2(3, 1)));
}

}  // namespace
}  // namespace acute
