// Layer: predicates (private). Floating-point expansion arithmetic: a real number is held exactly
// as an unevaluated sum of doubles ("components") that are nonoverlapping and sorted by increasing
// magnitude (Priest 1991, Shewchuk 1997). Written from the theory, not from predicates.c.
//
// Preconditions for exactness: IEEE binary64 round-to-nearest-even, no overflow and no underflow
// in any intermediate. validate_coordinate's range [2^-142, 2^201] guarantees both for polynomials
// of degree <= 4 in coordinate differences. The TU must be compiled with -ffp-contract=off (an FMA
// would silently break the error-free transformations below).
#pragma once

#include <cmath>

namespace acute::predicates::detail {

// ---- Error-free transformations on two doubles -------------------------------------------------

/// s + e == a + b exactly, s == fl(a + b) (Knuth's branch-free two-sum).
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double b_virtual = s - a;
  const double a_virtual = s - b_virtual;
  e = (a - a_virtual) + (b - b_virtual);
}

/// s + e == a + b exactly; requires |a| >= |b| (or a == 0) (Dekker's fast two-sum).
inline void fast_two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  e = b - (s - a);
}

/// d + e == a - b exactly, d == fl(a - b).
inline void two_diff(double a, double b, double& d, double& e) {
  d = a - b;
  const double b_virtual = a - d;
  const double a_virtual = d + b_virtual;
  e = (a - a_virtual) + (b_virtual - b);
}

/// Veltkamp splitting: a == hi + lo exactly, each half fits in 26 significant bits, so every
/// product of halves is exact. 2^27 + 1 is the splitter for a 53-bit significand.
inline void split(double a, double& hi, double& lo) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double c = kSplitter * a;
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

/// p + e == a * b exactly, p == fl(a * b) (Dekker's product; no FMA, see header note).
inline void two_product_presplit(double a, double b, double b_hi, double b_lo, double& p, double& e) {
  p = a * b;
  double a_hi, a_lo;
  split(a, a_hi, a_lo);
  // Each partial product is exact and each subtraction is exact (Dekker 1971, Theorem 5.7).
  const double err1 = p - a_hi * b_hi;
  const double err2 = err1 - a_lo * b_hi;
  const double err3 = err2 - a_hi * b_lo;
  e = a_lo * b_lo - err3;
}

inline void two_product(double a, double b, double& p, double& e) {
  double b_hi, b_lo;
  split(b, b_hi, b_lo);
  two_product_presplit(a, b, b_hi, b_lo, p, e);
}

// ---- Expansions ---------------------------------------------------------------------------------

/// An expansion with room for N components. Components are kept zero-eliminated: either n == 1 and
/// the value may be 0, or every stored component is nonzero. The sign of the value is the sign of
/// the last (largest) component because lower components sum to less than it in magnitude.
template <int N>
struct Expansion {
  double c[N];  // deliberately uninitialised: large buffers on the (rare) exact path
  int n;

  Expansion() : n(0) {}  // NOLINT(cppcoreguidelines-pro-type-member-init)
  explicit Expansion(double x) : n(1) { c[0] = x; }

  int sign() const { return c[n - 1] > 0 ? 1 : (c[n - 1] < 0 ? -1 : 0); }
  double estimate() const {
    double s = 0;
    for (int i = 0; i < n; ++i) s += c[i];
    return s;
  }
  void negate() {
    for (int i = 0; i < n; ++i) c[i] = -c[i];
  }
  void push_nonzero(double x) {
    if (x != 0) c[n++] = x;
  }
  void finish(double top) {  // store the most significant component; keep "0" if nothing else
    if (top != 0 || n == 0) c[n++] = top;
  }
};

/// The exact difference a - b as an expansion of at most two components.
inline Expansion<2> diff(double a, double b) {
  Expansion<2> r;
  double d, e;
  two_diff(a, b, d, e);
  r.push_nonzero(e);
  r.finish(d);
  return r;
}

/// The exact product a * b as an expansion of at most two components.
inline Expansion<2> product(double a, double b) {
  Expansion<2> r;
  double p, e;
  two_product(a, b, p, e);
  r.push_nonzero(e);
  r.finish(p);
  return r;
}

/// h = e + f for raw zero-eliminated expansions; h must hold m + k components and may not alias.
/// Merge both by magnitude, then sweep a two-sum accumulator from the small end, emitting each
/// roundoff as a component (the linear-time expansion sum of Shewchuk 1997, zero-eliminated).
/// Returns the length of h.
inline int sum_into(const double* e, int m, const double* f, int k, double* h) {
  int i = 0, j = 0, n = 0;
  auto next = [&]() -> double {
    if (j >= k || (i < m && std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
    return f[j++];
  };
  const int total = m + k;
  double q = next();
  if (total >= 2) {
    double s, err;
    fast_two_sum(next(), q, s, err);  // merged order: the second value is not smaller
    if (err != 0) h[n++] = err;
    q = s;
    for (int taken = 2; taken < total; ++taken) {
      two_sum(q, next(), s, err);
      if (err != 0) h[n++] = err;
      q = s;
    }
  }
  if (q != 0 || n == 0) h[n++] = q;
  return n;
}

/// h = e * b for a raw expansion e and a double b; h must hold 2m components. Returns its length.
inline int scale_into(const double* e, int m, double b, double* h) {
  int n = 0;
  double b_hi, b_lo;
  split(b, b_hi, b_lo);
  double q, low;
  two_product_presplit(e[0], b, b_hi, b_lo, q, low);
  if (low != 0) h[n++] = low;
  for (int i = 1; i < m; ++i) {
    double p_hi, p_lo, s, err;
    two_product_presplit(e[i], b, b_hi, b_lo, p_hi, p_lo);
    two_sum(q, p_lo, s, err);
    if (err != 0) h[n++] = err;
    fast_two_sum(p_hi, s, q, err);  // p_hi dominates s by the nonoverlapping property
    if (err != 0) h[n++] = err;
  }
  if (q != 0 || n == 0) h[n++] = q;
  return n;
}

template <int M, int K>
Expansion<M + K> sum(const Expansion<M>& e, const Expansion<K>& f) {
  Expansion<M + K> h;
  h.n = sum_into(e.c, e.n, f.c, f.n, h.c);
  return h;
}

template <int M, int K>
Expansion<M + K> difference(const Expansion<M>& e, Expansion<K> f) {
  f.negate();
  return sum(e, f);
}

template <int M>
Expansion<2 * M> scale(const Expansion<M>& e, double b) {
  Expansion<2 * M> h;
  h.n = scale_into(e.c, e.n, b, h.c);
  return h;
}

/// h = e * f: the sum over the components of f of e scaled by that component.
template <int M, int K>
Expansion<2 * M * K> product(const Expansion<M>& e, const Expansion<K>& f) {
  Expansion<2 * M * K> acc;
  double other[2 * M * K];
  double part[2 * M];
  acc.n = scale_into(e.c, e.n, f.c[0], acc.c);
  double* cur = acc.c;
  double* spare = other;
  for (int j = 1; j < f.n; ++j) {
    const int part_n = scale_into(e.c, e.n, f.c[j], part);
    acc.n = sum_into(cur, acc.n, part, part_n, spare);  // never longer than 2*M*K
    double* t = cur;
    cur = spare;
    spare = t;
  }
  if (cur != acc.c)
    for (int i = 0; i < acc.n; ++i) acc.c[i] = cur[i];
  return acc;
}

}  // namespace acute::predicates::detail
