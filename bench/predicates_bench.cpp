// Filtered exact predicates versus the naive double determinants.
// Random: 1e5 uniform points in a box, cycling through consecutive triples/quadruples (the filter
// decides almost everything). Degenerate: small integer grid / lattice circle points, where many
// calls are exactly zero and take the exact path.
#include <benchmark/benchmark.h>

#include <acute/predicates/predicates.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using acute::Point2;
namespace pr = acute::predicates;

constexpr std::size_t kPoints = 100000;

const std::vector<Point2>& random_points() {
  static const std::vector<Point2> pts = [] {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1000.0, 1000.0);
    std::vector<Point2> v(kPoints);
    for (Point2& p : v) p = Point2(u(rng), u(rng));
    return v;
  }();
  return pts;
}

const std::vector<Point2>& grid_points() {  // 5x5 grid: about a third of triples are collinear
  static const std::vector<Point2> pts = [] {
    std::mt19937_64 rng(43);
    std::uniform_int_distribution<int> u(0, 4);
    std::vector<Point2> v(kPoints);
    for (Point2& p : v) p = Point2(u(rng), u(rng));
    return v;
  }();
  return pts;
}

const std::vector<Point2>& circle_points() {  // lattice points of x^2 + y^2 = 1105^2: all cocircular
  static const std::vector<Point2> pts = [] {
    std::vector<Point2> on;
    for (int x = -1105; x <= 1105; ++x) {
      const double y = std::sqrt(1105.0 * 1105.0 - double(x) * x);
      if (y == std::floor(y)) {
        on.emplace_back(x, y);
        on.emplace_back(x, -y);
      }
    }
    std::mt19937_64 rng(44);
    std::uniform_int_distribution<std::size_t> u(0, on.size() - 1);
    std::vector<Point2> v(kPoints);
    for (Point2& p : v) p = on[u(rng)];
    return v;
  }();
  return pts;
}

template <typename F>
void run3(benchmark::State& state, const std::vector<Point2>& p, F f) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f(p[i], p[i + 1], p[i + 2]));
    i = i + 3 < kPoints - 2 ? i + 3 : 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <typename F>
void run4(benchmark::State& state, const std::vector<Point2>& p, F f) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f(p[i], p[i + 1], p[i + 2], p[i + 3]));
    i = i + 4 < kPoints - 3 ? i + 4 : 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void BM_orient2d_naive(benchmark::State& s) { run3(s, random_points(), pr::detail::orient2d_naive); }
void BM_orient2d(benchmark::State& s) { run3(s, random_points(), pr::orient2d); }
void BM_incircle_naive(benchmark::State& s) { run4(s, random_points(), pr::detail::incircle_naive); }
void BM_incircle(benchmark::State& s) { run4(s, random_points(), pr::incircle); }
void BM_orient2d_grid_degenerate(benchmark::State& s) { run3(s, grid_points(), pr::orient2d); }
void BM_incircle_cocircular(benchmark::State& s) { run4(s, circle_points(), pr::incircle); }
// The exact stages alone on random input: every difference inexact, full-length expansions (the
// worst case the filter hands over, e.g. nearly cocircular points with non-representable spacing).
void BM_orient2d_exact_stage(benchmark::State& s) { run3(s, random_points(), pr::detail::orient2d_exact); }
void BM_incircle_exact_stage(benchmark::State& s) { run4(s, random_points(), pr::detail::incircle_exact); }
void BM_angle_kind(benchmark::State& s) { run3(s, random_points(), pr::angle_kind); }
void BM_intersect_segments(benchmark::State& s) { run4(s, random_points(), pr::intersect_segments); }

BENCHMARK(BM_orient2d_naive);
BENCHMARK(BM_orient2d);
BENCHMARK(BM_incircle_naive);
BENCHMARK(BM_incircle);
BENCHMARK(BM_orient2d_grid_degenerate);
BENCHMARK(BM_incircle_cocircular);
BENCHMARK(BM_orient2d_exact_stage);
BENCHMARK(BM_incircle_exact_stage);
BENCHMARK(BM_angle_kind);
BENCHMARK(BM_intersect_segments);

}  // namespace

BENCHMARK_MAIN();
