#include <acute/ops/relocate.h>

#include "support/builders.h"
#include "support/mesh_verify.h"

namespace acute {

TEST(Relocate, interior_vertex_within_its_kernel_only) {
  Mesh mesh = test::grid_mesh(2);
  VertexHandle center;
  for (auto vh : mesh.vertices())
    if (point2(mesh, vh) == Point2(1, 1)) center = vh;
  EXPECT_EQ(can_relocate(mesh, center, Point2(1.2, 0.9)), OpVerdict::Ok);
  EXPECT_EQ(can_relocate(mesh, center, Point2(2.5, 1.0)), OpVerdict::WouldInvert);
  relocate(mesh, center, Point2(1.2, 0.9));
  EXPECT_MESH_VALID(mesh);
}

TEST(Relocate, input_vertex_never_moves_and_segment_vertex_stays_between_neighbours) {
  Mesh mesh = test::grid_mesh(2);
  for (auto vh : mesh.vertices()) {
    const Point2 p = point2(mesh, vh);
    if (is_input(mesh, vh)) {
      EXPECT_EQ(can_relocate(mesh, vh, p + Point2(0.1, 0.1)), OpVerdict::InputVertex);
    }
    if (p == Point2(1, 0)) {
      EXPECT_EQ(can_relocate(mesh, vh, Point2(1.3, 0)), OpVerdict::Ok);
      EXPECT_EQ(can_relocate(mesh, vh, Point2(2.5, 0)), OpVerdict::OffSegment);
    }
  }
}

}  // namespace acute

namespace acute {

// A free vertex on the border (an unconstrained border edge, e.g. a convex hull edge split before
// the hull edges were segments, issue #9) would drag the domain's boundary along: never moved.
TEST(Relocate, free_vertex_on_the_border_never_moves) {
  Mesh mesh = test::grid_mesh(2);
  for (auto vh : mesh.vertices()) {
    if (point2(mesh, vh) != Point2(1, 0)) continue;
    mesh.data(vh).kind = VertexKind::Free;
    mesh.data(vh).segment = -1;
    for (auto heh : mesh.voh_range(vh)) mesh.data(mesh.edge_handle(heh)).segment = -1;
    EXPECT_EQ(can_relocate(mesh, vh, Point2(1.0, -0.1)), OpVerdict::Boundary);  // outward: the area grows
    EXPECT_EQ(can_relocate(mesh, vh, Point2(1.3, 0)), OpVerdict::Boundary);      // even along the border
  }
}

}  // namespace acute
