// A triangle mesh read as a domain (`acute mesh grid.obj`): its boundary bounds the new mesh, and
// the edges the file tags (OBJ polylines) are kept as interior segments.
#include <acute/io/io.h>
#include <acute/mesh/quality.h>
#include <acute/mesher.h>
#include <acute/repair/repair.h>

#include "support/domain_verify.h"
#include "support/paths.h"
#include "support/wedge_domains.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace acute {
namespace {

TEST(MeshDomain, obj_polyline_is_kept_as_a_chain_of_edges_and_the_bounds_are_met) {
  const std::string path = std::string(acute::test::test_data_dir()) + "/tagged_polyline.obj";
  const Domain domain = io::read_domain(path);
  MeshOptions options;
  options.target_vertices = 300;
  options.time_limit_s = 30;  // a safety net: the properties are asserted whatever stopped the run
  const MeshResult r = generate_mesh(domain, options);
  EXPECT_EQ(test::verify_conforms(r.mesh, domain, 9.0), "") << path;  // the polyline's segments covered too
  EXPECT_EQ(bad_triangles(r.mesh, AngleBounds{}).size(), 0u) << path << ": [30, 90) on a square with a bent interior polyline";
  EXPECT_GE(r.mesh.n_vertices(), 150u);
}

// --size is the largest edge length, not a uniform one: la's strips and narrow sectors are far
// narrower than a fortieth of its diameter, and at that size uniformly they kept obtuse triangles
// for the whole 60 s (18 at the limit); graded to their width the run meets [30, 90) in seconds.
TEST(MeshDomain, a_size_coarser_than_the_features_is_graded_down_to_them) {
  const std::string path = std::string(acute::test::meshes_dir()) + "/la.poly";
  const Domain domain = io::read_domain(path);
  MeshOptions options;
  options.size = 1.1;  // a fortieth of la's diameter (43.4)
  // A safety net against a hang, far above the run: 1.5 s in Release, 35 s under ASan on an idle
  // machine (a limit of 60 s cut it short on a loaded one, 4 bad triangles left).
  options.time_limit_s = 600;
  const MeshResult r = generate_mesh(domain, options);
  EXPECT_EQ(r.status, MeshStatus::Ok) << path << ": " << r.remaining.size() << " bad triangles left";
  EXPECT_EQ(test::verify_conforms(r.mesh, domain, mesh_area(build_domain_cdt(domain))), "") << path;
  // Away from the features the size is the one asked for: the longest edges are near it.
  double longest = 0;
  for (auto eh : r.mesh.edges()) longest = std::max(longest, static_cast<double>(r.mesh.calc_edge_length(eh)));
  EXPECT_GT(longest, 0.8 * options.size) << path;
  EXPECT_LT(longest, 2.0 * options.size) << path;
}

// An input corner of the min bound's own angle, to rounding (30 degrees from cos and sin: a few
// ulps to either side, and 5e-10 degrees off, inside the referee's 1e-9 tolerance). It is no
// forced corner, and its one triangle's angle there is the input's: the repair asked it for the
// 1e-6 safety margin too, so such a corner could never be met (8 s of restarts and "bounds not
// met" on a mesh the referee passed; a 5-pointed star of 30-degree tips, 42 s).
TEST(MeshDomain, an_input_corner_at_the_min_bound_to_rounding_meets_the_bounds) {
  for (double deg : {30.0, 30.0 + 5e-10, 30.0 - 5e-10}) {
    SCOPED_TRACE(deg);
    const Domain domain = test::sharp_wedge(deg);
    MeshOptions options;
    options.time_limit_s = 30;  // a safety net: each run takes milliseconds
    const MeshResult r = generate_mesh(domain, options);
    EXPECT_EQ(r.status, MeshStatus::Ok) << r.remaining.size() << " bad triangles left";
    EXPECT_EQ(test::verify_conforms(r.mesh, domain, mesh_area(build_domain_cdt(domain))), "");
    EXPECT_GE(measure_quality(r.mesh).min_angle, 30.0 - 1e-9);
  }
}

// A floating grid of interior segments 7 apart at the default size (4.9 near them): 7 / 4.9 rounds
// to one piece, so the sides of its cells were left whole, and a cell's four right angles had to
// share interior vertices over them: 5-98 bad triangles after 60 s with any seed. A piece between
// two right-angled corners is now cut at least once, and the grid meets the bounds in a second.
TEST(MeshDomain, a_grid_of_interior_segments_about_a_spacing_apart_meets_the_bounds) {
  const std::string path = std::string(acute::test::meshes_dir()) + "/cgrid_lines10_floating.poly";
  const Domain domain = io::read_domain(path);
  MeshOptions options;
  options.restarts = 0;
  options.time_limit_s = 60;  // a safety net: the run takes about a second
  const MeshResult r = generate_mesh(domain, options);
  EXPECT_EQ(r.status, MeshStatus::Ok) << r.remaining.size() << " bad triangles left";
  EXPECT_EQ(test::verify_conforms(r.mesh, domain, mesh_area(build_domain_cdt(domain))), "");
}

// A square with an interior Y of segments whose fork is 10 degrees, meshed at [35, 85): the apex
// triangle of the fork's sector has base angles of at least 85 degrees, so the bounds cannot hold
// there (the note says so). The repair counts that triangle as good while it is nearly isosceles,
// and converges on the rest: the verdict still names it, the only bad triangle. (It used to spend
// 150 iterations on it, 15 s; a deeper tree of such forks kept 56 obtuse triangles elsewhere.)
TEST(MeshDomain, an_unsatisfiable_fork_leaves_only_its_apex_triangle_bad) {
  Domain d;
  d.points = {Point2(0, 0), Point2(100, 0), Point2(100, 100), Point2(0, 100), Point2(50, 10), Point2(50, 45)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}};
  for (double deg : {85.0, 95.0}) {
    d.points.push_back(Point2(50, 45) + test::polar(50, deg));
    d.segments.push_back({5, static_cast<int>(d.points.size()) - 1});
  }
  MeshOptions options;
  options.min_angle_deg = 35;
  options.max_angle_deg = 85;
  options.time_limit_s = 60;  // a safety net: the run takes about a second
  const MeshResult r = generate_mesh(d, options);
  EXPECT_EQ(r.status, MeshStatus::BoundsNotMet);
  ASSERT_EQ(r.remaining.size(), 1u);
  EXPECT_LT(r.remaining[0].max_angle_deg, 85.0 + 0.5 + 1e-9) << "nearly isosceles";
  EXPECT_LT(r.iterations, 100) << "converged on the rest rather than stalled";
  EXPECT_TRUE(std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& n) { return n.find("unsatisfiable") != std::string::npos; }));
  EXPECT_EQ(test::verify_conforms(r.mesh, d, mesh_area(build_domain_cdt(d))), "");
}

