#include <acute/ops/insert.h>
#include <acute/ops/remove.h>

#include "support/builders.h"
#include "support/mesh_verify.h"

#include <random>

namespace acute {

TEST(RemoveVertex, refuses_input_vertices) {
  Mesh mesh = test::grid_mesh(2);
  for (auto vh : mesh.vertices())
    if (is_input(mesh, vh)) {
      EXPECT_EQ(can_remove_vertex(mesh, vh), OpVerdict::InputVertex) << "vertex " << vh.idx();
    }
}

TEST(RemoveVertex, inserted_points_removed_again_restore_delaunay) {
  Mesh mesh = test::grid_mesh(4);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.1, 3.9);
  std::vector<VertexHandle> added;
  for (int i = 0; i < 60; ++i) added.push_back(insert_point(mesh, Point2(u(rng), u(rng)), *mesh.faces().begin()));
  for (std::size_t i = 0; i < added.size(); i += 2) {
    ASSERT_TRUE(remove_vertex(mesh, added[i])) << "vertex " << added[i].idx();
    ASSERT_EQ(test::verify_valid(mesh), "") << "after removing " << added[i].idx();
  }
  mesh.garbage_collection();
  EXPECT_MESH_VALID(mesh);
  EXPECT_MESH_DELAUNAY(mesh);
  EXPECT_NEAR(test::total_area(mesh), 16.0, 1e-12);
}

TEST(RemoveVertices, a_disk_of_points_goes_and_the_rest_stays_delaunay) {
  // 300 free points in a 10 x 10 grid square; those within 3 of the centre removed as one set,
  // with an input corner that must stay.
  Mesh mesh = test::grid_mesh(10);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.05, 9.95);
  for (int i = 0; i < 300; ++i) insert_point(mesh, Point2(u(rng), u(rng)), *mesh.faces().begin());
  std::vector<VertexHandle> disk;
  VertexHandle corner;
  for (auto vh : mesh.vertices()) {
    if (point2(mesh, vh) == Point2(0, 0)) corner = vh;
    if ((point2(mesh, vh) - Point2(5, 5)).norm() < 3) disk.push_back(vh);
  }
  ASSERT_GT(disk.size(), 80u);
  ASSERT_TRUE(corner.is_valid() && is_input(mesh, corner));
  EXPECT_TRUE(remove_vertices(mesh, disk));
  for (auto vh : disk) EXPECT_TRUE(mesh.status(vh).deleted()) << "vertex " << vh.idx();
  EXPECT_FALSE(remove_vertices(mesh, {corner})) << "an input vertex stays";
  EXPECT_FALSE(mesh.status(corner).deleted());
  mesh.garbage_collection();
  EXPECT_MESH_VALID(mesh);
  EXPECT_MESH_DELAUNAY(mesh);
  EXPECT_NEAR(test::total_area(mesh), 100.0, 1e-9);
}

TEST(RemoveVertex, boundary_vertex_on_segment_rejoins_the_segment) {
  Mesh mesh = test::grid_mesh(3);
  VertexHandle on_bottom;
  for (auto vh : mesh.vertices())
    if (point2(mesh, vh) == Point2(1, 0)) on_bottom = vh;
  ASSERT_EQ(mesh.data(on_bottom).kind, VertexKind::OnSegment);
  ASSERT_TRUE(remove_vertex(mesh, on_bottom));
  mesh.garbage_collection();
  EXPECT_MESH_VALID(mesh);
  EXPECT_NEAR(test::total_area(mesh), 9.0, 1e-12);
  int constrained_boundary = 0;
  for (auto eh : mesh.edges()) constrained_boundary += mesh.is_boundary(eh) && is_constrained(mesh, eh);
  EXPECT_EQ(constrained_boundary, 11);
}

TEST(Collapse, along_segment_and_interior) {
  Mesh mesh = test::grid_mesh(3);
  VertexHandle b1, b2, inner;
  for (auto vh : mesh.vertices()) {
    if (point2(mesh, vh) == Point2(1, 0)) b1 = vh;
    if (point2(mesh, vh) == Point2(2, 0)) b2 = vh;
    if (point2(mesh, vh) == Point2(1, 1)) inner = vh;
  }
  const auto along = mesh.find_halfedge(b1, b2);
  ASSERT_EQ(can_collapse(mesh, along), OpVerdict::Ok);
  collapse(mesh, along);
  EXPECT_MESH_VALID(mesh);
  // The interior vertex (1,1) onto the boundary vertex (2,0) would leave (1,0)-side triangles flat or inverted.
  const auto down = mesh.find_halfedge(inner, b2);
  if (down.is_valid()) {
    const OpVerdict verdict = can_collapse(mesh, down);
    if (verdict == OpVerdict::Ok) {
      collapse(mesh, down);
      EXPECT_MESH_VALID(mesh);
    }
  }
  mesh.garbage_collection();
  EXPECT_NEAR(test::total_area(mesh), 9.0, 1e-12);
}

}  // namespace acute
