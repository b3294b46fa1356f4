// CVT benchmarks on the unit square (uniform size for a target vertex count) and on a graded
// domain (square with a small square hole near a corner: the default local-feature-size field).
//  - BM_Sample: size field + sampling + the two CDTs.
//  - BM_LloydIteration / BM_LbfgsIteration: one iteration (cells + moves + Delaunay restoration),
//    measured over 10 iterations after a 10-iteration Lloyd warm-up; should grow about linearly.
//  - BM_Converged: cvt_mesh with the default schedule (10 Lloyd, then L-BFGS to max |v - c|/h < 1e-3
//    or 300 iterations); counters give the iterations used.
#include <acute/cvt/cvt.h>
#include <acute/delaunay/cdt.h>

#include <benchmark/benchmark.h>

#include <ctime>

namespace {

acute::Domain square() {
  acute::Domain d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  d.name = "unit_square";
  return d;
}

acute::Domain square_with_hole() {
  acute::Domain d = square();
  d.points.insert(d.points.end(), {{0.05, 0.05}, {0.07, 0.05}, {0.07, 0.07}, {0.05, 0.07}});
  d.segments.insert(d.segments.end(), {{4, 5}, {5, 6}, {6, 7}, {7, 4}});
  d.holes.push_back({0.06, 0.06});
  d.name = "square_with_small_hole";
  return d;
}

struct Start {
  acute::Mesh mesh;
  acute::SizeField field;
};

Start prepare(std::size_t n) {
  const acute::Domain d = square();
  const acute::Mesh cdt = acute::build_cdt(d);
  acute::SizeFieldParams sp;
  sp.target_vertices = n;
  Start s{acute::Mesh(), acute::make_size_field(cdt, sp)};
  // Random seeds: the lattice start on a square is a CVT already, and the optimiser's cost is
  // measured from a rough start (as the seams and boundary rows of a real domain are).
  acute::SamplingParams random;
  random.interior = acute::InteriorSampling::Random;
  s.mesh = acute::sample_domain(d, cdt, s.field, random);
  acute::CvtOptimizeParams warm;
  warm.lloyd_iterations = 10;
  warm.lbfgs_iterations = 0;
  acute::cvt_optimize(s.mesh, s.field, warm);
  return s;
}

void BM_Sample(benchmark::State& state) {
  const acute::Domain d = square();
  const acute::Mesh cdt = acute::build_cdt(d);
  acute::SizeFieldParams sp;
  sp.target_vertices = static_cast<std::size_t>(state.range(0));
  const acute::SizeField f = acute::make_size_field(cdt, sp);
  std::size_t nv = 0;
  for (auto _ : state) {
    acute::Mesh m = acute::sample_domain(d, cdt, f);
    nv = m.n_vertices();
    benchmark::DoNotOptimize(nv);
  }
  state.counters["vertices"] = static_cast<double>(nv);
}

void iterations(benchmark::State& state, bool lbfgs) {
  const Start s = prepare(static_cast<std::size_t>(state.range(0)));
  constexpr int kIters = 10;
  double per_iter = 0;
  for (auto _ : state) {
    state.PauseTiming();
    acute::Mesh m = s.mesh;
    state.ResumeTiming();
    acute::CvtOptimizeParams p;
    p.lloyd_iterations = lbfgs ? 0 : kIters;
    p.lbfgs_iterations = lbfgs ? kIters : 0;
    p.move_tolerance = 0;
    p.max_move_tolerance = 0;
    p.energy_tolerance = 0;
    const std::clock_t t0 = std::clock();  // CPU time: the machine is shared
    const auto r = acute::cvt_optimize(m, s.field, p);
    per_iter = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC / kIters;
    benchmark::DoNotOptimize(r.energy);
  }
  state.counters["vertices"] = static_cast<double>(s.mesh.n_vertices());
  state.counters["cpu_s_per_iter"] = per_iter;
  state.counters["cpu_us_per_iter_per_1k_vertices"] = 1e9 * per_iter / static_cast<double>(s.mesh.n_vertices());
}

void BM_LloydIteration(benchmark::State& state) { iterations(state, false); }
void BM_LbfgsIteration(benchmark::State& state) { iterations(state, true); }

void BM_Converged(benchmark::State& state) {
  const acute::Domain d = state.range(1) ? square_with_hole() : square();
  acute::CvtParams p;
  if (!state.range(1)) p.target_vertices = static_cast<std::size_t>(state.range(0));
  p.move_tolerance = 1e-3;
  p.lbfgs_iterations = 300;
  p.interior = state.range(2) ? acute::InteriorSampling::Random : acute::InteriorSampling::Lattice;
  acute::CvtResult r;
  for (auto _ : state) {
    r = acute::cvt_mesh(d, p);
    benchmark::DoNotOptimize(r.energy);
  }
  state.SetLabel(d.name + (state.range(2) ? " random start" : " lattice start"));
  state.counters["vertices"] = static_cast<double>(r.mesh.n_vertices());
  state.counters["iterations"] = r.iterations;
  state.counters["converged"] = r.optimization.converged;
  state.counters["fallbacks"] = r.optimization.fallbacks;
}

}  // namespace

BENCHMARK(BM_Sample)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_LloydIteration)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_LbfgsIteration)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->Iterations(1);
// {vertices (0: the domain's own size), square_with_hole, random start}
BENCHMARK(BM_Converged)
    ->Args({10'000, 0, 0})
    ->Args({10'000, 0, 1})
    ->Args({100'000, 0, 0})
    ->Args({100'000, 0, 1})
    ->Args({0, 1, 0})
    ->Args({0, 1, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

BENCHMARK_MAIN();
