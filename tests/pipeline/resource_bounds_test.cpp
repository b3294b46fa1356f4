// Resource bounds of the default pipeline on a domain whose features alone call for far more
// vertices than requested (a boundary of many tiny teeth, like shared/domains/classic/debug2):
// --max-vertices and --time-limit must end the run with a valid, conforming mesh within the budget
// and a note saying what stopped it. Nothing here is timed: a near-zero time limit only has to
// give a valid mesh.
#include <acute/cvt/cvt.h>
#include <acute/mesh/check.h>
#include <acute/mesher.h>
#include <acute/refine/refine.h>
#include <acute/repair/repair.h>
#include <acute/repair_mesh.h>

#include "support/domain_verify.h"

#include <gtest/gtest.h>

#include <string>

namespace acute {
namespace {

/// The unit square whose bottom side is `teeth` teeth 1e-4 high.
Domain toothed_square(int teeth) {
  Domain d;
  d.name = "toothed_square";
  for (int i = 0; i <= 2 * teeth; ++i) d.points.emplace_back(static_cast<double>(i) / (2 * teeth), i % 2 ? -1e-4 : 0.0);
  d.points.emplace_back(1.0, 1.0);
  d.points.emplace_back(0.0, 1.0);
  const int n = static_cast<int>(d.points.size());
  for (int i = 0; i < n; ++i) d.segments.push_back({i, (i + 1) % n});
  return d;
}

bool has_note(const MeshResult& r, const std::string& word) {
  for (const auto& n : r.notes)
    if (n.find(word) != std::string::npos) return true;
  return false;
}

// Without a time limit the features decide: a strip 1 long and 1e-3 wide at a 10-vertex request
// (its features alone ask for some thousand) is meshed at its width, and meets the bounds.
TEST(ResourceBounds, features_needing_far_more_than_the_request_decide_the_count_without_a_time_limit) {
  Domain d;
  d.name = "strip";
  d.points = {{0, 0}, {1, 0}, {1, 1e-3}, {0, 1e-3}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  MeshOptions options;
  options.target_vertices = 10;
  std::vector<std::string> early;  // told while the run goes on, before the CVT and the repair
  options.on_note = [&](const std::string& note) { early.push_back(note); };
  const MeshResult r = generate_mesh(d, options);
  EXPECT_EQ(r.status, MeshStatus::Ok);
  EXPECT_GT(r.mesh.n_vertices(), 16u * 10u) << "more than the count held under a time limit";
  EXPECT_TRUE(has_note(r, "small features need a finer size"));
  ASSERT_EQ(early.size(), 1u);
  EXPECT_NE(early[0].find("small features need"), std::string::npos) << early[0];
  EXPECT_EQ(bad_triangles(r.mesh, AngleBounds{}).size(), 0u);
  EXPECT_EQ(test::verify_conforms(r.mesh, d, mesh_area(build_domain_cdt(d))), "");
  EXPECT_EQ(test::verify_segment_chains(r.mesh, d), "");
}

TEST(ResourceBounds, no_early_note_where_the_request_decides_the_count) {
  Domain d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  MeshOptions options;
  options.target_vertices = 200;
  std::vector<std::string> early;
  options.on_note = [&](const std::string& note) { early.push_back(note); };
  EXPECT_EQ(generate_mesh(d, options).status, MeshStatus::Ok);
  EXPECT_TRUE(early.empty()) << early.front();
}

/// The CVT start alone (the repair has its own budget tests) of a 500-tooth square (1003 input
/// points) at a 200-vertex target under a vertex budget: within it, valid and conforming.
void expect_cvt_start_within(std::size_t max_vertices) {
  const Domain d = toothed_square(500);
  MeshOptions options;
  options.method = Method::Cvt;
  options.target_vertices = 200;
  options.max_vertices = max_vertices;
  const MeshResult r = generate_mesh(d, options);
  EXPECT_LE(r.mesh.n_vertices(), options.max_vertices);
  EXPECT_EQ(test::verify_conforms(r.mesh, d, mesh_area(build_domain_cdt(d))), "");
  EXPECT_EQ(test::verify_segment_chains(r.mesh, d), "");
}

TEST(ResourceBounds, vertex_budget_below_what_the_features_need_gives_a_valid_mesh_within_it) {
  expect_cvt_start_within(1500);  // the CVT start had ~2000 vertices unbounded
}

TEST(ResourceBounds, budget_barely_above_the_input_points_falls_back_to_a_refinement_within_it) {
  expect_cvt_start_within(1010);
}

TEST(ResourceBounds, exhausted_time_limit_still_gives_a_valid_mesh) {
  const Domain d = toothed_square(200);
  MeshOptions options;
  options.target_vertices = 200;
  options.time_limit_s = 1e-6;
  const MeshResult r = generate_mesh(d, options);
  EXPECT_TRUE(has_note(r, "time limit"));
  EXPECT_TRUE(has_note(r, "in its size field")) << "the CVT start is given up: a refinement start within the limit";
  EXPECT_EQ(test::verify_conforms(r.mesh, d, mesh_area(build_domain_cdt(d))), "");
  EXPECT_EQ(test::verify_segment_chains(r.mesh, d), "");
}

// A domain whose size field alone outlasts the CVT's share of the time limit (a 3.7M-vertex mesh of
// debug2 given to `acute repair --time-limit 30` computed its size field for over 300 s): the CVT
// start gives up after the lfs samples (and the pipeline starts the repair from a Delaunay refinement: see
// exhausted_time_limit_still_gives_a_valid_mesh).
TEST(ResourceBounds, cvt_start_past_its_share_after_the_size_field_is_abandoned) {
  const Domain d = toothed_square(200);
  CvtParams cp;
  cp.graded = true;
  cp.target_vertices = 200;
  cp.time_limit_s = 1e-9;
  const CvtResult cvt = cvt_mesh(d, cp);
  EXPECT_TRUE(cvt.abandoned);
  EXPECT_TRUE(cvt.out_of_time);
  EXPECT_EQ(cvt.mesh.n_vertices(), 0u);
}

/// A Delaunay refinement (20 degrees) of the toothed square: many triangles outside [30, 90).
Mesh refined_toothed_square() {
  Mesh mesh = build_domain_cdt(toothed_square(200));
  RefineParams rp;
  rp.min_angle_deg = 20;
  refine(mesh, rp);
  return mesh;
}

TEST(ResourceBounds, repair_stops_at_an_exhausted_time_limit_with_a_valid_mesh) {
  Mesh mesh = refined_toothed_square();
  RepairParams params;
  params.bounds.min_deg = 30;
  params.bounds.max_deg = 90;
  ASSERT_FALSE(bad_triangles(mesh, params.bounds).empty());
  params.time_limit_s = 1e-9;
  const RepairResult r = repair_acute(mesh, params);
  EXPECT_EQ(r.status, RepairStatus::TimeLimit);
  EXPECT_TRUE(check_mesh(mesh, CheckLevel::Geometry).ok());
}

TEST(ResourceBounds, repair_of_a_mesh_honours_the_time_limit_in_its_start_mesh_too) {
  // The whole `acute repair` (its CVT start included, not only the repair after it) is bounded:
  // an exhausted limit stops the start, says so, and still gives a valid mesh of the region.
  const Mesh in = refined_toothed_square();
  RepairMeshOptions o;
  o.time_limit_s = 1e-9;
  const RepairMeshResult r = repair_mesh(in, o);
  bool noted = false;
  for (const auto& n : r.notes) noted = noted || n.find("time limit") != std::string::npos;
  EXPECT_TRUE(noted);
  EXPECT_TRUE(check_mesh(r.mesh, CheckLevel::Geometry).ok());
  EXPECT_NEAR(mesh_area(r.mesh), mesh_area(in), 1e-9);
}

}  // namespace
}  // namespace acute
