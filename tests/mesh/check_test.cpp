#include "mesh/builders.h"

#include <acute/mesh/check.h>

#include <gtest/gtest.h>

namespace acute {
namespace {

bool mentions(const CheckReport& r, const std::string& text) {
  for (const auto& v : r.violations)
    if (v.find(text) != std::string::npos) return true;
  return false;
}

TEST(CheckMesh, valid_grid_passes_every_level) {
  for (int n : {1, 2, 5}) {
    const Mesh m = test::grid(n);
    const auto r = check_mesh(m, CheckLevel::Delaunay);
    EXPECT_TRUE(r.ok()) << "grid " << n << ": " << r.summary();
    EXPECT_EQ(r.summary(), "ok") << "grid " << n;
  }
}

TEST(CheckMesh, clockwise_face_is_named) {
  // Face 1 is given clockwise; as an isolated triangle OpenMesh accepts it.
  const Mesh m = test::make_mesh({{0, 0}, {1, 0}, {0, 1}, {3, 0}, {4, 0}, {3, 1}}, {{0, 1, 2}, {3, 5, 4}});
  EXPECT_TRUE(check_mesh(m, CheckLevel::Topology).ok()) << check_mesh(m, CheckLevel::Topology).summary();
  const auto r = check_mesh(m, CheckLevel::Geometry);
  ASSERT_EQ(r.violations.size(), 1u) << r.summary();
  EXPECT_EQ(r.violations[0].rfind("face 1: not counter-clockwise", 0), 0u) << r.violations[0];
}

TEST(CheckMesh, degenerate_face_is_reported) {
  const Mesh m = test::make_mesh({{0, 0}, {1, 1}, {2, 2}}, {{0, 1, 2}});
  const auto r = check_mesh(m, CheckLevel::Geometry);
  EXPECT_TRUE(mentions(r, "face 0: degenerate")) << r.summary();
}

TEST(CheckMesh, duplicate_positions_are_found) {
  // Two separate triangles sharing a position through different vertices (3 == 1).
  const Mesh m = test::make_mesh({{0, 0}, {1, 0}, {0, 1}, {1, 0}, {2, 0}, {2, 1}}, {{0, 1, 2}, {3, 4, 5}});
  const auto r = check_mesh(m, CheckLevel::Topology);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(mentions(r, "vertices 1 and 3: same position")) << r.summary();
  EXPECT_EQ(r.total, 1u) << r.summary();
}

TEST(CheckMesh, duplicate_search_scales) {
  const Mesh m = test::grid(150);  // 22801 vertices: a quadratic search would be slow
  const auto r = check_mesh(m, CheckLevel::Delaunay);
  EXPECT_TRUE(r.ok()) << r.summary();
}

TEST(CheckMesh, non_delaunay_edge_is_detected) {
  // A thin quad split along its long diagonal: the far apex is inside the circumcircle.
  //   2 = (0, 1), 0 = (-3, 0), 1 = (3, 0), 3 = (0, -1): diagonal 0-1 is not Delaunay.
  const Mesh m = test::make_mesh({{-3, 0}, {3, 0}, {0, 1}, {0, -1}}, {{0, 1, 2}, {1, 0, 3}});
  EXPECT_TRUE(check_mesh(m, CheckLevel::Geometry).ok()) << check_mesh(m).summary();
  const auto r = check_mesh(m, CheckLevel::Delaunay);
  ASSERT_EQ(r.total, 1u) << r.summary();
  EXPECT_TRUE(mentions(r, "not locally Delaunay")) << r.summary();
  EXPECT_TRUE(mentions(r, "(vertices 0-1)") || mentions(r, "(vertices 1-0)")) << r.summary();
}

TEST(CheckMesh, constrained_edge_is_exempt_from_delaunay) {
  Mesh m = test::make_mesh({{-3, 0}, {3, 0}, {0, 1}, {0, -1}}, {{0, 1, 2}, {1, 0, 3}});
  const auto heh = m.find_halfedge(VertexHandle(0), VertexHandle(1));
  ASSERT_TRUE(heh.is_valid());
  m.data(m.edge_handle(heh)).segment = 0;
  const auto r = check_mesh(m, CheckLevel::Delaunay);
  EXPECT_TRUE(r.ok()) << r.summary();
}

TEST(CheckMesh, cocircular_quad_is_delaunay_either_way) {
  for (int diag = 0; diag < 2; ++diag) {
    const Mesh m = diag == 0 ? test::make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}})
                             : test::make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 3}, {1, 2, 3}});
    const auto r = check_mesh(m, CheckLevel::Delaunay);
    EXPECT_TRUE(r.ok()) << "diagonal " << diag << ": " << r.summary();
  }
}

TEST(CheckMesh, deleted_elements_are_skipped) {
  Mesh m = test::grid(2);
  m.delete_face(FaceHandle(0), true);  // a corner triangle: what remains is manifold
  const auto r = check_mesh(m, CheckLevel::Delaunay);
  EXPECT_TRUE(r.ok()) << r.summary();
}

TEST(CheckMesh, pinch_vertex_is_valid) {
  // Deleting face 3 of the 2x2 grid leaves vertex 1 = (1, 0) with two fans that share no edge:
  // the region touches itself there (a pinch vertex), which a planar triangulation may do.
  Mesh m = test::grid(2);
  m.delete_face(FaceHandle(3), true);
  const auto r = check_mesh(m, CheckLevel::Geometry);
  EXPECT_TRUE(r.ok()) << r.summary();
}

TEST(CheckMesh, broken_link_is_reported) {
  Mesh m = test::grid(1);
  // Corrupt: make the face's halfedge point into the other face.
  const auto f0 = FaceHandle(0), f1 = FaceHandle(1);
  m.set_halfedge_handle(f0, m.halfedge_handle(f1));
  const auto r = check_mesh(m, CheckLevel::Geometry);
  EXPECT_TRUE(mentions(r, "face 0: its halfedge belongs to another face")) << r.summary();
}

TEST(CheckMesh, caps_the_list_but_counts_all) {
  // Ten clockwise triangles.
  std::vector<std::pair<double, double>> pts;
  std::vector<std::array<int, 3>> tris;
  for (int i = 0; i < 10; ++i) {
    pts.insert(pts.end(), {{3.0 * i, 0}, {3.0 * i + 1, 0}, {3.0 * i, 1}});
    tris.push_back({3 * i, 3 * i + 2, 3 * i + 1});
  }
  const Mesh m = test::make_mesh(pts, tris);
  const auto r = check_mesh(m, CheckLevel::Geometry, 4);
  EXPECT_EQ(r.violations.size(), 4u);
  EXPECT_EQ(r.total, 10u);
  EXPECT_EQ(r.summary(2).rfind("10 violations: face 0: not counter-clockwise", 0), 0u) << r.summary(2);
  EXPECT_EQ(r.summary(2).find('\n'), std::string::npos) << "summary is one line";
}

}  // namespace
}  // namespace acute
