#include <acute/mesh/sectors.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace acute {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A hexagon (ring v[0..5], radius 1, v[i] at 60 i degrees) fanned from its centre c, with the
// spokes c-v0 and c-v2 constrained (input segments 0 and 1).
struct Hexagon {
  Mesh mesh;
  VertexHandle c;
  std::array<VertexHandle, 6> v;

  Hexagon() {
    c = mesh.add_vertex(Mesh::Point(0, 0, 0));
    for (int i = 0; i < 6; ++i) v[i] = mesh.add_vertex(Mesh::Point(std::cos(i * kPi / 3), std::sin(i * kPi / 3), 0));
    for (int i = 0; i < 6; ++i) mesh.add_face(c, v[i], v[(i + 1) % 6]);
    mesh.data(mesh.edge_handle(spoke(c, v[0]))).segment = 0;
    mesh.data(mesh.edge_handle(spoke(c, v[2]))).segment = 1;
  }
  HalfedgeHandle spoke(VertexHandle from, VertexHandle to) const { return mesh.find_halfedge(from, to); }
  WallTest walls() const {
    return [this](HalfedgeHandle h) { return is_segment_or_boundary(mesh, h); };
  }
};

TEST(SweepSector, sectors_at_an_interior_vertex_split_its_360_degrees_between_the_segments) {
  const Hexagon hex;
  const SectorSweep narrow = sweep_sector(hex.mesh, hex.spoke(hex.c, hex.v[0]), hex.walls());
  EXPECT_EQ(narrow.how, SectorEnd::Wall);
  EXPECT_EQ(narrow.end, hex.spoke(hex.c, hex.v[2]));
  EXPECT_EQ(narrow.triangles, 2);
  EXPECT_NEAR(narrow.degrees, 120, 1e-12);
  const SectorSweep wide = sweep_sector(hex.mesh, narrow.end, hex.walls());
  EXPECT_EQ(wide.how, SectorEnd::Wall);
  EXPECT_EQ(wide.end, hex.spoke(hex.c, hex.v[0]));
  EXPECT_EQ(wide.triangles, 4);
  EXPECT_NEAR(narrow.degrees + wide.degrees, 360, 1e-12);
  EXPECT_NEAR(narrow.radians + wide.radians, 2 * kPi, 1e-14);
  EXPECT_NEAR(wide.radians * 180 / kPi, wide.degrees, 1e-12);
}

TEST(SweepSector, without_walls_the_sweep_closes_on_the_full_star) {
  const Hexagon hex;
  const HalfedgeHandle start = hex.spoke(hex.c, hex.v[1]);
  const SectorSweep star = sweep_sector(hex.mesh, start, [](HalfedgeHandle) { return false; });
  EXPECT_EQ(star.how, SectorEnd::Closed);
  EXPECT_EQ(star.end, start);
  EXPECT_EQ(star.triangles, 6);
  EXPECT_NEAR(star.degrees, 360, 1e-12);
  // From a non-wall spoke the sweep runs to the next wall.
  const SectorSweep rest = sweep_sector(hex.mesh, start, hex.walls());
  EXPECT_EQ(rest.how, SectorEnd::Wall);
  EXPECT_EQ(rest.triangles, 1);
  EXPECT_NEAR(rest.degrees, 60, 1e-12);
}

TEST(SweepSector, stops_after_max_triangles) {
  const Hexagon hex;
  const SectorSweep part = sweep_sector(hex.mesh, hex.spoke(hex.c, hex.v[2]), hex.walls(), 3);
  EXPECT_EQ(part.how, SectorEnd::Unfinished);
  EXPECT_EQ(part.triangles, 3);
  EXPECT_EQ(part.end, hex.spoke(hex.c, hex.v[5]));
  EXPECT_NEAR(part.degrees, 180, 1e-12);
  EXPECT_EQ(sweep_sector(hex.mesh, hex.spoke(hex.c, hex.v[2]), hex.walls(), 0).how, SectorEnd::Unfinished);
}

TEST(SweepSector, sectors_at_a_boundary_corner_sum_to_its_interior_angle) {
  const Hexagon hex;
  const VertexHandle corner = hex.v[0];
  // The fan at v0 runs counter-clockwise from the boundary edge v0-v1 to the boundary edge v0-v5.
  const HalfedgeHandle first = hex.spoke(corner, hex.v[1]);
  ASSERT_FALSE(hex.mesh.is_boundary(first));
  const SectorSweep a = sweep_sector(hex.mesh, first, hex.walls());
  EXPECT_EQ(a.how, SectorEnd::Wall);
  EXPECT_EQ(a.end, hex.spoke(corner, hex.c));  // the segment c-v0
  EXPECT_EQ(a.triangles, 1);
  const SectorSweep b = sweep_sector(hex.mesh, a.end, hex.walls());
  EXPECT_EQ(b.how, SectorEnd::Wall);  // the boundary edge is a wall
  EXPECT_EQ(b.end, hex.spoke(corner, hex.v[5]));
  EXPECT_TRUE(hex.mesh.is_boundary(b.end));
  EXPECT_EQ(b.triangles, 1);
  EXPECT_NEAR(a.degrees + b.degrees, 120, 1e-12);

  // Without walls, the boundary ends a partial fan.
  const SectorSweep fan = sweep_sector(hex.mesh, first, [](HalfedgeHandle) { return false; });
  EXPECT_EQ(fan.how, SectorEnd::Border);
  EXPECT_EQ(fan.end, b.end);
  EXPECT_EQ(fan.triangles, 2);
  EXPECT_NEAR(fan.degrees, 120, 1e-12);

  // A start without a face sweeps nothing.
  const SectorSweep none = sweep_sector(hex.mesh, b.end, hex.walls());
  EXPECT_EQ(none.how, SectorEnd::Border);
  EXPECT_EQ(none.triangles, 0);
}

}  // namespace
}  // namespace acute
