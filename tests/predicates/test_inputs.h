// Input generators shared by the predicate tests: seeded, so every failure reproduces.
#pragma once

#include <acute/core/types.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

namespace acute::test {

using Rng = std::mt19937_64;

inline double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
inline int uniform_int(Rng& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

inline Point2 random_in_box(Rng& rng, double lo, double hi) { return {uniform(rng, lo, hi), uniform(rng, lo, hi)}; }

/// A signed value with a random significand and a decimal magnitude 10^[lo_exp, hi_exp].
inline double random_magnitude(Rng& rng, int lo_exp, int hi_exp) {
  const double v = uniform(rng, 1.0, 10.0) * std::pow(10.0, uniform_int(rng, lo_exp, hi_exp));
  return uniform_int(rng, 0, 1) != 0 ? v : -v;
}

/// x moved by k units in the last place (k may be negative).
inline double ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, INFINITY);
  for (; k < 0; ++k) x = std::nextafter(x, -INFINITY);
  return x;
}

inline Point2 perturb(Rng& rng, const Point2& p, int max_ulps) {
  return {ulps(p.x(), uniform_int(rng, -max_ulps, max_ulps)), ulps(p.y(), uniform_int(rng, -max_ulps, max_ulps))};
}

inline Point2 scaled(const Point2& p, int pow2) { return {std::ldexp(p.x(), pow2), std::ldexp(p.y(), pow2)}; }

/// Human-readable, round-trippable description of points for failure messages.
template <typename... P>
std::string describe(const P&... p) {
  std::ostringstream out;
  out.precision(17);
  ((out << "(" << p.x() << ", " << p.y() << ") "), ...);
  return out.str();
}

}  // namespace acute::test