/// A bundled CG:SHOP instance meshed at ~2,000 vertices (0: the default size) meets [30, 90) and
/// conforms (a time limit of 120 s as a safety net: each run takes a few seconds).
void expect_cgshop_instance_meets_the_bounds(const std::string& name, std::size_t vertices = 2000, int restarts = MeshOptions().restarts) {
  const std::string path = std::string(acute::test::meshes_dir()) + "/cgshop/" + name;
  const Domain domain = io::read_domain(path);
  MeshOptions options;
  options.target_vertices = vertices;
  options.restarts = restarts;
  options.time_limit_s = 120;
  const MeshResult r = generate_mesh(domain, options);
  EXPECT_EQ(r.status, MeshStatus::Ok) << name << ": " << r.remaining.size() << " bad triangles left";
  EXPECT_EQ(test::verify_conforms(r.mesh, domain, mesh_area(build_domain_cdt(domain))), "") << name;
}

// A 32.7-degree sector at an input corner (a CG:SHOP exterior instance) holds one triangle: its base
// angles stay below 90 only while the first vertices along its two walls are nearly as far from the
// corner. At ~2,000 vertices they were 2.40 and 2.85 away (a right angle at the nearer one, whose
// other side then had two right triangles) and no move or split mended it in 150 iterations; the
// repair now also equalises the first radii of sectors narrower than twice the min bound (inward,
// and outward: the nearer moved out, when moving the farther in leaves a wall vertex short).
TEST(MeshDomain, a_sector_narrower_than_twice_the_min_bound_gets_an_apex_triangle_within_the_bounds) {
  expect_cgshop_instance_meets_the_bounds("simple-polygon-exterior_250_a97729dd.instance.json");  // about 1.5 s
}

