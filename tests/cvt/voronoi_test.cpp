#include "cvt/cvt_domains.h"

#include <acute/cvt/cvt.h>
#include <acute/cvt/sampling.h>
#include <acute/cvt/voronoi.h>
#include <acute/delaunay/cdt.h>
#include <acute/mesh/geometry.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace acute {
namespace {

/// Stratified random samples: an obtuse start, whose cells the boundary cuts in every way (the
/// default lattice start is nearly a CVT already).
SamplingParams random_start() {
  SamplingParams p;
  p.interior = InteriorSampling::Random;
  return p;
}

std::size_t obtuse_triangles(const Mesh& mesh) {
  std::size_t n = 0;
  for (auto fh : mesh.faces()) {
    const auto p = face_points(mesh, fh);
    for (int i = 0; i < 3; ++i) n += (p[(i + 1) % 3] - p[i]).dot(p[(i + 2) % 3] - p[i]) < 0;
  }
  return n;
}

void expect_finite(const CellIntegrals& cells, const std::string& what) {
  for (std::size_t i = 0; i < cells.area.size(); ++i) {
    ASSERT_TRUE(std::isfinite(cells.area[i]) && std::isfinite(cells.mass[i]) && cells.moment[i].allFinite() && cells.shift[i].allFinite())
        << what << " vertex " << i;
    ASSERT_GE(cells.area[i], 0) << what << " vertex " << i;
  }
  ASSERT_TRUE(std::isfinite(cells.energy)) << what;
}

TEST(Cells, uniform_integrals_of_a_single_triangle_are_exact) {
  // Right isosceles triangle: the cells are known; (1,0) and (0,1) are not Delaunay neighbours
  // of... every pair is, the circumcentre is the hypotenuse midpoint.
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
  // Energy of the square [0,.5]^2 about its corner: 2 * int x^2 = 1/24; each corner triangle
  // (b, (0.5,0.5), (0.5,0)): 1/48.
  EXPECT_NEAR(cells.energy, 1.0 / 24 + 2.0 / 48, 1e-15);
}

TEST(Cells, an_obtuse_triangle_is_split_by_the_true_bisectors) {
  // Two triangles sharing the long edge: (0,0) (4,0) (2,0.5) and (0,0) (2,-3) (4,0). In the upper
  // triangle (obtuse at (2,0.5)) part of the bottom belongs to (2,-3), a vertex not of that
  // triangle: the per-triangle split gave it to the corners instead.
  Mesh mesh;
  const auto a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({4, 0, 0}), c = mesh.add_vertex({2, 0.5, 0}),
             d = mesh.add_vertex({2, -3, 0});
  mesh.add_face(a, b, c);
  mesh.add_face(a, d, b);
  CellIntegrals cells;
  CellWorkspace ws;
  compute_cells(mesh, SizeField::uniform(1), cells, ws);
  EXPECT_GT(cells.pieces, 6u);
  // Brute force on a fine grid.
  const int n = 2000;
  std::vector<double> area(4, 0.0);
  const Point2 site[4] = {{0, 0}, {4, 0}, {2, 0.5}, {2, -3}};
  const double dx = 4.0 / n, dy = 3.5 / n;
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      const Point2 x(dx * (ix + 0.5), -3 + dy * (iy + 0.5));
      const bool in = (signed_area2(site[0], site[1], x) >= 0 && signed_area2(site[1], site[2], x) >= 0 && signed_area2(site[2], site[0], x) >= 0) ||
                      (signed_area2(site[0], site[3], x) >= 0 && signed_area2(site[3], site[1], x) >= 0 && signed_area2(site[1], site[0], x) >= 0);
      if (!in) continue;
      int best = 0;
      for (int k = 1; k < 4; ++k)
        if ((x - site[k]).squaredNorm() < (x - site[best]).squaredNorm()) best = k;
      area[static_cast<std::size_t>(best)] += dx * dy;
    }
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(cells.area[static_cast<std::size_t>(k)], area[static_cast<std::size_t>(k)], 5e-3) << "vertex " << k;
  EXPECT_NEAR(cells.total_area, 7.0, 1e-14);
}

/// Meshes of each test domain: the bare CDT of the domain, the sampled start (obtuse triangles,
/// not Delaunay near constraints), uniform and graded.
struct Case {
  std::string name;
  Mesh mesh;
  SizeField field;
  double area;
};

