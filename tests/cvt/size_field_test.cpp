#include "cvt/cvt_domains.h"

#include <acute/core/errors.h>
#include <acute/cvt/size_field.h>
#include <acute/delaunay/cdt.h>

#include <gtest/gtest.h>

#include <cmath>

namespace acute {
namespace {

TEST(SizeField, uniform_is_constant) {
  const SizeField f = SizeField::uniform(0.25);
  EXPECT_TRUE(f.is_uniform());
  EXPECT_EQ(f({3, -7}), 0.25);
  EXPECT_THROW(SizeField::uniform(0), InvalidInput);
}

TEST(SizeField, piecewise_linear_interpolates_and_clamps_outside) {
  const SizeField f = SizeField::piecewise_linear({{0, 0}, {1, 0}, {0, 1}, {1, 1}}, {{{0, 1, 3}}, {{0, 3, 2}}}, {1, 2, 3, 4});
  EXPECT_NEAR(f({0.5, 0.25}), 1 + 0.5 * 1 + 0.25 * 2, 1e-14);
  EXPECT_NEAR(f({0.25, 0.75}), 1 + 0.25 + 1.5, 1e-14);
  EXPECT_NEAR(f({2, 0}), 2, 1e-14) << "outside the background: clamped to the nearest triangle";
  int hint = 1;
  EXPECT_NEAR(f.eval({0.9, 0.05}, hint), 1 + 0.9 + 0.1, 1e-14);
  EXPECT_EQ(hint, 0);
}

// Samples along a slanted wall are collinear up to rounding: the background triangulation can hold
// a triangle whose rounded area is zero. Its barycentric coordinates are infinite; the value came
// out NaN, and one NaN in a wall's integral of 1/h left the whole wall undivided (a CG:SHOP
// boundary side 7,000 long with no vertex on it).
TEST(SizeField, a_background_triangle_of_zero_rounded_area_interpolates_along_its_edges) {
  const SizeField f = SizeField::piecewise_linear({{0, 0}, {1, 0}, {2, 0}}, {{{0, 1, 2}}}, {1, 2, 3});
  int hint = 0;
  const double h = f.eval({1.5, 0}, hint);
  ASSERT_TRUE(std::isfinite(h));
  EXPECT_NEAR(h, 2.5, 1e-14);
  EXPECT_NEAR(f({0.25, 0}), 1.25, 1e-14);
  EXPECT_NEAR(f({3, 0}), 3, 1e-14) << "beyond its ends: the nearest end's value";
}

TEST(SizeField, vertex_count_formula_inverts) {
  DomainMeasures m;
  m.area = 3;
  m.boundary_length = 8;
  const double h = size_for_vertex_count(m, 2000);
  const double n = 2 * m.area / (std::sqrt(3.0) * h * h) + m.boundary_length / (2 * h) + 1;
  EXPECT_NEAR(n, 2000, 1e-6);
}

TEST(SizeField, graded_field_meets_gradation_and_clamps) {
  for (const Domain& d : {test::unit_square(), test::l_shape(), test::wedge_with_hole()}) {
    const Mesh cdt = build_cdt(d);
    SizeFieldParams p;
    const SizeField f = local_feature_size_field(cdt, p);
    const double diam = measure_domain(cdt).diameter;
    EXPECT_LE(f.max_value(), diam / 25 * (1 + 1e-12)) << d.name;
    EXPECT_GT(f.min_value(), 0) << d.name;
    const auto& pts = f.background_points();
    const auto& val = f.background_values();
    for (const auto& t : f.background_triangles())
      for (int i = 0; i < 3; ++i) {
        const auto a = static_cast<std::size_t>(t[static_cast<std::size_t>(i)]), b = static_cast<std::size_t>(t[static_cast<std::size_t>((i + 1) % 3)]);
        EXPECT_LE(std::abs(val[a] - val[b]), 0.3 * (pts[a] - pts[b]).norm() * (1 + 1e-9) + 1e-15) << d.name << " edge " << a << "-" << b;
      }
  }
}

TEST(SizeField, graded_field_is_small_near_close_features) {
  const Domain d = test::wedge_with_hole();
  const Mesh cdt = build_cdt(d);
  const SizeField f = local_feature_size_field(cdt, {});
  // The hole corner (2.4, 0.5) is 0.5 from the bottom segment.
  EXPECT_LE(f({2.4, 0.5}), 0.5 + 1e-12) << d.name;
  EXPECT_LE(f({2.4, 0.0}), 0.5 + 1e-12) << d.name << ": the foot of that feature on the segment";
}

TEST(SizeField, two_tiny_features_far_apart_do_not_keep_the_field_small_between_them) {
  // Two isolated segments 1e-7 long, closer than the background grid's step (stress seed 35): the
  // background triangulation joined their samples by an edge, and the field, linear along it,
  // stayed 1e-7 all the way (933,000 predicted vertices instead of about 2,000 there). Between
  // them it must grow as the gradation allows.
  Domain d = test::unit_square();
  const Point2 a{0.52, 0.52}, b{0.535, 0.535};
  d.points.insert(d.points.end(), {a, a + Point2(0, 1e-7), b, b + Point2(0, 1e-7)});
  d.segments.push_back({4, 5});
  d.segments.push_back({6, 7});
  const Mesh cdt = build_cdt(d);
  const SizeField f = local_feature_size_field(cdt, {});
  const double half = 0.5 * (b - a).norm();
  EXPECT_LE(f(a), 1e-7 * (1 + 1e-9));
  EXPECT_GT(f(0.5 * (a + b)), 0.5 * 0.3 * half) << "halfway, " << half << " from either feature";
  EXPECT_LT(predicted_vertex_count(cdt, f), 20000);
}

TEST(SizeField, a_long_wall_is_small_where_a_tiny_feature_is_near_it) {
  // A tiny segment 0.005 below the top wall, between two of the wall's lfs samples (stress seed
  // 476, a tiny hole): those were at least 1/16 of the wall's length apart, and on the wall the
  // field is the interpolation of its own samples, so it missed the feature (0.0095 there).
  Domain d = test::unit_square();
  d.points.insert(d.points.end(), {Point2(0.53, 0.995), Point2(0.53 + 1e-5, 0.995)});
  d.segments.push_back({4, 5});
  const Mesh cdt = build_cdt(d);
  const SizeField f = local_feature_size_field(cdt, {});
  EXPECT_LE(f({0.53, 1.0}), 0.006) << "the wall above the feature, 0.005 from it";
}

/// The unit square with an isolated interior segment of the given length far from the boundary,
/// shorter than any spacing a vertex count would give.
Domain square_with_short_segment(double length) {
  Domain d = test::unit_square();
  d.name = "square_with_short_segment";
  d.points.insert(d.points.end(), {{0.44382, 0.08974}, {0.44382 + 0.6 * length, 0.08974 - 0.8 * length}});
  d.segments.push_back({4, 5});
  return d;
}

TEST(SizeField, a_segment_shorter_than_the_spacing_is_resolved) {
  // The corner (0, 0) has its nearest feature at the segment's endpoint: a sample there with
  // the corner's distance (0.45) stood beside the endpoint's own (the segment length), and the
  // field kept the large one, so the segment vanished from it.
  for (double length : {1e-3, 1e-6}) {
    const Mesh cdt = build_cdt(square_with_short_segment(length));
    SizeFieldParams p;
    p.target_vertices = 300;
    p.graded = true;
    p.lfs_factor = 0.7;
    const LfsSamples samples = local_feature_size_samples(cdt, 0.06);
    for (std::size_t i = 0; i < samples.points.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) EXPECT_NE(samples.points[i], samples.points[j]) << "samples " << j << " and " << i << " share a point";
    const SizeField f = make_size_field(cdt, p);
    EXPECT_LE(f({0.44382, 0.08974}), 0.7 * length * (1 + 1e-9)) << length;
    EXPECT_LE(f.min_value(), 0.7 * length * (1 + 1e-9)) << length;
    EXPECT_GT(f({0.9, 0.9}), 0.03) << length << ": far away the field keeps the spacing of the vertex count";
  }
}

TEST(SizeField, wide_corners_are_the_input_vertices_with_a_sector_of_at_least_80_degrees) {
  // The L-shape: five 90-degree corners and one of 270; a triangle: 60-degree corners only.
  EXPECT_EQ(local_feature_size_samples(build_cdt(test::l_shape()), 0.1).wide_corners.size(), 6u);
  EXPECT_EQ(local_feature_size_samples(build_cdt(test::polygon_domain({{0, 0}, {1, 0}, {0.5, 0.8660254037844386}}, "equilateral")), 0.1).wide_corners.size(), 0u);
}

// A strip 1 long and 1e-3 wide: the local feature size along its walls is its width, so at 10
// vertices its features alone ask for some thousand, far over kMaxFeatureExcess times the count.
TEST(SizeField, features_past_the_excess_decide_the_count_at_the_coarsest_factor_unless_it_is_held_below_them) {
  const Mesh cdt = build_cdt(test::polygon_domain({{0, 0}, {1, 0}, {1, 1e-3}, {0, 1e-3}}, "strip"));
  SizeFieldParams p;
  p.target_vertices = 10;
  p.graded = true;
  p.lfs_factor = 0.7;
  bool decide = false;
  const SizeField free = make_size_field(cdt, p, nullptr, &decide);
  EXPECT_TRUE(decide);
  EXPECT_GT(predicted_vertex_count(cdt, free), 2 * kMaxFeatureExcess * 10) << "the features decide the count";
  for (double x : {0.1, 0.5, 0.9}) {
    EXPECT_LE(free({x, 5e-4}), 1.05 * kCoarsestLfsFactor * 1e-3) << x << ": the strip's width (its lfs samples are 2% wider near the ends)";
    EXPECT_GT(free({x, 5e-4}), 0.7 * 1e-3 * (1 + 1e-3)) << x << ": coarser than the lfs factor asked for";
  }
  // Its four 90-degree corners are wide (one triangle cannot cover one): they keep the factor asked
  // for, room for the vertex that splits them.
  EXPECT_EQ(local_feature_size_samples(cdt, 0.06).wide_corners.size(), 4u);
  for (const Point2& corner : {Point2(0, 0), Point2(1, 1e-3)}) EXPECT_LE(free(corner), 0.7 * 1e-3 * (1 + 1e-9));
  p.max_vertices = 400;
  EXPECT_LE(predicted_vertex_count(cdt, make_size_field(cdt, p, nullptr, &decide)), 1.1 * 400) << "within the vertex budget";
  EXPECT_FALSE(decide);
  p.max_vertices = 0;
  p.hold_count = true;
  EXPECT_LE(predicted_vertex_count(cdt, make_size_field(cdt, p, nullptr, &decide)), 1.1 * kMaxFeatureExcess * 10) << "held near the request";
  EXPECT_FALSE(decide);
  // A hold that the features' own count fits under leaves the field as it was (a run whose time
  // limit can mesh them at their density).
  p.held_count_at_least = 2 * predicted_vertex_count(cdt, free);
  bool held = true;
  const SizeField roomy = make_size_field(cdt, p, nullptr, &decide, &held);
  EXPECT_TRUE(decide);
  EXPECT_FALSE(held);
  EXPECT_EQ(predicted_vertex_count(cdt, roomy), predicted_vertex_count(cdt, free));
  for (double x : {0.1, 0.5, 0.9}) EXPECT_EQ(roomy({x, 5e-4}), free({x, 5e-4})) << x;
  // One it does not fit under holds the count there.
  p.held_count_at_least = 0.5 * predicted_vertex_count(cdt, free);
  EXPECT_LE(predicted_vertex_count(cdt, make_size_field(cdt, p, nullptr, &decide, &held)), 1.1 * p.held_count_at_least) << "held at the floor";
  EXPECT_FALSE(decide);
  EXPECT_TRUE(held);
}

// A size with the graded flag is the largest edge length: uniform where nothing needs finer (the
// exact lattice), the local feature size's graded field below it where the features do.
TEST(SizeField, a_graded_size_is_uniform_unless_the_features_need_finer) {
  SizeFieldParams p;
  p.size = 0.01;
  p.graded = true;
  p.lfs_factor = 0.7;
  const SizeField square = make_size_field(build_cdt(test::unit_square()), p);
  EXPECT_TRUE(square.is_uniform());
  EXPECT_EQ(square.max_value(), 0.01);
  const Mesh strip = build_cdt(test::polygon_domain({{0, 0}, {1, 0}, {1, 1e-3}, {0, 1e-3}}, "strip"));
  p.size = 0.1;
  bool decide = true;
  const SizeField f = make_size_field(strip, p, nullptr, &decide);
  EXPECT_FALSE(f.is_uniform());
  // The strip's width asks for a thousand vertices, the uniform size's count for a handful: past
  // the excess, the features decide at the coarsest factor.
  EXPECT_TRUE(decide);
  for (double x : {0.1, 0.5, 0.9}) EXPECT_LE(f({x, 5e-4}), kCoarsestLfsFactor * 1e-3 * 1.05) << x << ": the strip's width";
  EXPECT_LE(f.max_value(), 0.1);
  p.graded = false;
  EXPECT_TRUE(make_size_field(strip, p).is_uniform()) << "without the flag, uniform as asked";
}

TEST(SizeField, the_default_field_coarsens_features_past_the_excess_of_its_largest_size) {
  // Neither a size nor a count: the graded field under the default largest size (a 25th of the
  // diameter). Its feature-bound sizes keep the factor asked for while the features ask for at
  // most kMaxFeatureExcess times a uniform largest size's vertices, and stop at the coarsest factor
  // past that (debug2's needles: 3.1M vertices at 0.7, 1.9M at 1.0), as with --size.
  SizeFieldParams p;
  p.graded = true;
  p.lfs_factor = 0.7;
  const Mesh notch = build_cdt(test::polygon_domain({{0, 0}, {1, 0}, {1, 1}, {0.52, 1}, {0.5, 0.9}, {0.48, 1}, {0, 1}}, "notch"));
  bool decide = true;
  const SizeField mild = make_size_field(notch, p, nullptr, &decide);
  EXPECT_FALSE(decide) << "a notch a tenth deep asks for a few times the count, not 16";
  EXPECT_DOUBLE_EQ(mild.min_value(), local_feature_size_field(notch, p).min_value());
  const Mesh strip = build_cdt(test::polygon_domain({{0, 0}, {1, 0}, {1, 1e-3}, {0, 1e-3}}, "strip"));
  const SizeField f = make_size_field(strip, p, nullptr, &decide);
  EXPECT_TRUE(decide) << "the strip's width asks for a thousand vertices, a 25th of its diameter for a handful";
  for (double x : {0.1, 0.5, 0.9}) {
    EXPECT_LE(f({x, 5e-4}), kCoarsestLfsFactor * 1e-3 * 1.05) << x << ": the strip's width";
    EXPECT_GE(f({x, 5e-4}), 0.9 * 1e-3) << x << ": coarsened from 0.7 of it";
  }
  EXPECT_GT(predicted_vertex_count(strip, local_feature_size_field(strip, p)), 1.5 * predicted_vertex_count(strip, f));
}

TEST(SizeField, a_wall_few_doubles_wide_gets_as_many_edges_as_it_can_carry_graded_from_its_ends) {
  // The unit square at x = 2 whose left wall leans 4 doubles of x over its height: a chain on it
  // can hold 3 points (the referee walks it along x), where 2,000 vertices ask for about 45.
  double x4 = 2.0;
  for (int k = 0; k < 4; ++k) x4 = std::nextafter(x4, 3.0);
  SizeFieldParams p;
  p.target_vertices = 2000;
  p.graded = true;
  auto edges_along_left_wall = [](const SizeField& f, double top_x) {
    double n = 0;
    constexpr int kSteps = 20000;
    for (int k = 0; k < kSteps; ++k) n += (1.0 / kSteps) / f({2.0 + (top_x - 2.0) * (k + 0.5) / kSteps, (k + 0.5) / kSteps});
    return n;
  };
  const Mesh plumb = build_cdt(test::polygon_domain({{2, 0}, {3, 0}, {3, 1}, {2, 1}}, "plumb"));
  EXPECT_GT(edges_along_left_wall(make_size_field(plumb, p), 2.0), 30) << "an exact vertical carries any number";
  const Mesh leaning = build_cdt(test::polygon_domain({{2, 0}, {3, 0}, {3, 1}, {x4, 1}}, "leaning"));
  const SizeField f = make_size_field(leaning, p);
  const double n = edges_along_left_wall(f, x4);
  EXPECT_LE(n, 4.0 * 1.1) << "3 points: 4 edges";
  EXPECT_GE(n, 4.0 * 0.9);
  // Graded from its ends (as fine there as the plumb wall's field), coarsest half way up.
  EXPECT_LE(f({2.0, 1e-4}), 1.5 * make_size_field(plumb, p)({2.0, 1e-4}));
  EXPECT_GT(f({2.0, 0.5}), 3 * f({2.0, 0.02}));
}

TEST(SizeField, a_scaled_field_is_finer_everywhere_but_beside_a_wall_that_cannot_carry_more) {
  // The leaning square above with scale 0.8 (a restart's finer start): away from the leaning
  // wall's raise the sizes are 0.8 times, and the wall still gets the 4 edges it can carry
  // (scaled after its raise, it would ask for 5).
  double x4 = 2.0;
  for (int k = 0; k < 4; ++k) x4 = std::nextafter(x4, 3.0);
  const Mesh leaning = build_cdt(test::polygon_domain({{2, 0}, {3, 0}, {3, 1}, {x4, 1}}, "leaning"));
  SizeFieldParams p;
  p.target_vertices = 2000;
  p.graded = true;
  const SizeField plain = make_size_field(leaning, p);
  p.scale = 0.8;
  const SizeField finer = make_size_field(leaning, p);
  for (const Point2& q : {Point2(2.99, 0.02), Point2(2.5, 0.02), Point2(2.99, 0.99)})  // out of the wall's raise
    EXPECT_NEAR(finer(q), 0.8 * plain(q), 1e-9 * plain(q)) << q.transpose();
  double n = 0;
  constexpr int kSteps = 20000;
  for (int k = 0; k < kSteps; ++k) n += (1.0 / kSteps) / finer({2.0 + (x4 - 2.0) * (k + 0.5) / kSteps, (k + 0.5) / kSteps});
  EXPECT_LE(n, 4.0 * 1.1);
  EXPECT_GE(n, 4.0 * 0.9);
  p.scale = 0;
  EXPECT_THROW(make_size_field(leaning, p), InvalidInput);
}

TEST(SizeField, a_field_given_up_at_its_abandon_time_says_so) {
  // The CVT start gives itself up on this flag, not on its own clock: a grading round predicted to
  // outlast the share used to return a uniform field early, and the CVT then ran on it (debug2
  // at 2,000 vertices under a 10 s limit: 15,000 vertices, 91% obtuse, instead of the refinement
  // start).
  const Domain d = test::wedge_with_hole();
  const Mesh cdt = build_cdt(d);
  SizeFieldParams p;
  p.target_vertices = 2000;
  p.graded = true;
  bool abandoned = true;
  const SizeField full = make_size_field(cdt, p, &abandoned);
  EXPECT_FALSE(abandoned);
  EXPECT_FALSE(full.is_uniform());
  p.abandon_after_s = 1e-12;
  const SizeField gone = make_size_field(cdt, p, &abandoned);
  EXPECT_TRUE(abandoned);
  EXPECT_TRUE(gone.is_uniform());
  abandoned = false;
  SizeFieldParams q;
  q.abandon_after_s = 1e-12;
  EXPECT_TRUE(local_feature_size_field(cdt, q, &abandoned).is_uniform());
  EXPECT_TRUE(abandoned);
}

}  // namespace
}  // namespace acute
