#include <acute/ops/insert.h>

#include "support/builders.h"
#include "support/mesh_verify.h"

#include <random>

namespace acute {

TEST(Locate, finds_face_edge_and_vertex) {
  Mesh mesh = test::grid_mesh(3);
  const FaceHandle start = *mesh.faces().begin();
  EXPECT_EQ(locate(mesh, Point2(2.2, 2.7), start).kind, LocationKind::InFace);
  EXPECT_EQ(locate(mesh, Point2(1.5, 1.0), start).kind, LocationKind::OnEdge);
  const Location at_vertex = locate(mesh, Point2(2, 1), start);
  ASSERT_EQ(at_vertex.kind, LocationKind::OnVertex);
  EXPECT_EQ(point2(mesh, at_vertex.vertex), Point2(2, 1));
  EXPECT_EQ(locate(mesh, Point2(5, 1), start).kind, LocationKind::Blocked);
}

TEST(InsertPoint, random_points_keep_mesh_valid_and_delaunay) {
  Mesh mesh = test::grid_mesh(4);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 4.0);
  for (int i = 0; i < 200; ++i) {
    const VertexHandle vh = insert_point(mesh, Point2(u(rng), u(rng)), *mesh.faces().begin());
    ASSERT_TRUE(vh.is_valid()) << "insertion " << i;
  }
  EXPECT_MESH_VALID(mesh);
  EXPECT_MESH_DELAUNAY(mesh);
  EXPECT_NEAR(test::total_area(mesh), 16.0, 1e-12);
}

TEST(InsertPoint, on_constrained_boundary_edge_creates_on_segment_vertex) {
  Mesh mesh = test::grid_mesh(2);
  const VertexHandle vh = insert_point(mesh, Point2(0.5, 0.0), *mesh.faces().begin());
  ASSERT_TRUE(vh.is_valid());
  EXPECT_EQ(mesh.data(vh).kind, VertexKind::OnSegment);
  EXPECT_EQ(mesh.data(vh).segment, 0);
  EXPECT_MESH_VALID(mesh);
}

/// A 2 x 2 grid with the line x = 1 constrained; its centre (1, 1) on the line and its corner (0, 2).
struct GridWithLine {
  Mesh mesh = test::grid_mesh(2);
  VertexHandle centre, corner;
  GridWithLine() {
    for (auto eh : mesh.edges()) {
      const auto h = mesh.halfedge_handle(eh, 0);
      if (point2(mesh, mesh.from_vertex_handle(h)).x() == 1 && point2(mesh, mesh.to_vertex_handle(h)).x() == 1) mesh.data(eh).segment = 4;
    }
    for (auto vh : mesh.vertices()) {
      if (point2(mesh, vh) == Point2(1, 1)) centre = vh;
      if (point2(mesh, vh) == Point2(0, 2)) corner = vh;
    }
  }
};

TEST(InsertPoint, from_a_vertex_tries_its_faces_until_a_walk_is_not_blocked) {
  // From (1, 1) a walk towards (1.5, 0.5) that starts left of the line is blocked by it, one that
  // starts right of it is not; from (0, 2) every walk is blocked.
  GridWithLine g;
  Mesh& mesh = g.mesh;
  const VertexHandle centre = g.centre, corner = g.corner;
  const Point2 q(1.5, 0.5);
  int blocked = 0;
  for (auto fh : mesh.vf_range(centre)) blocked += locate(mesh, q, fh).kind == LocationKind::Blocked;
  ASSERT_GT(blocked, 0);
  EXPECT_FALSE(insert_point_from(mesh, q, corner).is_valid());
  EXPECT_EQ(mesh.n_vertices(), 9u);
  const VertexHandle vh = insert_point_from(mesh, q, centre);
  ASSERT_TRUE(vh.is_valid());
  EXPECT_EQ(point2(mesh, vh), q);
  EXPECT_MESH_VALID(mesh);
  EXPECT_NEAR(test::total_area(mesh), 4.0, 1e-12);
}

TEST(InsertPoint, after_a_blocked_or_missing_previous_vertex_walks_from_the_anchor) {
  // Points right of x = 1 inserted one after another, the first with no previous vertex, the second
  // after one left of the line (every walk from it blocked), the third after the second.
  GridWithLine g;
  Mesh& mesh = g.mesh;
  const VertexHandle centre = g.centre, corner = g.corner;
  const VertexHandle a = insert_point_after(mesh, Point2(1.5, 0.5), VertexHandle(), centre);
  ASSERT_TRUE(a.is_valid());
  const VertexHandle b = insert_point_after(mesh, Point2(1.5, 1.5), corner, centre);
  ASSERT_TRUE(b.is_valid());
  const VertexHandle c = insert_point_after(mesh, Point2(1.75, 1.25), b, corner);
  ASSERT_TRUE(c.is_valid());
  EXPECT_EQ(point2(mesh, c), Point2(1.75, 1.25));
  EXPECT_FALSE(insert_point_after(mesh, Point2(1.25, 0.25), corner, corner).is_valid());
  EXPECT_EQ(mesh.n_vertices(), 12u);
  EXPECT_MESH_VALID(mesh);
  EXPECT_MESH_DELAUNAY(mesh);
  EXPECT_NEAR(test::total_area(mesh), 4.0, 1e-12);
}

TEST(SplitEdge, midpoint_of_interior_and_boundary_edges) {
  Mesh mesh = test::grid_mesh(2);
  std::vector<EdgeHandle> edges(mesh.edges().begin(), mesh.edges().end());
  for (auto eh : edges) {
    const auto h = mesh.halfedge_handle(eh, 0);
    const Point2 mid = 0.5 * (point2(mesh, mesh.from_vertex_handle(h)) + point2(mesh, mesh.to_vertex_handle(h)));
    const bool constrained = is_constrained(mesh, eh);
    const VertexHandle vh = split_edge(mesh, eh, mid);
    ASSERT_TRUE(vh.is_valid()) << "edge " << eh.idx();
    EXPECT_EQ(mesh.data(vh).kind, constrained ? VertexKind::OnSegment : VertexKind::Free) << "edge " << eh.idx();
    EXPECT_MESH_VALID(mesh);
  }
  EXPECT_MESH_DELAUNAY(mesh);
}

TEST(SplitEdge, refuses_point_that_would_invert) {
  Mesh mesh = test::grid_mesh(1);
  EdgeHandle diagonal;
  for (auto eh : mesh.edges())
    if (!mesh.is_boundary(eh)) diagonal = eh;
  EXPECT_FALSE(split_edge(mesh, diagonal, Point2(1.5, -0.5)).is_valid());
}

}  // namespace acute
