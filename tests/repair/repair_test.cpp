#include <acute/io/io.h>
#include <acute/mesh/check.h>
#include <acute/mesher.h>
#include <acute/repair/repair.h>

#include "repair/region.h"
#include "support/mesh_verify.h"
#include "support/paths.h"

#include <algorithm>
#include <set>

namespace acute {
namespace {

Domain polygon(std::vector<Point2> pts) {
  Domain d;
  d.points = std::move(pts);
  for (int i = 0; i < static_cast<int>(d.points.size()); ++i) d.segments.push_back({i, (i + 1) % static_cast<int>(d.points.size())});
  return d;
}

/// d with an interior segment from p to p + v (the domain continues on both sides of it).
Domain with_segment(Domain d, const Point2& p, const Point2& v) {
  const int n = static_cast<int>(d.points.size());
  d.points.push_back(p);
  d.points.push_back(p + v);
  d.segments.push_back({n, n + 1});
  return d;
}

/// Every input point is still a vertex, exactly.
void expect_input_points_kept(const Mesh& mesh, const Domain& domain) {
  std::set<std::pair<double, double>> vertices;
  for (auto vh : mesh.vertices()) vertices.insert({mesh.point(vh)[0], mesh.point(vh)[1]});
  for (const auto& p : domain.points) EXPECT_TRUE(vertices.count({p.x(), p.y()})) << "input point " << p.transpose();
}

void expect_acute(const Mesh& mesh, const char* name) {
  for (auto fh : mesh.faces()) {
    Point2 p[3];
    int k = 0;
    for (auto vh : mesh.fv_range(fh)) p[k++] = point2(mesh, vh);
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(predicates::angle_kind(p[i], p[(i + 1) % 3], p[(i + 2) % 3]), AngleKind::Acute) << name << ": face " << fh.idx();
  }
}

struct Case {
  const char* name;
  Domain domain;
  int corners = 4;  ///< points of the outer polygon (the first ones)
};

class AcutePipeline : public ::testing::TestWithParam<int> {};

std::vector<Case> cases() {
  return {
      {"unit_square", polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}})},
      {"l_shape", polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}), 6},
      {"hexagon", polygon({{2, 0}, {1, 1.7320508075688772}, {-1, 1.7320508075688772}, {-2, 0}, {-1, -1.7320508075688772}, {1, -1.7320508075688772}}), 6},
      {"trapezoid_with_45_degree_corners", polygon({{0, 0}, {6, 0}, {4, 2}, {2, 2}})},
      {"square_with_isolated_segment_1e-3", with_segment(polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), {0.44382, 0.08974}, {0.6e-3, -0.8e-3})},
      {"square_with_isolated_segment_1e-6", with_segment(polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), {0.44382, 0.08974}, {0.6e-6, -0.8e-6})},
  };
}

TEST_P(AcutePipeline, meets_30_90_keeps_input_and_constraints) {
  const Case c = cases()[static_cast<std::size_t>(GetParam())];
  MeshOptions options;
  options.target_vertices = 400;
  const MeshResult result = generate_mesh(c.domain, options);
  EXPECT_EQ(result.status, MeshStatus::Ok) << c.name << ": " << result.remaining.size() << " bad triangles left";
  EXPECT_MESH_VALID(result.mesh);
  EXPECT_TRUE(check_mesh(result.mesh, CheckLevel::Delaunay).ok()) << c.name << ": " << check_mesh(result.mesh, CheckLevel::Delaunay).summary();
  EXPECT_EQ(detail::constraint_violation(result.mesh), "") << c.name;
  expect_input_points_kept(result.mesh, c.domain);
  if (result.status == MeshStatus::Ok) {
    expect_acute(result.mesh, c.name);
    EXPECT_TRUE(bad_triangles(result.mesh, AngleBounds{}).empty()) << c.name;
  }
  double area = 0;
  for (auto fh : result.mesh.faces()) (void)fh, area = test::total_area(result.mesh);
  // The outer polygon's area (its segments are the first ones, in order; interior segments add none).
  double expected = 0;
  const auto& pts = c.domain.points;
  for (const auto& seg : c.domain.segments) {
    if (seg[0] >= c.corners) continue;
    const Point2& a = pts[static_cast<std::size_t>(seg[0])];
    const Point2& b = pts[static_cast<std::size_t>(seg[1])];
    expected += 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  EXPECT_NEAR(area, expected, 1e-12 * expected) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Domains, AcutePipeline, ::testing::Range(0, 6));

TEST(Repair, deterministic_for_a_seed) {
  const Domain d = polygon({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {0, 2}});
  MeshOptions options;
  options.target_vertices = 300;
  const Mesh a = generate_mesh(d, options).mesh;
  const Mesh b = generate_mesh(d, options).mesh;
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  for (auto vh : a.vertices()) EXPECT_EQ(a.point(vh), b.point(VertexHandle(vh.idx()))) << "vertex " << vh.idx();
}

TEST(Repair, never_fails_the_budget_contract) {
  // An iteration cap of 1 must still return a valid mesh and report the remaining triangles.
  const Domain d = polygon({{0, 0}, {5, 0}, {5, 0.7}, {0, 0.7}});
  MeshOptions options;
  options.target_vertices = 200;
  options.max_iterations = 1;
  const MeshResult result = generate_mesh(d, options);
  EXPECT_MESH_VALID(result.mesh);
  EXPECT_EQ(detail::constraint_violation(result.mesh), "");
  if (result.status != MeshStatus::Ok) {
    EXPECT_FALSE(result.remaining.empty());
  }
}

}  // namespace
}  // namespace acute

namespace acute {
namespace {

// Regression (stress seed, issue 9): two triangles touching at one vertex; region copies around the
// pinch used to re-add faces at a complex vertex and leave an invalid mesh.
TEST(Repair, regression_pinch_vertex_domain_stays_valid) {
  const Domain d = io::read_poly(std::string(acute::test::test_data_dir()) + "/regressions/pinch_vertex.poly");
  MeshOptions options;
  options.target_vertices = 300;
  const MeshResult result = generate_mesh(d, options);
  EXPECT_MESH_VALID(result.mesh);
  EXPECT_EQ(detail::constraint_violation(result.mesh), "");
  expect_input_points_kept(result.mesh, d);
  EXPECT_NEAR(test::total_area(result.mesh), test::total_area(build_domain_cdt(d)), 1e-12 * test::total_area(result.mesh));
}

}  // namespace
}  // namespace acute
