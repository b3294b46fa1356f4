// Delaunay refinement: validity, the angle bound away from forced corners, the size bound,
// conformity to the input segments, determinism and the vertex budget.
#include "support/mesh_verify.h"
#include "support/paths.h"

#include <acute/io/io.h>
#include <acute/mesh/check.h>
#include <acute/mesh/geometry.h>
#include <acute/mesh/quality.h>
#include <acute/mesh/segments.h>
#include <acute/mesher.h>
#include <acute/refine/refine.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace acute {
namespace {

constexpr double kPi = 3.14159265358979323846;

Domain polygon(const std::string& name, const std::vector<Point2>& pts) {
  Domain d;
  d.name = name;
  d.points = pts;
  const int n = static_cast<int>(pts.size());
  for (int i = 0; i < n; ++i) d.segments.push_back({i, (i + 1) % n});
  return d;
}

void add_loop(Domain& d, const std::vector<Point2>& pts) {
  const int base = static_cast<int>(d.points.size()), n = static_cast<int>(pts.size());
  for (int i = 0; i < n; ++i) {
    d.points.push_back(pts[static_cast<std::size_t>(i)]);
    d.segments.push_back({base + i, base + (i + 1) % n});
  }
}

Point2 polar(double r, double deg) { return Point2(r * std::cos(deg * kPi / 180), r * std::sin(deg * kPi / 180)); }

Domain square() { return polygon("square", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}); }
Domain l_shape() { return polygon("l-shape", {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}); }
Domain thin_channel() { return polygon("thin-channel", {{0, 0}, {10, 0}, {10, 0.05}, {0, 0.05}}); }

/// A 5-degree corner at the origin and a 20-degree corner at (26, 0).
Domain sharp_corners() {
  const Point2 e(26, 0);
  return polygon("sharp-5-20", {Point2(0, 0), polar(10, -2.5), e + polar(10, 190), e, e + polar(10, 170), polar(10, 2.5)});
}

