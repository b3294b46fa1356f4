// Delaunay / CDT benchmarks: 1M uniform random points, and the CDT of a large synthetic domain
// (a 100k-gon with 20 polygonal holes of 5k vertices and 500k random points). With
// ACUTE_BENCH_CGAL the same inputs are also triangulated by CGAL in the same run.
#include <acute/delaunay/cdt.h>

#include "delaunay/triangulation.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#ifdef ACUTE_BENCH_CGAL
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#endif

namespace {

using acute::Point2;

const std::vector<Point2>& random_points_1m() {
  static const std::vector<Point2> pts = [] {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Point2> p(1000000);
    for (auto& q : p) q = Point2(u(rng), u(rng));
    return p;
  }();
  return pts;
}

const acute::Domain& large_domain() {
  static const acute::Domain d = [] {
    acute::Domain dom;
    dom.name = "bench-large";
    auto add_circle = [&](double cx, double cy, double r, int n) {
      const int base = static_cast<int>(dom.points.size());
      for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n;
        dom.points.emplace_back(cx + r * std::cos(a), cy + r * std::sin(a));
        dom.segments.push_back({base + k, base + (k + 1) % n});
      }
    };
    add_circle(0.5, 0.5, 0.5, 100000);
    for (int h = 0; h < 20; ++h) {
      const double a = 2 * M_PI * h / 20;
      const double cx = 0.5 + 0.3 * std::cos(a), cy = 0.5 + 0.3 * std::sin(a);
      add_circle(cx, cy, 0.03, 5000);
      dom.holes.emplace_back(cx, cy);
    }
    std::mt19937_64 rng(777);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 500000; ++k) dom.points.emplace_back(u(rng), u(rng));
    return dom;
  }();
  return d;
}

void BM_acute_delaunay_1M(benchmark::State& state) {
  const auto& pts = random_points_1m();
  for (auto _ : state) {
    auto tris = acute::delaunay_triangles(pts);
    benchmark::DoNotOptimize(tris.data());
    state.counters["triangles"] = static_cast<double>(tris.size());
  }
}
BENCHMARK(BM_acute_delaunay_1M)->Unit(benchmark::kMillisecond)->Iterations(3);

// The engine alone: CDT (points + segments, no domain extraction or Mesh).
void BM_acute_cdt_engine_large(benchmark::State& state) {
  const auto& d = large_domain();
  for (auto _ : state) {
    const auto order = acute::detail::brio_hilbert_order(d.points);
    acute::detail::Triangulation tr(d.points);
    tr.insert_points(order);
    for (std::size_t s = 0; s < d.segments.size(); ++s) tr.insert_segment(d.segments[s][0], d.segments[s][1], static_cast<int>(s));
    benchmark::DoNotOptimize(tr.num_slots());
  }
}
BENCHMARK(BM_acute_cdt_engine_large)->Unit(benchmark::kMillisecond)->Iterations(3);

// build_cdt end to end: + domain (flood, holes) + acute::Mesh (OpenMesh) hand-over.
void BM_acute_build_cdt_large(benchmark::State& state) {
  const auto& d = large_domain();
  for (auto _ : state) {
    acute::CdtStats st;
    acute::Mesh m = acute::build_cdt(d, {}, &st);
    state.counters["faces"] = static_cast<double>(m.n_faces());
  }
}
BENCHMARK(BM_acute_build_cdt_large)->Unit(benchmark::kMillisecond)->Iterations(3);

#ifdef ACUTE_BENCH_CGAL
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

void BM_cgal_delaunay_1M(benchmark::State& state) {
  const auto& pts = random_points_1m();
  std::vector<K::Point_2> cp;
  cp.reserve(pts.size());
  for (const auto& p : pts) cp.emplace_back(p.x(), p.y());
  for (auto _ : state) {
    CGAL::Delaunay_triangulation_2<K> dt(cp.begin(), cp.end());
    state.counters["triangles"] = static_cast<double>(dt.number_of_faces());
  }
}
BENCHMARK(BM_cgal_delaunay_1M)->Unit(benchmark::kMillisecond)->Iterations(3);

using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<int, K>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Points (spatially sorted range insert), then constraints by vertex handles, then the same
// domain flood (outside + hole seeds) as build_cdt.
void BM_cgal_cdt_large(benchmark::State& state) {
  const auto& d = large_domain();
  std::vector<K::Point_2> cp;
  for (const auto& p : d.points) cp.emplace_back(p.x(), p.y());
  for (auto _ : state) {
    Cdt cdt;
    std::vector<std::pair<K::Point_2, std::size_t>> indexed;
    indexed.reserve(cp.size());
    for (std::size_t i = 0; i < cp.size(); ++i) indexed.emplace_back(cp[i], i);
    std::vector<Cdt::Vertex_handle> vh(cp.size());
    // Range insert with indices (spatially sorted by CGAL), then handles by index.
    cdt.insert(indexed.begin(), indexed.end());
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) vh[v->info()] = v;
    for (const auto& s : d.segments) cdt.insert_constraint(vh[static_cast<std::size_t>(s[0])], vh[static_cast<std::size_t>(s[1])]);
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = 0;
    std::vector<Cdt::Face_handle> stack;
    auto flood = [&](Cdt::Face_handle start) {
      start->info() = 1;
      stack.push_back(start);
      while (!stack.empty()) {
        auto f = stack.back();
        stack.pop_back();
        for (int i = 0; i < 3; ++i) {
          if (f->is_constrained(i)) continue;
          auto n = f->neighbor(i);
          if (n->info()) continue;
          n->info() = 1;
          stack.push_back(n);
        }
      }
    };
    flood(cdt.infinite_face());
    for (const auto& h : d.holes) {
      auto f = cdt.locate(K::Point_2(h.x(), h.y()));
      if (!f->info()) flood(f);
    }
    std::size_t kept = 0;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) kept += f->info() ? 0 : 1;
    state.counters["faces"] = static_cast<double>(kept);
  }
}
BENCHMARK(BM_cgal_cdt_large)->Unit(benchmark::kMillisecond)->Iterations(3);
#endif

}  // namespace

BENCHMARK_MAIN();
