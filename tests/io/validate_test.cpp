#include "io/io_test_util.h"

#include <acute/io/io.h>
#include <acute/predicates/predicates.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace acute;
using acute::test::expect_error;

namespace {
Domain square() {
  Domain d;
  d.points = {Point2(0, 0), Point2(1, 0), Point2(1, 1), Point2(0, 1)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return d;
}
// A star polygon with n spikes (like debug2.poly): 2n vertices, 2n segments, no crossings.
Domain star(int n) {
  Domain d;
  for (int i = 0; i < 2 * n; ++i) {
    const double a = M_PI * i / n, r = i % 2 ? 1.0 : 2.0;
    d.points.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  for (int i = 0; i < 2 * n; ++i) d.segments.push_back({i, (i + 1) % (2 * n)});
  return d;
}
}  // namespace

TEST(ValidateDomain, accepts_touching_segments_and_points_on_segments) {
  Domain d = square();
  d.points.emplace_back(0.5, 0);    // on segment 0: allowed, reported by find_points_on_segments
  d.points.emplace_back(0.5, 0.5);  // free point
  d.segments.push_back({4, 5});     // T-junction at point 4
  EXPECT_NO_THROW(io::validate_domain(d));
  const auto on = io::find_points_on_segments(d);
  ASSERT_EQ(on.size(), 1u);
  EXPECT_EQ(on[0].point, 4);
  EXPECT_EQ(on[0].segment, 0);
}

TEST(ValidateDomain, rejects_each_degeneracy_naming_elements) {
  {
    Domain d = square();
    d.points[2].x() = std::numeric_limits<double>::quiet_NaN();
    expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"point 2", "not finite"}, "nan");
  }
  {
    Domain d = square();
    d.points[1].y() = 1e-300;
    expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"point 1", "outside the exact range"}, "tiny");
  }
  {
    Domain d = square();
    d.holes.emplace_back(std::numeric_limits<double>::infinity(), 0);
    expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"hole 0", "not finite"}, "hole");
  }
  {
    Domain d = square();
    d.segments.push_back({1, 4});
    expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"segment 4 uses point 4", "out of range"}, "range");
  }
  {
    Domain d = square();
    d.points.emplace_back(1, 1);
    d.source_path = "sq.poly";
    expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"sq.poly: ", "point 4 duplicates point 2"}, "dup");
  }
  {
    Domain d = square();
    d.segments.push_back({2, 2});
    expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"segment 4 has zero length"}, "zero");
  }
  {
    Domain d = square();
    d.segments.push_back({3, 2});
    expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"segment 4 (points 3-2) repeats segment 2"}, "repeat");
  }
  {
    Domain d = square();
    d.segments.push_back({0, 2});
    d.segments.push_back({1, 3});
    expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"segment 5 (points 1-3) crosses segment 4 (points 0-2)"},
                               "cross");
  }
  {
    Domain d = square();
    d.points.emplace_back(2, 0);
    d.segments.push_back({0, 4});  // contains segment 0
    expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"segment 4 (points 0-4) overlaps segment 0"}, "overlap");
  }
  {
    Domain d = square();
    d.point_markers = {1, 2};
    expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"point_markers has 2 entries for 4 points"}, "markers");
  }
}

TEST(ValidateDomain, near_miss_is_not_a_crossing) {
  // Segment 4 stops one ulp short of segment 1 (x = 1): exact predicates must say "no crossing".
  Domain d = square();
  d.points.emplace_back(0.5, 0.5);
  d.points.emplace_back(std::nextafter(1.0, 0.0), 0.5);
  d.segments.push_back({4, 5});
  EXPECT_NO_THROW(io::validate_domain(d));
  d.points[5].x() = std::nextafter(1.0, 2.0);
  expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"segment 4 (points 4-5) crosses segment 1"}, "one ulp over");
}

// (No timing here: a loaded machine makes timed tests flaky. A quadratic check would take minutes.)
TEST(ValidateDomain, large_inputs_pass_and_the_crossing_is_found) {
  Domain d = star(10000);  // 20000 segments
  EXPECT_NO_THROW(io::validate_domain(d));
  // A chord from a spike tip to a far inner corner cuts many spikes: must be found.
  d.segments.push_back({0, 5001});
  expect_error<InvalidInput>([&] { io::validate_domain(d); }, {"segment 20000 (points 0-5001)", "crosses"}, "chord");
}

TEST(ValidateDomain, random_segments_match_brute_force) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(0, 30);
  for (int round = 0; round < 200; ++round) {
    Domain d;
    for (int i = 0; i < 24; ++i) d.points.emplace_back(coord(rng), coord(rng));
    // drop duplicate points
    std::vector<Point2> unique;
    for (const auto& p : d.points)
      if (std::find(unique.begin(), unique.end(), p) == unique.end()) unique.push_back(p);
    d.points = unique;
    std::uniform_int_distribution<int> pick(0, static_cast<int>(d.points.size()) - 1);
    for (int s = 0; s < 6; ++s) {
      int a = pick(rng), b = pick(rng);
      if (a != b) d.segments.push_back({a, b});
    }
    bool brute_bad = false;
    for (std::size_t i = 0; i < d.segments.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) {
        const auto& s = d.segments[i];
        const auto& t = d.segments[j];
        const auto k = predicates::intersect_segments(d.points[s[0]], d.points[s[1]], d.points[t[0]], d.points[t[1]]);
        const bool same = std::minmax(s[0], s[1]) == std::minmax(t[0], t[1]);
        if (same || k == predicates::SegmentIntersection::Proper || k == predicates::SegmentIntersection::Overlapping)
          brute_bad = true;
      }
    bool threw = false;
    try {
      io::validate_domain(d);
    } catch (const InvalidInput&) {
      threw = true;
    }
    EXPECT_EQ(threw, brute_bad) << "round " << round;
  }
}
