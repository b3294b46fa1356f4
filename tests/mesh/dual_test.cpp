// The circumcentric dual and the exact well-centredness check.
#include "mesh/builders.h"

#include <acute/mesh/dual.h>
#include <acute/mesh/geometry.h>
#include <acute/predicates/predicates.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>

using namespace acute;
using acute::test::make_mesh;

namespace {

// Equilateral triangles filling a regular hexagon of side n, vertices shifted and slightly
// jittered (well-centred: every angle stays within a few degrees of 60).
Mesh hexagon_mesh(int n, double jitter = 0.0, unsigned seed = 1) {
  Mesh m;
  std::map<std::pair<int, int>, VertexHandle> at;  // axial coordinates (q, r)
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> noise(-jitter, jitter);
  const double h = std::sqrt(3.0) / 2;
  auto inside = [n](int q, int r) { return std::abs(q) <= n && std::abs(r) <= n && std::abs(q + r) <= n; };
  auto vertex = [&](int q, int r) {
    auto it = at.find({q, r});
    if (it != at.end()) return it->second;
    const bool interior = std::abs(q) < n && std::abs(r) < n && std::abs(q + r) < n;
    const double dx = interior ? noise(rng) : 0, dy = interior ? noise(rng) : 0;
    return at[{q, r}] = m.add_vertex(Mesh::Point(10 + q + 0.5 * r + dx, -3 + h * r + dy, 0.0));
  };
  for (int q = -n; q <= n; ++q)
    for (int r = -n; r <= n; ++r) {
      if (inside(q, r) && inside(q + 1, r) && inside(q, r + 1)) m.add_face(vertex(q, r), vertex(q + 1, r), vertex(q, r + 1));
      if (inside(q + 1, r) && inside(q + 1, r + 1) && inside(q, r + 1))
        m.add_face(vertex(q + 1, r), vertex(q + 1, r + 1), vertex(q, r + 1));
    }
  return m;
}

double mesh_area(const Mesh& m) {
  double a = 0;
  for (auto fh : m.faces()) {
    const auto p = face_points(m, fh);
    a += 0.5 * signed_area2(p[0], p[1], p[2]);
  }
  return a;
}

// No corner of the polygon turns clockwise (collinear corners allowed). The dual points are
// rounded constructions: a boundary vertex between two midpoints of a straight boundary is
// collinear with them only up to rounding, hence the relative tolerance.
bool is_convex(const DualMesh& d, std::size_t cell) {
  const auto& c = d.cells[cell];
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Point2& a = d.points[c[k]];
    const Point2& b = d.points[c[(k + 1) % c.size()]];
    const Point2& e = d.points[c[(k + 2) % c.size()]];
    if (signed_area2(a, b, e) < -1e-12 * (b - a).norm() * (e - b).norm()) return false;
  }
  return true;
}

}  // namespace

TEST(CircumcentricDual, well_centred_hexagon_has_convex_cells_tiling_the_mesh) {
  for (double jitter : {0.0, 0.05}) {
    const Mesh m = hexagon_mesh(4, jitter);
    const std::string name = "hexagon(4) jitter " + std::to_string(jitter);
    ASSERT_TRUE(check_well_centered(m).well_centered()) << name;
    const DualMesh d = circumcentric_dual(m);
    ASSERT_EQ(d.n_cells(), m.n_vertices()) << name << ": one cell per vertex";
    ASSERT_EQ(d.cells.size(), d.cell_vertex.size()) << name;
    ASSERT_EQ(d.points.size(), d.point_kinds.size()) << name;
    std::size_t n_boundary_vertices = 0, n_boundary_edges = 0;
    for (auto vh : m.vertices()) n_boundary_vertices += m.is_boundary(vh);
    for (auto eh : m.edges()) n_boundary_edges += m.is_boundary(eh);
    EXPECT_EQ(d.n_points(), m.n_faces() + n_boundary_edges + n_boundary_vertices) << name << ": dual points shared";
    double total = 0;
    for (std::size_t c = 0; c < d.n_cells(); ++c) {
      const double area = cell_area(d, c);
      EXPECT_GT(area, 0) << name << " cell " << c << " of vertex " << d.cell_vertex[c];
      EXPECT_TRUE(is_convex(d, c)) << name << " cell " << c << " of vertex " << d.cell_vertex[c];
      const VertexHandle vh(d.cell_vertex[c]);
      EXPECT_EQ(d.cell_on_boundary[c] != 0, m.is_boundary(vh)) << name << " cell " << c;
      // interior cells: one circumcentre per incident triangle; boundary cells: + 2 midpoints + the vertex
      EXPECT_EQ(d.cells[c].size(), m.valence(vh) + (m.is_boundary(vh) ? 2u : 0u)) << name << " cell " << c;
      total += area;
    }
    EXPECT_NEAR(total, mesh_area(m), 1e-12 * mesh_area(m)) << name << ": cell areas sum to the mesh area";
  }
}

TEST(CircumcentricDual, interior_cell_of_regular_hexagon_is_regular_hexagon) {
  const Mesh m = hexagon_mesh(1);
  const DualMesh d = circumcentric_dual(m);
  for (std::size_t c = 0; c < d.n_cells(); ++c) {
    if (d.cell_on_boundary[c]) continue;
    ASSERT_EQ(d.cells[c].size(), 6u) << "centre cell";
    const Point2 centre = point2(m, VertexHandle(d.cell_vertex[c]));
    for (int k : d.cells[c]) {
      EXPECT_EQ(d.point_kinds[k], DualPointKind::Circumcenter) << "centre cell point " << k;
      EXPECT_NEAR((d.points[k] - centre).norm(), 1 / std::sqrt(3.0), 1e-14) << "centre cell point " << k;
    }
    // area of a regular hexagon with circumradius 1/sqrt(3): (3 sqrt 3 / 2) / 3 = sqrt(3)/2
    EXPECT_NEAR(cell_area(d, c), std::sqrt(3.0) / 2, 1e-14) << "centre cell";
  }
}