std::vector<Case> tiling_cases() {
  std::vector<Case> out;
  for (const Domain& d : {test::unit_square(), test::l_shape(), test::wedge_with_hole(), test::square_with_segment(), test::split_square()}) {
    const Mesh cdt = build_cdt(d);
    const double area = measure_domain(cdt).area;
    out.push_back({d.name + " cdt", cdt, SizeField::uniform(1), area});
    for (bool graded : {false, true}) {
      const SizeField f = graded ? local_feature_size_field(cdt, {}) : SizeField::uniform(size_for_vertex_count(measure_domain(cdt), 1000));
      out.push_back({d.name + (graded ? " graded start" : " uniform start"), sample_domain(d, cdt, f, {}), f, area});
    }
  }
  return out;
}

TEST(Cells, tile_the_domain_also_on_obtuse_and_non_delaunay_meshes) {
  std::size_t obtuse = 0;
  for (const Case& c : tiling_cases()) {
    CellIntegrals cells;
    CellWorkspace ws;
    compute_cells(c.mesh, c.field, cells, ws);
    expect_finite(cells, c.name);
    double sum = 0;
    for (double a : cells.area) sum += a;
    EXPECT_NEAR(sum, c.area, 1e-12 * c.area) << c.name;
    EXPECT_NEAR(cells.total_area, c.area, 1e-12 * c.area) << c.name;
    obtuse += obtuse_triangles(c.mesh);
    // Every vertex owns a neighbourhood of itself.
    for (auto vh : c.mesh.vertices()) EXPECT_GT(cells.area[static_cast<std::size_t>(vh.idx())], 0) << c.name << " vertex " << vh.idx();
  }
  EXPECT_GT(obtuse, 100u);  // the cases do exercise obtuse triangles
}

/// Brute force: every point of a fine grid goes to the nearest vertex of its region (the
/// triangles connected through unconstrained edges; found by a scan: small meshes only).
struct BruteForce {
  std::vector<double> area;
  std::vector<Point2> moment;
};

BruteForce brute_force(const Mesh& mesh, int n) {
  BruteForce b{std::vector<double>(mesh.n_vertices(), 0.0), std::vector<Point2>(mesh.n_vertices(), Point2(0, 0))};
  std::vector<int> region(mesh.n_faces(), -1);
  int regions = 0;
  for (auto f0 : mesh.faces()) {
    if (region[static_cast<std::size_t>(f0.idx())] >= 0) continue;
    std::vector<FaceHandle> stack{f0};
    region[static_cast<std::size_t>(f0.idx())] = regions;
    while (!stack.empty()) {
      const FaceHandle f = stack.back();
      stack.pop_back();
      for (auto h : mesh.fh_range(f)) {
        const auto g = mesh.face_handle(mesh.opposite_halfedge_handle(h));
        if (!g.is_valid() || is_constrained(mesh, mesh.edge_handle(h)) || region[static_cast<std::size_t>(g.idx())] >= 0) continue;
        region[static_cast<std::size_t>(g.idx())] = regions;
        stack.push_back(g);
      }
    }
    ++regions;
  }
  std::vector<std::vector<VertexHandle>> sites(static_cast<std::size_t>(regions));
  for (int r = 0; r < regions; ++r) {
    std::vector<char> in(mesh.n_vertices(), 0);
    for (auto f : mesh.faces())
      if (region[static_cast<std::size_t>(f.idx())] == r)
        for (auto vh : mesh.fv_range(f))
          if (!in[static_cast<std::size_t>(vh.idx())]) in[static_cast<std::size_t>(vh.idx())] = 1, sites[static_cast<std::size_t>(r)].push_back(vh);
  }
  Point2 lo(1e300, 1e300), hi(-1e300, -1e300);
  for (auto vh : mesh.vertices()) {
    lo = lo.cwiseMin(point2(mesh, vh));
    hi = hi.cwiseMax(point2(mesh, vh));
  }
  std::vector<std::pair<std::array<Point2, 3>, int>> tris;
  for (auto fh : mesh.faces()) tris.emplace_back(face_points(mesh, fh), region[static_cast<std::size_t>(fh.idx())]);
  const Point2 step = (hi - lo) / n;
  const double cell = step.x() * step.y();
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      const Point2 x = lo + Point2((ix + 0.5) * step.x(), (iy + 0.5) * step.y());
      int r = -1;
      for (const auto& [t, tr] : tris)
        if (signed_area2(t[0], t[1], x) >= 0 && signed_area2(t[1], t[2], x) >= 0 && signed_area2(t[2], t[0], x) >= 0) {
          r = tr;
          break;
        }
      if (r < 0) continue;
      const auto& cand = sites[static_cast<std::size_t>(r)];
      VertexHandle best = cand[0];
      for (VertexHandle w : cand)
        if ((x - point2(mesh, w)).squaredNorm() < (x - point2(mesh, best)).squaredNorm()) best = w;
      b.area[static_cast<std::size_t>(best.idx())] += cell;
      b.moment[static_cast<std::size_t>(best.idx())] += cell * x;
    }
  return b;
}

