// The oracle checks everything else, so check the oracle first against native 128-bit integers.
#include <gtest/gtest.h>

#include <cstdint>

#include "predicates/test_inputs.h"
#include "support/exact_rational.h"

namespace acute::test {
namespace {

__extension__ typedef __int128 Int128;

int sign128(Int128 v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

TEST(ExactOracle, big_integer_arithmetic_matches_int128) {
  Rng rng(7);
  for (int i = 0; i < 20000; ++i) {
    // Integers below 2^53 are exact doubles, and Dyadic(x) holds them exactly.
    const auto draw = [&]() { return static_cast<std::int64_t>(uniform(rng, -9.0e15, 9.0e15)); };
    const std::int64_t a = draw(), b = draw(), c = draw(), d = draw();
    const Dyadic da(static_cast<double>(a)), db(static_cast<double>(b));
    const Dyadic dc(static_cast<double>(c)), dd(static_cast<double>(d));
    const Int128 ab = Int128{a} * b, cd = Int128{c} * d;
    EXPECT_EQ((da * db - dc * dd).sign(), sign128(ab - cd)) << a << " " << b << " " << c << " " << d;
    EXPECT_EQ((da * db + dc * dd).sign(), sign128(ab + cd)) << a << " " << b << " " << c << " " << d;
    EXPECT_EQ((da - db).sign(), sign128(Int128{a} - b)) << a << " " << b;
  }
}

TEST(ExactOracle, dyadic_sees_differences_below_double_precision) {
  // 1 + 2^-80 - 1 is not zero exactly, although it rounds to zero in doubles.
  const Dyadic one(1.0), tiny(std::ldexp(1.0, -80));
  EXPECT_EQ((one + tiny - one).sign(), 1) << "1 + 2^-80 - 1";
  EXPECT_EQ((one - (one + tiny)).sign(), -1) << "1 - (1 + 2^-80)";
  const Dyadic huge(std::ldexp(1.0, 201)), small(std::ldexp(1.0, -142));
  EXPECT_EQ((huge * huge * huge * huge + small - huge * huge * huge * huge).sign(), 1) << "2^804 + 2^-142";
  EXPECT_EQ(Dyadic(std::ldexp(3.0, -1074)).sign(), 1) << "denormal";
  EXPECT_EQ(Dyadic(-0.0).sign(), 0) << "negative zero";
}

}  // namespace
}  // namespace acute::test