Domain square_with_hole() {
  Domain d = polygon("square-with-hole", {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  add_loop(d, {{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}});
  d.holes.push_back({0.5, 0.5});
  return d;
}

/// Three segments meeting at the origin at 8 and 12 degrees inside a square, plus a slit.
Domain fan_of_segments() {
  Domain d = polygon("fan-of-segments", {{-1, -1}, {3, -1}, {3, 3}, {-1, 3}});
  const int o = static_cast<int>(d.points.size());
  d.points.push_back({0, 0});
  for (double deg : {30.0, 38.0, 50.0}) {
    d.points.push_back(polar(2, deg));
    d.segments.push_back({o, static_cast<int>(d.points.size()) - 1});
  }
  return d;
}

std::vector<Domain> hand_made() { return {square(), l_shape(), thin_channel(), sharp_corners(), square_with_hole(), fan_of_segments()}; }

Mesh refined(const Domain& d, const RefineParams& params, RefineResult* result = nullptr) {
  Mesh mesh = build_domain_cdt(d);
  const RefineResult r = refine(mesh, params);
  if (result) *result = r;
  return mesh;
}

/// Mesh vertices at forced corners (by input index).
std::set<int> forced_vertices(const Mesh& mesh, const Domain& d, double min_angle) {
  std::set<int> points, out;
  for (const auto& fc : forced_corners(d, min_angle)) points.insert(fc.point);
  for (auto vh : mesh.vertices())
    if (points.count(mesh.data(vh).input_index)) out.insert(vh.idx());
  return out;
}

/// Smallest angle over triangles not incident on a forced corner (180 when there are none).
double free_min_angle(const Mesh& mesh, const Domain& d, double min_angle) {
  const auto forced = forced_vertices(mesh, d, min_angle);
  double worst = 180;
  for (auto fh : mesh.faces()) {
    const auto v = face_vertices(mesh, fh);
    if (forced.count(v[0].idx()) || forced.count(v[1].idx()) || forced.count(v[2].idx())) continue;
    const auto p = face_points(mesh, fh);
    for (double a : triangle_angles_deg(p[0], p[1], p[2])) worst = std::min(worst, a);
  }
  return worst;
}

/// Every input segment is covered by mesh edges carrying its id, whose ends lie on it, as far as
/// the CDT `cdt` of the domain covers it (segments outside the domain are dropped).
std::string verify_conforming(const Mesh& mesh, const Domain& d, const Mesh& cdt) {
  std::vector<double> expected(d.segments.size(), 0.0);
  for (auto eh : cdt.edges())
    if (cdt.data(eh).segment >= 0) expected[static_cast<std::size_t>(cdt.data(eh).segment)] += cdt.calc_edge_length(eh);
  std::vector<double> covered(d.segments.size(), 0.0);
  if (segment_table(mesh).size() != d.segments.size()) return "segment table has " + std::to_string(segment_table(mesh).size()) + " entries";
  for (auto eh : mesh.edges()) {
    const int s = mesh.data(eh).segment;
    if (s < 0) continue;
    if (s >= static_cast<int>(d.segments.size())) return "edge with unknown segment id " + std::to_string(s);
    const Point2 a = d.points[static_cast<std::size_t>(d.segments[static_cast<std::size_t>(s)][0])];
    const Point2 b = d.points[static_cast<std::size_t>(d.segments[static_cast<std::size_t>(s)][1])];
    const auto h = mesh.halfedge_handle(eh, 0);
    for (auto vh : {mesh.from_vertex_handle(h), mesh.to_vertex_handle(h)}) {
      const Point2 p = point2(mesh, vh);
      if (std::abs(signed_area2(a, b, p)) > 1e-10 * (b - a).squaredNorm()) return "vertex " + std::to_string(vh.idx()) + " off segment " + std::to_string(s);
    }
    covered[static_cast<std::size_t>(s)] += (point2(mesh, mesh.from_vertex_handle(h)) - point2(mesh, mesh.to_vertex_handle(h))).norm();
  }
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    const double len = expected[s];
    if (std::abs(covered[s] - len) > 1e-9 * len) return "segment " + std::to_string(s) + " covered " + std::to_string(covered[s]) + " of " + std::to_string(len);
  }
  return {};
}

void expect_good(const Mesh& mesh, const Domain& d, double min_angle) {
  const Mesh cdt = build_domain_cdt(d);
  const double area = test::total_area(cdt);
  EXPECT_EQ(test::verify_valid(mesh), "") << d.name;
  // No violation beyond those of the CDT itself (check_mesh accepts pinch vertices since issue 6).
  const auto report = check_mesh(mesh, CheckLevel::Delaunay), before = check_mesh(cdt, CheckLevel::Delaunay);
  EXPECT_EQ(report.total, before.total) << d.name << ": " << report.summary() << " (CDT: " << before.summary() << ")";
  EXPECT_EQ(verify_conforming(mesh, d, cdt), "") << d.name;
  EXPECT_NEAR(test::total_area(mesh), area, 1e-9 * area) << d.name;
  EXPECT_GE(free_min_angle(mesh, d, min_angle), min_angle) << d.name;
}

TEST(Refine, hand_made_domains_meet_30_degrees_away_from_forced_corners) {
  for (const auto& d : hand_made()) {
    RefineParams params;
    params.min_angle_deg = 30;
    RefineResult r;
    const Mesh mesh = refined(d, params, &r);
    EXPECT_EQ(r.status, RefineStatus::Converged) << d.name;
    EXPECT_LT(mesh.n_vertices(), 20000u) << d.name;
    expect_good(mesh, d, 30);
  }
}

TEST(Refine, other_bounds_and_circumcentres) {
  for (const auto& d : hand_made())
    for (double bound : {20.7, 33.0})
      for (bool off : {true, false}) {
            RefineParams params;
        params.min_angle_deg = bound;
        params.off_centers = off;
        RefineResult r;
        const Mesh mesh = refined(d, params, &r);
        EXPECT_EQ(r.status, RefineStatus::Converged) << d.name << " bound " << bound << " off-centres " << off;
        expect_good(mesh, d, bound);
      }
}

TEST(Refine, forced_corners_are_the_only_small_angles) {
  // The 5- and 20-degree corners keep their angle; all other triangles meet the bound.
  const Domain d = sharp_corners();
  ASSERT_EQ(forced_corners(d, 30).size(), 2u);
  RefineParams params;
  params.min_angle_deg = 30;
  const Mesh mesh = refined(d, params);
  const QualityReport q = measure_quality(mesh, {}, &d);
  EXPECT_NEAR(q.min_angle, 5.0, 1e-6) << d.name;
  ASSERT_TRUE(q.free_min_angle.has_value()) << d.name;
  EXPECT_GE(*q.free_min_angle, 30.0) << d.name;
  EXPECT_EQ(q.n_below_min_free, 0u) << d.name;
}

TEST(Refine, size_bound_is_respected) {
  for (const auto& d : hand_made()) {
    for (double h : {0.3, 0.05}) {
      RefineParams params;
      params.min_angle_deg = 30;
      params.max_edge = h;
      const Mesh mesh = refined(d, params);
      expect_good(mesh, d, 30);
      double worst = 0;
      for (auto fh : mesh.faces()) {
        const auto p = face_points(mesh, fh);
        worst = std::max(worst, (circumcenter(p[0], p[1], p[2]) - p[0]).norm());
      }
      EXPECT_LE(worst, h / std::sqrt(3.0) * (1 + 1e-12)) << d.name << " size " << h;
    }
  }
}

TEST(Refine, vertex_count_follows_size) {
  // Equilateral density: about 2A / (sqrt(3) h^2) vertices; refinement gives the same order.
  RefineParams params;
  params.max_edge = 0.02;
  const Mesh mesh = refined(square(), params);
  const double expected = 2.0 / (std::sqrt(3.0) * 0.02 * 0.02);
  EXPECT_GT(static_cast<double>(mesh.n_vertices()), 0.5 * expected) << "square";
  EXPECT_LT(static_cast<double>(mesh.n_vertices()), 2.5 * expected) << "square";
}

TEST(Refine, deterministic) {
  for (const auto& d : hand_made()) {
    RefineParams params;
    params.min_angle_deg = 30;
    params.max_edge = 0.1;
    const Mesh a = refined(d, params), b = refined(d, params);
    ASSERT_EQ(a.n_vertices(), b.n_vertices()) << d.name;
    ASSERT_EQ(a.n_faces(), b.n_faces()) << d.name;
    bool same = true;
    for (auto vh : a.vertices()) same = same && point2(a, vh) == point2(b, VertexHandle(vh.idx()));
    for (auto fh : a.faces()) same = same && face_vertices(a, fh) == face_vertices(b, FaceHandle(fh.idx()));
    EXPECT_TRUE(same) << d.name;
  }
}

TEST(Refine, budget_stops_runaway_refinement) {
  RefineParams params;
  params.max_edge = 0.001;
  params.max_vertices = 500;
  RefineResult r;
  const Mesh mesh = refined(square(), params, &r);
  EXPECT_EQ(r.status, RefineStatus::BudgetExhausted) << "square";
  EXPECT_LE(mesh.n_vertices(), 500u) << "square";
  EXPECT_EQ(test::verify_valid(mesh), "") << "square";
  EXPECT_TRUE(check_mesh(mesh, CheckLevel::Delaunay).ok()) << "square";
}

// A time limit already past stops refinement at its first clock check (every 256 steps), with a
// valid constrained Delaunay mesh: the CVT-fallback start of the pipeline relies on it.
TEST(Refine, time_limit_stops_runaway_refinement) {
  RefineParams params;
  params.max_edge = 0.001;
  params.max_vertices = 200000;
  params.time_limit_s = 1e-9;
  RefineResult r;
  const Mesh mesh = refined(square(), params, &r);
  EXPECT_EQ(r.status, RefineStatus::OutOfTime) << "square";
  EXPECT_LT(mesh.n_vertices(), 2000u) << "square";
  EXPECT_EQ(test::verify_valid(mesh), "") << "square";
  EXPECT_TRUE(check_mesh(mesh, CheckLevel::Delaunay).ok()) << "square";
}

TEST(Refine, pipeline_method_refine_with_vertex_target) {
  MeshOptions o;
  o.method = Method::Refine;
  o.target_vertices = 2000;
  const MeshResult r = generate_mesh(l_shape(), o);
  EXPECT_GT(r.mesh.n_vertices(), 1000u) << "l-shape";
  EXPECT_LT(r.mesh.n_vertices(), 5000u) << "l-shape";
  EXPECT_GE(free_min_angle(r.mesh, l_shape(), 30), 30.0) << "l-shape";
}

TEST(Refine, classic_domains_with_small_angles) {
  const fs::path dir = fs::path(acute::test::shared_dir()) / "domains" / "classic";
  if (!fs::exists(dir)) GTEST_SKIP() << "no shared domains at " << dir;
  for (const char* name : {"la", "debug", "clusters", "fish-and-rectangle", "bird", "superior", "trivial", "A"}) {
    const Domain d = io::read_domain((dir / (std::string(name) + ".poly")).string());
    RefineParams params;
    params.min_angle_deg = 30;
    RefineResult r;
    const Mesh mesh = refined(d, params, &r);
    EXPECT_EQ(r.status, RefineStatus::Converged) << name;
    EXPECT_LT(mesh.n_vertices(), 20000u) << name;
    expect_good(mesh, d, 30);
  }
}

}  // namespace
}  // namespace acute