TEST(Cells, match_a_brute_force_nearest_vertex_integration) {
  // Small unoptimised starts (obtuse triangles) on the L-shape (reflex corner), the domain with a
  // hole, one with a dangling interior segment (one region) and one cut in two by a segment.
  for (const Domain& d : {test::l_shape(), test::wedge_with_hole(), test::square_with_segment(), test::split_square()}) {
    const Mesh cdt = build_cdt(d);
    const SizeField f = SizeField::uniform(size_for_vertex_count(measure_domain(cdt), 60));
    const Mesh mesh = sample_domain(d, cdt, f, random_start());
    CellIntegrals cells;
    CellWorkspace ws;
    compute_cells(mesh, SizeField::uniform(1), cells, ws);
    EXPECT_GT(obtuse_triangles(mesh), 10u) << d.name;
    const BruteForce b = brute_force(mesh, 700);
    const double h = f.max_value();
    double worst = 0;
    for (auto vh : mesh.vertices()) {
      const auto i = static_cast<std::size_t>(vh.idx());
      ASSERT_GT(b.area[i], 0) << d.name << " vertex " << i;
      EXPECT_NEAR(cells.area[i], b.area[i], 0.02 * h * h) << d.name << " vertex " << i;
      const double err = (cells.centroid(vh.idx()) - b.moment[i] / b.area[i]).norm();
      worst = std::max(worst, err / h);
      EXPECT_LT(err, 0.01 * h) << d.name << " vertex " << i;
    }
    std::cout << "[cells] " << d.name << ": " << mesh.n_vertices() << " vertices, " << obtuse_triangles(mesh)
              << " obtuse triangles, worst centroid error vs a 700^2 grid " << worst << " h\n";
  }
}

TEST(Cells, degenerate_grids_give_exact_areas_and_no_nan) {
  // A square grid cut by diagonals (every quad cocircular, collinear boundary vertices).
  const int n = 8;
  Mesh mesh;
  std::vector<VertexHandle> v;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) v.push_back(mesh.add_vertex({static_cast<double>(i), static_cast<double>(j), 0}));
  auto at = [&](int i, int j) { return v[static_cast<std::size_t>(j * (n + 1) + i)]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  CellIntegrals cells;
  CellWorkspace ws;
  compute_cells(mesh, SizeField::uniform(1), cells, ws);
  expect_finite(cells, "grid");
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double w = (i == 0 || i == n) ? 0.5 : 1.0, hgt = (j == 0 || j == n) ? 0.5 : 1.0;
      const int k = at(i, j).idx();
      EXPECT_NEAR(cells.area[static_cast<std::size_t>(k)], w * hgt, 1e-13) << i << "," << j;
      const Point2 offset((i == 0) - (i == n), (j == 0) - (j == n));  // half cells lean inwards by 1/4
      EXPECT_NEAR((cells.centroid(k) - point2(mesh, at(i, j)) - 0.25 * offset).norm(), 0.0, 1e-13) << i << "," << j;
    }
  // A fan of nearly collinear points along the bottom edge.
  Mesh fan;
  const auto apex = fan.add_vertex({0.5, 1, 0});
  std::vector<VertexHandle> base;
  for (int i = 0; i <= 20; ++i) base.push_back(fan.add_vertex({i / 20.0, 1e-17 * (i % 2), 0}));
  for (int i = 0; i < 20; ++i) fan.add_face(base[static_cast<std::size_t>(i)], base[static_cast<std::size_t>(i) + 1], apex);
  compute_cells(fan, SizeField::uniform(1), cells, ws);
  expect_finite(cells, "fan");
  double sum = 0;
  for (double a : cells.area) sum += a;
  EXPECT_NEAR(sum, cells.total_area, 1e-14);
}

