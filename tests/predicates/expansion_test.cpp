// The private expansion arithmetic, checked component by component against the exact oracle.
#include <gtest/gtest.h>

#include <cmath>

#include "predicates/expansion.h"
#include "predicates/test_inputs.h"
#include "support/exact_rational.h"

namespace acute::test {
namespace {

namespace ex = predicates::detail;

// A double with a random significand and a binary exponent in [lo, hi].
double random_double(Rng& rng, int lo, int hi) {
  const double v = std::ldexp(uniform(rng, 1.0, 2.0), uniform_int(rng, lo, hi));
  return uniform_int(rng, 0, 1) != 0 ? v : -v;
}

template <int N>
Dyadic value_of(const ex::Expansion<N>& e) {
  Dyadic s;
  for (int i = 0; i < e.n; ++i) s = s + Dyadic(e.c[i]);
  return s;
}

// Zero-eliminated, sorted by increasing magnitude, and nonoverlapping: each component is smaller
// than the lowest set bit of the next one, so the top component carries the sign.
template <int N>
::testing::AssertionResult well_formed(const ex::Expansion<N>& e) {
  if (e.n < 1 || e.n > N) return ::testing::AssertionFailure() << "length " << e.n;
  if (e.n == 1) return ::testing::AssertionSuccess();
  for (int i = 0; i + 1 < e.n; ++i) {
    if (e.c[i] == 0) return ::testing::AssertionFailure() << "zero component " << i;
    int exp_next = 0;
    std::frexp(e.c[i + 1], &exp_next);
    // lowest set bit of c[i+1]: scale until integral
    double m = std::fabs(e.c[i + 1]);
    int low = exp_next - 53;
    while (std::ldexp(m, -(low + 1)) == std::floor(std::ldexp(m, -(low + 1)))) ++low;
    if (!(std::fabs(e.c[i]) < std::ldexp(1.0, low)))
      return ::testing::AssertionFailure() << "components " << i << " and " << i + 1 << " overlap";
  }
  return ::testing::AssertionSuccess();
}

ex::Expansion<4> random_expansion(Rng& rng, int lo, int hi) {
  // Sum of four random doubles: exact as an expansion, usually with several components.
  const auto s1 = ex::sum(ex::Expansion<1>(random_double(rng, lo, hi)), ex::Expansion<1>(random_double(rng, lo, hi)));
  const auto s2 = ex::sum(ex::Expansion<1>(random_double(rng, lo, hi)), ex::Expansion<1>(random_double(rng, lo, hi)));
  return ex::sum(s1, s2);
}

TEST(Expansion, two_product_and_two_diff_are_error_free) {
  Rng rng(31);
  for (int i = 0; i < 20000; ++i) {
    const double a = random_double(rng, -200, 200), b = random_double(rng, -200, 200);
    const auto p = ex::product(a, b);
    EXPECT_EQ((value_of(p) - Dyadic(a) * Dyadic(b)).sign(), 0) << a << " * " << b;
    EXPECT_TRUE(well_formed(p)) << a << " * " << b;
    const auto d = ex::diff(a, b);
    EXPECT_EQ((value_of(d) - (Dyadic(a) - Dyadic(b))).sign(), 0) << a << " - " << b;
    EXPECT_TRUE(well_formed(d)) << a << " - " << b;
  }
}

TEST(Expansion, sum_scale_and_product_are_exact_and_well_formed) {
  Rng rng(32);
  for (int i = 0; i < 5000; ++i) {
    const int lo = uniform_int(rng, -300, 0), hi = lo + uniform_int(rng, 0, 300);
    const auto e = random_expansion(rng, lo, hi), f = random_expansion(rng, lo, hi);
    const Dyadic ve = value_of(e), vf = value_of(f);
    EXPECT_TRUE(well_formed(e)) << "input " << i;

    const auto s = ex::sum(e, f);
    EXPECT_EQ((value_of(s) - (ve + vf)).sign(), 0) << "sum " << i;
    EXPECT_TRUE(well_formed(s)) << "sum " << i;
    EXPECT_EQ(s.sign(), (ve + vf).sign()) << "sum sign " << i;

    const auto dd = ex::difference(e, e);
    EXPECT_EQ(dd.n, 1) << "e - e " << i;
    EXPECT_EQ(dd.sign(), 0) << "e - e " << i;

    const double b = random_double(rng, lo, hi);
    const auto sc = ex::scale(e, b);
    EXPECT_EQ((value_of(sc) - ve * Dyadic(b)).sign(), 0) << "scale " << i;
    EXPECT_TRUE(well_formed(sc)) << "scale " << i;

    const auto pr = ex::product(e, f);
    EXPECT_EQ((value_of(pr) - ve * vf).sign(), 0) << "product " << i;
    EXPECT_TRUE(well_formed(pr)) << "product " << i;
    EXPECT_EQ(pr.sign(), (ve * vf).sign()) << "product sign " << i;
  }
}

}  // namespace
}  // namespace acute::test
