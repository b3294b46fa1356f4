// Delaunay refinement benchmarks: the unit square refined to about 1M triangles (CDT + refine),
// at 20.7 degrees (CGAL's default B = 0.125) and at 30 degrees. With ACUTE_BENCH_CGAL the same
// square is refined by CGAL's Delaunay_mesher_2 with B = 0.125 and an edge-length bound
// calibrated (outside the timing) to give the same vertex count as acute at 20.7 degrees.
#include <acute/mesher.h>
#include <acute/refine/refine.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>

#ifdef ACUTE_BENCH_CGAL
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

// Circumradius bound H / sqrt(3) with this H gives about 1M triangles.
constexpr double kMaxEdge = 0.002;

acute::Domain unit_square() {
  acute::Domain d;
  d.name = "unit-square";
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return d;
}

std::size_t acute_refine_square(double min_angle, double max_edge, std::size_t* faces = nullptr) {
  acute::Mesh mesh = acute::build_domain_cdt(unit_square());
  acute::RefineParams params;
  params.min_angle_deg = min_angle;
  params.max_edge = max_edge;
  acute::refine(mesh, params);
  if (faces) *faces = mesh.n_faces();
  return mesh.n_vertices();
}

[[maybe_unused]] std::size_t acute_vertices_20_7() {  // the CGAL peer's vertex target
  static const std::size_t n = acute_refine_square(20.7, kMaxEdge);
  return n;
}

void BM_acute_refine_square_1M(benchmark::State& state) {
  const double min_angle = state.range(0) / 10.0;
  std::size_t v = 0, f = 0;
  for (auto _ : state) {
    v = acute_refine_square(min_angle, kMaxEdge, &f);
    benchmark::DoNotOptimize(v);
  }
  state.counters["vertices"] = static_cast<double>(v);
  state.counters["triangles"] = static_cast<double>(f);
}
BENCHMARK(BM_acute_refine_square_1M)->Arg(207)->Arg(300)->Unit(benchmark::kMillisecond)->Iterations(3);

#ifdef ACUTE_BENCH_CGAL
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

std::size_t cgal_refine_square(double size_bound, std::size_t* faces = nullptr) {
  Cdt cdt;
  const auto a = cdt.insert(K::Point_2(0, 0)), b = cdt.insert(K::Point_2(1, 0));
  const auto c = cdt.insert(K::Point_2(1, 1)), d = cdt.insert(K::Point_2(0, 1));
  cdt.insert_constraint(a, b);
  cdt.insert_constraint(b, c);
  cdt.insert_constraint(c, d);
  cdt.insert_constraint(d, a);
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, size_bound));
  if (faces) *faces = cdt.number_of_faces();
  return cdt.number_of_vertices();
}

/// CGAL's edge bound giving acute's vertex count: vertices scale as 1/S^2; two secant steps.
double cgal_size_bound() {
  static const double s = [] {
    const double target = static_cast<double>(acute_vertices_20_7());
    double bound = kMaxEdge;
    for (int k = 0; k < 2; ++k) bound *= std::sqrt(static_cast<double>(cgal_refine_square(bound)) / target);
    return bound;
  }();
  return s;
}

void BM_cgal_refine_square_1M(benchmark::State& state) {
  const double bound = cgal_size_bound();
  std::size_t v = 0, f = 0;
  for (auto _ : state) {
    v = cgal_refine_square(bound, &f);
    benchmark::DoNotOptimize(v);
  }
  state.counters["vertices"] = static_cast<double>(v);
  state.counters["triangles"] = static_cast<double>(f);
  state.counters["size_bound"] = bound;
}
BENCHMARK(BM_cgal_refine_square_1M)->Unit(benchmark::kMillisecond)->Iterations(3);
#endif

}  // namespace

BENCHMARK_MAIN();
