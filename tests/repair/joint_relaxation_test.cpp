#include <acute/mesh/geometry.h>
#include <acute/mesher.h>
#include <acute/predicates/predicates.h>
#include <acute/repair/angle_bounds.h>
#include <acute/repair/joint_relaxation.h>

#include "support/builders.h"
#include "support/wedge_domains.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace acute {
namespace {

constexpr double kPi = 3.14159265358979323846;

Point2 polar(double r, double deg) { return Point2(r * std::cos(deg * kPi / 180), r * std::sin(deg * kPi / 180)); }

double max_angle(const Mesh& mesh) {
  double worst = 0;
  for (auto fh : mesh.faces()) {
    const auto p = face_points(mesh, fh);
    for (double a : angles_deg(p[0], p[1], p[2])) worst = std::max(worst, a);
  }
  return worst;
}

/// A 6 x 6 grid of right triangles with its free vertices jittered (deterministically).
Mesh jittered_grid() {
  Mesh mesh = test::grid_mesh(6);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  for (auto vh : mesh.vertices()) {
    const Point2 p = point2(mesh, vh);
    if (mesh.data(vh).kind == VertexKind::Free) set_point2(mesh, vh, p + Point2(u(rng), u(rng)));
    if (mesh.data(vh).kind == VertexKind::OnSegment) {
      const bool horizontal = p.y() == 0 || p.y() == 6;
      set_point2(mesh, vh, p + (horizontal ? Point2(u(rng), 0) : Point2(0, u(rng))));
    }
  }
  return mesh;
}

TEST(JointRelaxation, lowers_the_energy_and_keeps_the_mesh_valid) {
  Mesh mesh = jittered_grid();
  const Mesh before = mesh;
  AngleBounds bounds;
  const std::vector<bool> none(mesh.n_vertices(), false);
  std::vector<VertexHandle> all(mesh.vertices_begin(), mesh.vertices_end());
  const double e0 = joint_energy(mesh, all, bounds, none, 1.0);
  ASSERT_TRUE(relax_jointly(mesh, all, bounds, none));
  const double e1 = joint_energy(mesh, all, bounds, none, 1.0);
  EXPECT_LT(e1, e0);
  EXPECT_LT(max_angle(mesh), max_angle(before));
  for (auto fh : mesh.faces()) {
    const auto p = face_points(mesh, fh);
    EXPECT_EQ(predicates::orient2d(p[0], p[1], p[2]), Sign::Positive) << "face " << fh.idx();
  }
  for (auto vh : mesh.vertices()) {
    const Point2 p = point2(mesh, vh), q = point2(before, vh);
    if (mesh.data(vh).kind == VertexKind::Input) {
      EXPECT_EQ(p, q);
    }
    if (mesh.data(vh).kind == VertexKind::OnSegment) {
      // Axis-aligned segments: the projection is exact.
      const bool horizontal = q.y() == 0 || q.y() == 6;
      EXPECT_EQ(horizontal ? p.y() : p.x(), horizontal ? q.y() : q.x()) << "vertex " << vh.idx() << " left its segment";
    }
  }
}

TEST(JointRelaxation, input_vertices_alone_never_move) {
  Mesh mesh = jittered_grid();
  std::vector<VertexHandle> corners;
  for (auto vh : mesh.vertices())
    if (mesh.data(vh).kind == VertexKind::Input) corners.push_back(vh);
  const std::vector<bool> none(mesh.n_vertices(), false);
  EXPECT_FALSE(relax_jointly(mesh, corners, AngleBounds{}, none));
}

/// An 80-degree wedge at the origin split by an interior segment into sectors of 20 and 60 degrees.
Domain split_wedge() {
  Domain d;
  d.points = {Point2(0, 0), polar(10, 0), polar(10, 80), polar(5, 20)};
  d.segments = {{0, 1}, {1, 2}, {2, 0}, {0, 3}};
  return d;
}

TEST(SectorAngle, sectors_at_a_corner_with_an_interior_segment) {
  const Mesh mesh = build_domain_cdt(split_wedge());
  const auto forced = forced_corner_vertices(mesh, 30);
  const VertexHandle apex = test::vertex_at(mesh, Point2(0, 0));
  ASSERT_TRUE(apex.is_valid());
  ASSERT_TRUE(forced[static_cast<std::size_t>(apex.idx())]);
  int narrow = 0, wide = 0;
  for (auto fh : mesh.vf_range(apex)) {
    const double s = sector_angle(mesh, apex, fh);
    // Which sector holds fh: the direction of its centroid from the apex.
    const auto p = face_points(mesh, fh);
    const Point2 g = (p[0] + p[1] + p[2]) / 3.0;
    const double dir = std::atan2(g.y(), g.x()) * 180 / kPi;
    if (dir < 20) {
      EXPECT_NEAR(s, 20, 1e-9);
      EXPECT_TRUE(min_exempt_corner(mesh, apex, fh, 30, forced));
      ++narrow;
    } else {
      EXPECT_NEAR(s, 60, 1e-9);
      EXPECT_FALSE(min_exempt_corner(mesh, apex, fh, 30, forced)) << "a 60-degree sector is not exempt";
      ++wide;
    }
  }
  EXPECT_GT(narrow, 0);
  EXPECT_GT(wide, 0);
}

}  // namespace
}  // namespace acute
