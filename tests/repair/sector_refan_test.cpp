// Re-fanning a sector that holds too few triangles for the max bound (repair/sector_refan.h):
// the sector gains spokes, and the mesh stays valid, conforming and of the same area.
#include <acute/mesh/geometry.h>
#include <acute/mesh/sectors.h>

#include "repair/sector_refan.h"
#include "support/builders.h"
#include "support/mesh_verify.h"
#include "support/wedge_domains.h"

#include <gtest/gtest.h>

namespace acute {
namespace {

using test::vertex_at;

/// Triangles at vh between its segment spokes on the side facing +y (the bottom side's inside).
int triangles_at(const Mesh& mesh, VertexHandle vh) { return static_cast<int>(mesh.valence(vh)) - (mesh.is_boundary(vh) ? 1 : 0); }

std::size_t constrained_edges(const Mesh& mesh) {
  std::size_t n = 0;
  for (auto eh : mesh.edges()) n += !mesh.status(eh).deleted() && is_constrained(mesh, eh);
  return n;
}

// In the alternating grid, the bottom side's vertex (1, 0) has two right triangles above it: 90 +
// 90 on a straight segment, which no relocation can share out. Re-fanned, it has three or more.
TEST(SectorRefan, a_segment_vertex_with_two_right_triangles_gets_a_third) {
  Mesh mesh = test::grid_mesh(4);
  const VertexHandle v = vertex_at(mesh, Point2(1, 0));
  ASSERT_EQ(triangles_at(mesh, v), 2);
  const auto crowded = detail::crowded_sectors(mesh, v, 89.9);
  ASSERT_EQ(crowded.size(), 1u);
  EXPECT_NEAR(crowded[0].degrees, 180, 1e-9);
  EXPECT_EQ(crowded[0].triangles, 2);
  EXPECT_FALSE(crowded[0].closed);
  const std::size_t walls = constrained_edges(mesh);
  ASSERT_TRUE(detail::refan_sector(mesh, v, crowded[0]));
  EXPECT_EQ(test::verify_valid(mesh), "");
  EXPECT_NEAR(test::total_area(mesh), 16, 1e-12);
  EXPECT_GE(triangles_at(mesh, v), 3);
  EXPECT_EQ(constrained_edges(mesh), walls);  // no segment split or lost
  EXPECT_TRUE(detail::crowded_sectors(mesh, v, 89.9).empty());
  EXPECT_EQ(point2(mesh, v), Point2(1, 0));  // the apex stays
}

// An interior vertex of degree four (360 / 4 = 90) gets a star of about six.
TEST(SectorRefan, an_interior_vertex_of_degree_four_gets_a_fuller_star) {
  Mesh mesh = test::grid_mesh(4);
  const VertexHandle v = vertex_at(mesh, Point2(2, 1));
  ASSERT_EQ(mesh.valence(v), 4u);
  const auto crowded = detail::crowded_sectors(mesh, v, 89.9);
  ASSERT_EQ(crowded.size(), 1u);
  EXPECT_TRUE(crowded[0].closed);
  ASSERT_TRUE(detail::refan_sector(mesh, v, crowded[0]));
  EXPECT_EQ(test::verify_valid(mesh), "");
  EXPECT_NEAR(test::total_area(mesh), 16, 1e-12);
  EXPECT_GE(mesh.valence(v), 5u);
  EXPECT_TRUE(detail::crowded_sectors(mesh, v, 89.9).empty());
}

// Sectors that share out within the bound, and input vertices' closed stars, are not crowded.
TEST(SectorRefan, sectors_within_the_bound_are_not_crowded) {
  const Mesh mesh = test::grid_mesh(4);
  EXPECT_TRUE(detail::crowded_sectors(mesh, vertex_at(mesh, Point2(2, 0)), 89.9).empty());  // 90 + 45 + 45
  EXPECT_TRUE(detail::crowded_sectors(mesh, vertex_at(mesh, Point2(1, 1)), 89.9).empty());  // degree 8
  EXPECT_TRUE(detail::crowded_sectors(mesh, vertex_at(mesh, Point2(0, 0)), 89.9).empty());  // a 90-degree corner: 45 + 45
}

}  // namespace
}  // namespace acute