TEST(CircumcentricDual, areas_sum_to_mesh_area_even_when_not_well_centred) {
  const Mesh m = test::grid(3);  // right triangles: circumcentres on the hypotenuses
  const DualMesh d = circumcentric_dual(m);
  double total = 0;
  for (std::size_t c = 0; c < d.n_cells(); ++c) total += cell_area(d, c);
  EXPECT_NEAR(total, 9.0, 1e-12) << "grid(3)";
  EXPECT_EQ(d.n_cells(), m.n_vertices()) << "grid(3)";
}

TEST(CircumcentricDual, vertex_with_two_fans_gets_two_cells) {
  // Two triangles sharing only vertex 0 (a bow tie).
  const Mesh m = make_mesh({{0, 0}, {1, 0}, {0.5, 1}, {-1, 0}, {-0.5, -1}}, {{0, 1, 2}, {0, 3, 4}});
  const DualMesh d = circumcentric_dual(m);
  std::size_t cells_of_0 = 0;
  for (std::size_t c = 0; c < d.n_cells(); ++c)
    if (d.cell_vertex[c] == 0) {
      ++cells_of_0;
      EXPECT_EQ(d.cells[c].size(), 4u) << "bow tie cell " << c;
      EXPECT_GT(cell_area(d, c), 0) << "bow tie cell " << c;
    }
  EXPECT_EQ(cells_of_0, 2u) << "bow tie centre";
  EXPECT_EQ(d.n_cells(), 6u) << "bow tie";
}

TEST(CircumcentricDual, empty_and_isolated_vertices_give_no_cells) {
  Mesh m;
  EXPECT_EQ(circumcentric_dual(m).n_cells(), 0u) << "empty mesh";
  m.add_vertex(Mesh::Point(1, 2, 0));
  EXPECT_EQ(circumcentric_dual(m).n_cells(), 0u) << "isolated vertex";
  EXPECT_TRUE(check_well_centered(m).well_centered()) << "isolated vertex";
}

TEST(CheckWellCentered, reports_obtuse_and_right_triangles) {
  // Face 0 acute, face 1 obtuse at vertex 3, face 2 right at vertex 4 (sharing only vertex 1).
  const Mesh m = make_mesh({{0, 0}, {1, 0}, {0.5, 0.8}, {0.5, -0.1}, {2, 0}, {2, 1}},
                           {{0, 1, 2}, {0, 3, 1}, {1, 4, 5}});
  const DualCheck check = check_well_centered(m);
  EXPECT_FALSE(check.well_centered()) << "mixed mesh";
  EXPECT_EQ(check.n_faces, 3u) << "mixed mesh";
  EXPECT_EQ(check.n_obtuse, 1u) << "mixed mesh";
  EXPECT_EQ(check.n_right, 1u) << "mixed mesh";
  ASSERT_EQ(check.first_bad.size(), 2u) << "mixed mesh";
  EXPECT_EQ(check.first_bad[0].face.idx(), 1) << "obtuse face";
  EXPECT_EQ(check.first_bad[0].kind, AngleKind::Obtuse) << "obtuse face";
  EXPECT_EQ(face_vertices(m, check.first_bad[0].face)[check.first_bad[0].corner].idx(), 3) << "obtuse corner";
  EXPECT_GT(check.first_bad[0].angle_deg, 90) << "obtuse face";
  EXPECT_EQ(check.first_bad[1].face.idx(), 2) << "right face";
  EXPECT_EQ(check.first_bad[1].kind, AngleKind::Right) << "right face";
  EXPECT_EQ(face_vertices(m, check.first_bad[1].face)[check.first_bad[1].corner].idx(), 4) << "right corner";
  EXPECT_EQ(check_well_centered(m, 1).first_bad.size(), 1u) << "max_reported 1";

  // The circumcentre of the obtuse face (0, 3, 1) lies beyond its edge 1-0.
  const DualMesh d = circumcentric_dual(m);
  bool found = false;
  for (std::size_t k = 0; k < d.n_points(); ++k)
    if (d.point_kinds[k] == DualPointKind::Circumcenter && d.point_sources[k] == 1) {
      found = true;
      EXPECT_EQ(predicates::orient2d(point2(m, VertexHandle(1)), point2(m, VertexHandle(0)), d.points[k]), Sign::Negative)
          << "circumcentre of the obtuse face";
    }
  EXPECT_TRUE(found) << "circumcentre of face 1 in the dual";
}

TEST(CheckWellCentered, exact_near_right_angles) {
  // Right angle at the origin up to one ulp: the exact sign test separates the three cases.
  const double x = 1.0, y = 1.0;
  const double tiny = std::ldexp(1.0, -60);  // inside the predicates' exact range
  for (auto [dx, kind] : {std::pair{0.0, AngleKind::Right}, std::pair{tiny, AngleKind::Obtuse}, std::pair{-tiny, AngleKind::Acute}}) {
    // angle at (0,0) between (x, 0) and (-dx, y): dot = -x dx
    const Mesh m = make_mesh({{0, 0}, {x, 0}, {-dx, y}}, {{0, 1, 2}});
    const DualCheck check = check_well_centered(m);
    const std::string name = dx > 0 ? "dx = +2^-60" : dx < 0 ? "dx = -2^-60" : "dx = 0";
    EXPECT_EQ(check.well_centered(), kind == AngleKind::Acute) << name;
    if (!check.well_centered()) {
      EXPECT_EQ(check.first_bad.at(0).kind, kind) << name;
    }
  }
}
