#include <acute/ops/delaunay_flips.h>
#include <acute/ops/flip.h>

#include "support/builders.h"
#include "support/mesh_verify.h"

namespace acute {

TEST(Flip, refuses_boundary_and_constrained_edges) {
  Mesh mesh = test::grid_mesh(2);
  for (auto eh : mesh.edges()) {
    if (mesh.is_boundary(eh)) {
      EXPECT_EQ(can_flip(mesh, eh), OpVerdict::Boundary) << "edge " << eh.idx();
    }
  }
}

TEST(Flip, cocircular_square_diagonals_are_both_delaunay_and_flippable) {
  Mesh mesh = test::grid_mesh(1);
  EdgeHandle diagonal;
  for (auto eh : mesh.edges())
    if (!mesh.is_boundary(eh)) diagonal = eh;
  ASSERT_TRUE(diagonal.is_valid());
  EXPECT_TRUE(is_locally_delaunay(mesh, diagonal));
  ASSERT_EQ(can_flip(mesh, diagonal), OpVerdict::Ok);
  flip(mesh, diagonal);
  EXPECT_MESH_VALID(mesh);
  EXPECT_TRUE(is_locally_delaunay(mesh, diagonal));
}

TEST(Flip, refuses_non_convex_quadrilateral) {
  Mesh mesh;
  auto a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({4, 0, 0}), c = mesh.add_vertex({1, 1, 0}), d = mesh.add_vertex({0, 4, 0});
  mesh.add_face(a, b, c);
  mesh.add_face(a, c, d);
  const auto eh = mesh.edge_handle(mesh.find_halfedge(a, c));
  EXPECT_EQ(can_flip(mesh, eh), OpVerdict::WouldInvert);
}

TEST(Lawson, make_delaunay_on_skewed_grid_gives_brute_force_delaunay) {
  Mesh mesh = test::grid_mesh(6, false);
  // Shear interior vertices so the fixed diagonals stop being Delaunay.
  for (auto vh : mesh.vertices())
    if (!mesh.is_boundary(vh)) {
      const Point2 p = point2(mesh, vh);
      set_point2(mesh, vh, Point2(p.x() + 0.3 * std::sin(3 * p.y()), p.y() + 0.25 * std::cos(2 * p.x())));
    }
  ASSERT_EQ(test::verify_valid(mesh), "");
  make_delaunay(mesh);
  EXPECT_MESH_VALID(mesh);
  EXPECT_MESH_DELAUNAY(mesh);
}

}  // namespace acute