TEST(Cells, whole_cells_equal_their_pieces) {
  // After optimisation most interior cells lie inside their vertex's star and are integrated
  // whole (their triangles skipped); with the face list given every cell is summed from its
  // pieces instead. Same integrals.
  for (const Domain& d : {test::l_shape(), test::wedge_with_hole(), test::square_with_segment()}) {
    const Mesh cdt = build_cdt(d);
    SizeFieldParams sp;
    sp.target_vertices = 1500;
    sp.graded = d.name == "wedge_with_hole";
    const SizeField f = make_size_field(cdt, sp);
    Mesh mesh = sample_domain(d, cdt, f, {});
    CvtOptimizeParams op;
    op.lbfgs_iterations = 20;
    cvt_optimize(mesh, f, op);
    std::vector<FaceHandle> all;
    for (auto fh : mesh.faces()) all.push_back(fh);
    CellIntegrals whole, pieces;
    CellWorkspace w1, w2;
    compute_cells(mesh, f, whole, w1);
    compute_cells(mesh, f, pieces, w2, &all);
    EXPECT_LT(whole.pieces * 2, pieces.pieces) << d.name << ": the whole-cell path is taken";
    const double h2 = f.min_value() * f.min_value();
    for (std::size_t i = 0; i < whole.area.size(); ++i) {
      EXPECT_NEAR(whole.area[i], pieces.area[i], 1e-12 * h2) << d.name << " vertex " << i;
      EXPECT_NEAR((whole.shift[i] - pieces.shift[i]).norm(), 0.0, 1e-9 * std::abs(pieces.mass[i]) * f.max_value()) << d.name << " vertex " << i;
    }
    EXPECT_NEAR(whole.energy, pieces.energy, 1e-11 * pieces.energy) << d.name;
  }
}

TEST(Cells, repaired_triangulation_equals_a_fresh_one) {
  // The workspace repairs its Delaunay triangulation by flips after small moves; a fresh workspace
  // builds it from scratch: same cells.
  const Domain d = test::l_shape();
  const Mesh cdt = build_cdt(d);
  const SizeField f = SizeField::uniform(size_for_vertex_count(measure_domain(cdt), 800));
  Mesh mesh = sample_domain(d, cdt, f, {});
  CellIntegrals reused, fresh;
  CellWorkspace ws;
  compute_cells(mesh, f, reused, ws);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (auto vh : mesh.vertices())
    if (mesh.data(vh).kind == VertexKind::Free) set_point2(mesh, vh, point2(mesh, vh) + f.max_value() * Point2(u(rng), u(rng)));
  compute_cells(mesh, f, reused, ws);
  EXPECT_EQ(ws.delaunay_rebuilds(), 1u);
  EXPECT_GT(ws.delaunay_flips(), 0u);
  CellWorkspace ws2;
  compute_cells(mesh, f, fresh, ws2);
  for (std::size_t i = 0; i < reused.area.size(); ++i) EXPECT_NEAR(reused.area[i], fresh.area[i], 1e-14 * f.max_value() * f.max_value()) << i;
  EXPECT_NEAR(reused.energy, fresh.energy, 1e-12 * fresh.energy);
}

TEST(Cells, gradient_matches_finite_differences_on_an_obtuse_start) {
  // dF/dv = 2 m (v - c) for the true clipped Voronoi cells, whatever the triangles: checked on the
  // unoptimised start of the L-shape at vertices of obtuse triangles.
  const Domain d = test::l_shape();
  const Mesh cdt = build_cdt(d);
  const SizeField f = SizeField::uniform(size_for_vertex_count(measure_domain(cdt), 200));
  Mesh mesh = sample_domain(d, cdt, f, random_start());
  CellIntegrals cells;
  CellWorkspace ws;
  int checked = 0;
  for (auto fh : mesh.faces()) {
    if (checked >= 10) break;
    const auto p = face_points(mesh, fh);
    const auto vs = face_vertices(mesh, fh);
    for (int i = 0; i < 3 && checked < 10; ++i) {
      if ((p[(i + 1) % 3] - p[i]).dot(p[(i + 2) % 3] - p[i]) >= 0 || mesh.data(vs[i]).kind != VertexKind::Free) continue;
      const VertexHandle c = vs[i];
      compute_cells(mesh, f, cells, ws);
      const Point2 g = -2.0 * cells.shift[static_cast<std::size_t>(c.idx())];
      const double eps = 1e-6 * f.max_value();
      for (int k = 0; k < 2; ++k) {
        Point2 dv(0, 0);
        dv[k] = eps;
        const Point2 p0 = point2(mesh, c);
        set_point2(mesh, c, p0 + dv);
        compute_cells(mesh, f, cells, ws);
        const double fp = cells.energy;
        set_point2(mesh, c, p0 - dv);
        compute_cells(mesh, f, cells, ws);
        const double fm = cells.energy;
        set_point2(mesh, c, p0);
        EXPECT_NEAR((fp - fm) / (2 * eps), g[k], 1e-5 * g.norm() + 1e-9 * cells.energy / f.max_value()) << "vertex " << c.idx() << " coordinate " << k;
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, 10);
}

}  // namespace
}  // namespace acute