// An input point 1.5 above a side 6,650 long (a CG:SHOP point set). A stuck cluster there was
// re-sampled at the region's median spacing (110), which divided the side at 110 below the point:
// one 178-degree triangle for 200 iterations. The re-sampling now grades its spacing down to the
// features that stay (the point's distance to the side).
TEST(MeshDomain, an_input_point_close_to_a_long_side_meets_the_bounds) {
  expect_cgshop_instance_meets_the_bounds("point-set_60_27bc003d.instance.json");  // about 3 s
}

// A 90-degree input sector covered by one right triangle (a CG:SHOP exterior instance: an interior
// segment leaves the boundary at a right angle). Its mend takes two steps, the point on the corner's
// bisector and then a vertex more for that point's star of four triangles; the two-step search
// expanded the six best first steps, and six no-ops (smoothing alone, flips the smoothing undid)
// scored as well as the region and ranked ahead of the bisector point: 150 iterations, 90.000
// degrees. No-op first steps are no longer expanded.
TEST(MeshDomain, a_right_angled_input_sector_of_one_triangle_meets_the_bounds) {
  expect_cgshop_instance_meets_the_bounds("simple-polygon-exterior-20_150_7768dd44.instance.json");  // about 3 s
}

// A 4.65-degree strip between a boundary side 7,000 long and a segment (a CG:SHOP exterior
// instance). The size field came out NaN at one point of that side (a background triangle of zero
// rounded area among its collinear samples): the CVT start left the side undivided, the strip a fan
// of slivers, and after 60 s one 92-degree triangle stayed at the strip's apex. Now the side is
// divided along the strip's width and the instance meets the bounds in under a second.
TEST(MeshDomain, a_long_boundary_side_of_a_narrow_strip_is_divided_and_meets_the_bounds) {
  expect_cgshop_instance_meets_the_bounds("simple-polygon-exterior_20_87cff693.instance.json");  // about 1 s
}

// A 34-degree corner between two interior segments (a CG:SHOP exterior instance) at the default
// size: its sector holds one triangle, and the start left the mesh beyond it one triangle wide, so
// a base vertex of the apex triangle kept two triangles on its straight side (90.0008 + 89.999
// degrees). Every single edit scored worse, and three seeds met the same plateau (70 s, one obtuse
// triangle). A restart with a 5% finer start met the bounds (8.7 s); now the repair mends it in
// place without one (about 3 s): the apex triangle made isosceles and a point put beyond it
// (apex_with_middle_point) is a first step the two-step search always expands, though it scores
// worse alone (that point has four neighbours until the second step gives it a fifth).
TEST(MeshDomain, a_one_triangle_corner_between_interior_segments_is_mended_without_a_restart) {
  expect_cgshop_instance_meets_the_bounds("simple-polygon-exterior_40_785575e7.instance.json", 0, /*restarts=*/0);
}

// A plateau of the repair's search: a segment vertex left with two right triangles on one side
// (90 + 90 on a straight wall), where every candidate edit scores worse than the region as it is
// (a split adds a vertex of degree four, a flip or a move keeps the right angle). Two CG:SHOP
// exterior instances stayed at 90.000 and 90.034 degrees for 150 iterations. On a plateau the
// repair now kicks: every fifth iteration a cluster takes its best candidate even when worse, and
// the search goes on from there (the best mesh so far is kept aside).
TEST(MeshDomain, a_segment_vertex_with_two_right_triangles_on_a_side_meets_the_bounds) {
  expect_cgshop_instance_meets_the_bounds("simple-polygon-exterior_80_22d34c7e.instance.json");   // about 2 s
  expect_cgshop_instance_meets_the_bounds("simple-polygon-exterior_100_37aaf06f.instance.json");  // about 5 s
}

