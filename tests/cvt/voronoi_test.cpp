#include "cvt/cvt_domains.h"

#include <acute/cvt/sampling.h>
#include <acute/cvt/voronoi.h>
#include <acute/delaunay/cdt.h>
#include <acute/mesh/geometry.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace acute {
namespace {

double polygon_area(const std::vector<Point2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) a += 0.5 * signed_area2(Point2(0, 0), p[i], p[(i + 1) % p.size()]);
  return a;
}

TEST(TrianglePieces, tile_the_triangle_and_belong_to_the_nearest_corner) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    Point2 p[3] = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    if (signed_area2(p[0], p[1], p[2]) < 0) std::swap(p[1], p[2]);
    if (signed_area2(p[0], p[1], p[2]) < 1e-3) continue;
    const auto pieces = triangle_pieces(p[0], p[1], p[2]);
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
      const auto& poly = pieces[static_cast<std::size_t>(i)];
      const double a = polygon_area(poly);
      EXPECT_GE(a, -1e-15) << "trial " << trial << " piece " << i;
      sum += a;
      // Every vertex of the piece is at least as close to its corner as to the other two.
      for (const Point2& q : poly)
        for (int j = 0; j < 3; ++j)
          EXPECT_LE((q - p[i]).norm(), (q - p[j]).norm() + 1e-12) << "trial " << trial << " piece " << i << " corner " << j;
    }
    EXPECT_NEAR(sum, 0.5 * signed_area2(p[0], p[1], p[2]), 1e-14) << "trial " << trial;
  }
}

TEST(Cells, uniform_integrals_of_a_single_triangle_are_exact) {
  // Right isosceles triangle: the pieces are known; the centroid of the whole is the mass-weighted
  // mean of the cell centroids.
  Mesh mesh;
  const auto a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({1, 0, 0}), c = mesh.add_vertex({0, 1, 0});
  mesh.add_face(a, b, c);
  CellIntegrals cells;
  CellWorkspace ws;
  compute_cells(mesh, SizeField::uniform(1), cells, ws);
  EXPECT_NEAR(cells.area[0], 0.25, 1e-15);  // square (0,0)-(0.5,0.5)
  EXPECT_NEAR(cells.area[1], 0.125, 1e-15);
  EXPECT_NEAR(cells.area[2], 0.125, 1e-15);
  EXPECT_NEAR(cells.centroid(0).x(), 0.25, 1e-15);
  EXPECT_NEAR(cells.centroid(0).y(), 0.25, 1e-15);
  // Energy of the square [0,.5]^2 about its corner: 2 * int x^2 = 2 * .5 * .5^3/3 = 1/24;
  // each corner triangle (b, (0.5,0.5), (0.5,0)): S/6 (q11 + q22 + q12) = 1/48.
  EXPECT_NEAR(cells.energy, 1.0 / 24 + 2.0 / 48, 1e-15);
}

TEST(Cells, tile_the_domain) {
  for (const Domain& d : {test::unit_square(), test::l_shape(), test::wedge_with_hole()}) {
    const Mesh cdt = build_cdt(d);
    for (bool graded : {false, true}) {
      const SizeField f = graded ? local_feature_size_field(cdt, {}) : SizeField::uniform(size_for_vertex_count(measure_domain(cdt), 1000));
      const Mesh mesh = sample_domain(d, cdt, f, {});
      CellIntegrals cells;
      CellWorkspace ws;
      compute_cells(mesh, f, cells, ws);
      double sum = 0, mass = 0;
      for (std::size_t i = 0; i < cells.area.size(); ++i) sum += cells.area[i], mass += cells.mass[i];
      const double area = measure_domain(cdt).area;
      EXPECT_NEAR(sum, area, 1e-12 * area) << d.name << (graded ? " graded" : " uniform");
      EXPECT_NEAR(cells.total_area, area, 1e-12 * area) << d.name;
      EXPECT_GT(mass, 0) << d.name;
    }
  }
}

TEST(Cells, gradient_matches_finite_differences_on_an_acute_mesh) {
  // On a mesh with no obtuse triangle the cells are the clipped Voronoi cells and dF/dv = 2 m (v - c).
  Mesh mesh;
  std::vector<VertexHandle> v;
  const double s = std::sqrt(3.0) / 2;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) v.push_back(mesh.add_vertex({i + 0.5 * (j % 2), j * s, 0}));
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      auto at = [&](int x, int y) { return v[static_cast<std::size_t>(y * 5 + x)]; };
      if (j % 2 == 0) {
        mesh.add_face(at(i, j), at(i + 1, j), at(i, j + 1));
        mesh.add_face(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      } else {
        mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      }
    }
  const VertexHandle c = v[12];
  set_point2(mesh, c, point2(mesh, c) + Point2(0.05, -0.03));
  // Uniform field: exact. Graded field: rho is interpolated between the piece corners, which move
  // with v, so the gradient is only approximately 2 m (v - c) (about 1% here).
  const SizeField graded = SizeField::piecewise_linear({{-1, -1}, {6, -1}, {6, 5}, {-1, 5}}, {{{0, 1, 2}}, {{0, 2, 3}}}, {0.8, 1.0, 1.3, 0.9});
  for (bool is_graded : {false, true}) {
    const SizeField f = is_graded ? graded : SizeField::uniform(0.9);
    CellIntegrals cells;
    CellWorkspace ws;
    compute_cells(mesh, f, cells, ws);
    const Point2 g = 2.0 * (cells.mass[12] * point2(mesh, c) - cells.moment[12]);
    const double eps = 1e-6;
    for (int k = 0; k < 2; ++k) {
      Point2 d(0, 0);
      d[k] = eps;
      const Point2 p0 = point2(mesh, c);
      set_point2(mesh, c, p0 + d);
      compute_cells(mesh, f, cells, ws);
      const double fp = cells.energy;
      set_point2(mesh, c, p0 - d);
      compute_cells(mesh, f, cells, ws);
      const double fm = cells.energy;
      set_point2(mesh, c, p0);
      EXPECT_NEAR((fp - fm) / (2 * eps), g[k], (is_graded ? 2e-2 : 1e-6) * g.norm()) << (is_graded ? "graded" : "uniform") << " coordinate " << k;
    }
  }
}

}  // namespace
}  // namespace acute
