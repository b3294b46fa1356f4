#include "mesh/modular_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace acute {
namespace {

// Every progression and interval for moduli up to 23 against brute force over two periods.
TEST(FirstHit, agrees_with_brute_force_for_every_small_case) {
  for (std::int64_t m = 1; m <= 23; ++m)
    for (std::int64_t a = 0; a < m; ++a)
      for (std::int64_t b = 0; b < m; ++b)
        for (std::int64_t lo = 0; lo < m; ++lo)
          for (std::int64_t hi = lo; hi < m; ++hi) {
            std::int64_t expected = -1;
            for (std::int64_t x = 0; x < 2 * m && expected < 0; ++x)
              if (const std::int64_t v = (a * x + b) % m; lo <= v && v <= hi) expected = x;
            ASSERT_EQ(detail::first_hit(a, b, m, lo, hi), expected) << "a " << a << " b " << b << " m " << m << " [" << lo << ", " << hi << "]";
          }
}

// Large moduli (the segment snap's, up to 2^52 columns): the answer hits the interval, and no
// smaller x does among the first million.
TEST(FirstHit, large_moduli_hit_the_interval_first) {
  std::uint64_t state = 99;
  auto next = [&](std::int64_t below) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<std::int64_t>((state >> 11) % static_cast<std::uint64_t>(below));
  };
  __extension__ typedef __int128 wide;
  for (int trial = 0; trial < 200; ++trial) {
    const std::int64_t m = (std::int64_t{1} << 52) - next(std::int64_t{1} << 40);
    const std::int64_t a = next(m), b = next(m), lo = next(m), hi = lo + next(std::min<std::int64_t>(m - lo, std::int64_t{1} << 36));
    const std::int64_t x = detail::first_hit(a, b, m, lo, hi);
    // The progression takes exactly the values congruent to b modulo gcd(a, m).
    const std::int64_t g = std::gcd(a, m), first_in = lo + (((b - lo) % g) + g) % g;
    ASSERT_EQ(x >= 0, first_in <= hi) << "trial " << trial;
    if (x < 0) continue;
    const auto value = static_cast<std::int64_t>((static_cast<wide>(a) * x + b) % m);
    EXPECT_TRUE(lo <= value && value <= hi) << "trial " << trial;
    for (std::int64_t y = 0; y < std::min<std::int64_t>(x, 1000000); ++y) {
      const auto v = static_cast<std::int64_t>((static_cast<wide>(a) * y + b) % m);
      ASSERT_FALSE(lo <= v && v <= hi) << "trial " << trial << ": " << y << " hits before " << x;
    }
  }
}

}  // namespace
}  // namespace acute
