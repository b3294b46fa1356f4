#include <acute/mesh/geometry.h>
#include <acute/predicates/predicates.h>
#include <acute/repair/relocation.h>

#include "support/builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace acute {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// A hexagon of fixed (Input) corners around one free vertex at `centre`.
Mesh hexagon_fan(const Point2& centre, VertexHandle& free) {
  Mesh mesh;
  free = mesh.add_vertex(Mesh::Point(centre.x(), centre.y(), 0));
  std::vector<VertexHandle> ring;
  for (int i = 0; i < 6; ++i) {
    ring.push_back(mesh.add_vertex(Mesh::Point(std::cos(i * kPi / 3), std::sin(i * kPi / 3), 0)));
    mesh.data(ring.back()).kind = VertexKind::Input;
  }
  for (int i = 0; i < 6; ++i) mesh.add_face(free, ring[i], ring[(i + 1) % 6]);
  return mesh;
}

void expect_counter_clockwise(const Mesh& mesh) {
  for (auto fh : mesh.faces()) {
    const auto p = face_points(mesh, fh);
    EXPECT_EQ(predicates::orient2d(p[0], p[1], p[2]), Sign::Positive) << "face " << fh.idx();
  }
}

TEST(Relocation, moves_a_displaced_vertex_until_its_star_meets_the_bounds) {
  for (const Point2& start : {Point2(0.45, 0.1), Point2(-0.3, -0.5), Point2(0.05, 0.7), Point2(0.8, 0.0)}) {
    VertexHandle v;
    Mesh mesh = hexagon_fan(start, v);
    const AngleBounds bounds;
    const std::vector<bool> none(mesh.n_vertices(), false);
    ASSERT_LT(star_margin(mesh, v, bounds, none), 0) << "start " << start.transpose() << " is already good";
    const double e0 = star_energy(mesh, v, bounds, none);
    ASSERT_TRUE(relocate_for_angles(mesh, v, bounds, none));
    EXPECT_LT(star_energy(mesh, v, bounds, none), e0);
    // One relocation from anywhere in the hexagon reaches the region where all 18 angles are good.
    EXPECT_GT(star_margin(mesh, v, bounds, none), 0) << "start " << start.transpose() << ", ended at " << point2(mesh, v).transpose();
    expect_counter_clockwise(mesh);
  }
}

TEST(Relocation, leaves_comfortable_stars_and_input_vertices_alone) {
  VertexHandle v;
  Mesh mesh = hexagon_fan(Point2(0, 0), v);  // every angle 60 degrees
  const std::vector<bool> none(mesh.n_vertices(), false);
  EXPECT_FALSE(relocate_for_angles(mesh, v, AngleBounds{}, none));
  EXPECT_EQ(point2(mesh, v), Point2(0, 0));

  set_point2(mesh, v, Point2(0.45, 0.1));
  mesh.data(v).kind = VertexKind::Input;
  EXPECT_FALSE(relocate_for_angles(mesh, v, AngleBounds{}, none));
  EXPECT_EQ(point2(mesh, v), Point2(0.45, 0.1));
}

TEST(Relocation, a_vertex_on_a_segment_slides_along_it) {
  Mesh mesh = test::grid_mesh(4);
  VertexHandle v;
  for (auto vh : mesh.vertices())
    if (point2(mesh, vh) == Point2(2, 0)) v = vh;
  ASSERT_TRUE(v.is_valid());
  ASSERT_EQ(mesh.data(v).kind, VertexKind::OnSegment);
  set_point2(mesh, v, Point2(2.7, 0));
  const AngleBounds bounds;
  const std::vector<bool> none(mesh.n_vertices(), false);
  const double e0 = star_energy(mesh, v, bounds, none);
  ASSERT_TRUE(relocate_for_angles(mesh, v, bounds, none));
  const Point2 p = point2(mesh, v);
  EXPECT_EQ(p.y(), 0.0);  // the bottom segment's line, exactly
  EXPECT_GT(p.x(), 1.0);
  EXPECT_LT(p.x(), 3.0);
  EXPECT_LT(p.x(), 2.7);  // back towards the middle of its neighbours
  EXPECT_LT(star_energy(mesh, v, bounds, none), e0);
  expect_counter_clockwise(mesh);
}

TEST(Relocation, never_raises_the_energy_nor_folds_a_jittered_grid) {
  Mesh mesh = test::grid_mesh(8);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (auto vh : mesh.vertices())
    if (mesh.data(vh).kind == VertexKind::Free) set_point2(mesh, vh, point2(mesh, vh) + Point2(u(rng), u(rng)));
  expect_counter_clockwise(mesh);
  const AngleBounds bounds;
  const std::vector<bool> none(mesh.n_vertices(), false);
  int moved = 0;
  for (int sweep = 0; sweep < 3; ++sweep)
    for (auto vh : mesh.vertices()) {
      const double e0 = star_energy(mesh, vh, bounds, none);
      const Point2 p0 = point2(mesh, vh);
      if (relocate_for_angles(mesh, vh, bounds, none)) {
        ++moved;
        EXPECT_LT(star_energy(mesh, vh, bounds, none), e0) << "vertex " << vh.idx();
        EXPECT_NE(point2(mesh, vh), p0);
      } else {
        EXPECT_EQ(point2(mesh, vh), p0) << "vertex " << vh.idx() << " moved but reported no move";
      }
    }
  EXPECT_GT(moved, 0);
  expect_counter_clockwise(mesh);
}

}  // namespace
}  // namespace acute