// The end of a strip one triangle wide between two 90-degree input corners (a CG:SHOP ortho
// instance at ~200 vertices, whose features alone ask for 3,700 at a coarsened size): one corner
// keeps one right triangle, and mending it takes a second row of triangles at the strip's end,
// points finer than the local spacing. The stuck cluster's re-sampling went down to 0.65 of that
// spacing, still one row: after two restarts, 90.000 degrees. It now also tries half.
TEST(MeshDomain, the_end_of_a_strip_one_triangle_wide_between_right_angles_meets_the_bounds) {
  expect_cgshop_instance_meets_the_bounds("ortho_150_53eb4022.instance.json", 200);  // about 6 s
}

// A stalled repair restarts from another seed's start (MeshOptions::restarts). At ~500 vertices the
// 32.7-degree sector's instance stalled for 150 iterations at 90.001 degrees with the first seed,
// the kicks and the sector re-fan notwithstanding; the restart meets the bounds (about 19 s in all).
TEST(MeshDomain, a_stalled_repair_restarts_from_another_seed_and_meets_the_bounds) {
  expect_cgshop_instance_meets_the_bounds("simple-polygon-exterior_250_a97729dd.instance.json", 500);
}

// A steep size gradation leaves plateaus where sizes change fast: at --gradation 1.5-2
// square_with_crack kept one or two 28.8-degree triangles at a corner of its 1e-4 slot (three small
// triangles between edges three times longer), whatever the seed. Restarts now grade more gently,
// down to the default (about 5 s). Asked for 3, the run is capped to 1.5, and the note saying so
// stays when a restart's mesh replaces the first run's.
TEST(MeshDomain, a_steep_gradation_that_stalls_restarts_more_gently_graded_and_meets_the_bounds) {
  const Domain domain = io::read_domain(std::string(acute::test::meshes_dir()) + "/square_with_crack.poly");
  MeshOptions options;
  options.target_vertices = 1000;
  options.gradation = 3;
  const MeshResult r = generate_mesh(domain, options);
  EXPECT_EQ(r.status, MeshStatus::Ok) << r.remaining.size() << " bad triangles left";
  EXPECT_EQ(test::verify_conforms(r.mesh, domain, mesh_area(build_domain_cdt(domain))), "");
  EXPECT_TRUE(std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& n) { return n.find("graded at") != std::string::npos; }));
  ASSERT_FALSE(r.notes.empty());
  EXPECT_EQ(r.notes.front(), "gradation 3 is steeper than the acute method follows: 1.5 used");
}

// A gradation steeper than the acute method follows is capped, and said so.
TEST(MeshDomain, a_gradation_steeper_than_the_acute_method_follows_is_capped_with_a_note) {
  const Domain domain = io::read_domain(std::string(acute::test::meshes_dir()) + "/A.poly");
  MeshOptions options;
  options.gradation = 3;
  const MeshResult r = generate_mesh(domain, options);
  EXPECT_EQ(r.status, MeshStatus::Ok);
  EXPECT_EQ(test::verify_conforms(r.mesh, domain, mesh_area(build_domain_cdt(domain))), "");
  ASSERT_FALSE(r.notes.empty());
  EXPECT_EQ(r.notes.front(), "gradation 3 is steeper than the acute method follows: 1.5 used");
  options.gradation = 1.5;
  const MeshResult at_cap = generate_mesh(domain, options);
  EXPECT_EQ(at_cap.mesh.n_vertices(), r.mesh.n_vertices());
  EXPECT_TRUE(std::none_of(at_cap.notes.begin(), at_cap.notes.end(), [](const std::string& n) { return n.find("steeper") != std::string::npos; }));
}

}  // namespace
}  // namespace acute
