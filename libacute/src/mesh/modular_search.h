// Private to the mesh layer: the first term of an arithmetic progression modulo m that falls in
// an interval. The segment snap (segments.cpp) uses it to find, among the columns of doubles near
// a line, the ones whose lattice point lies closest to the line without scanning them.
#pragma once

#include <cstdint>

namespace acute::detail {

/// The least x >= 0 with (a x + b) mod m in [lo, hi], for 0 <= a, b < m < 2^62 and
/// 0 <= lo <= hi < m; -1 when there is none. Euclid's steps: where a x first reaches lo without
/// wrapping it is ceil(lo / a) unless that overshoots hi, and then the wraps y it needs are the
/// same question modulo a (a multiple of a in [lo + m y, hi + m y]), so O(log m) rounds.
inline std::int64_t first_hit(std::int64_t a, std::int64_t b, std::int64_t m, std::int64_t lo, std::int64_t hi) {
  if (lo <= b && b <= hi) return 0;
  if (a == 0) return -1;
  // (a x) mod m in [l, r]: the interval moved by -b, which does not wrap (it misses 0: b is outside).
  const std::int64_t l = ((lo - b) % m + m) % m, r = ((hi - b) % m + m) % m;
  const std::int64_t x = (l + a - 1) / a;
  if (a * x <= r) return x;
  // No multiple of a in [l, r], so r - l < a: a multiple lies in [l + m y, r + m y] exactly when
  // (m y + r) mod a is in [0, r - l].
  const std::int64_t y = first_hit(m % a, r % a, a, 0, r - l);
  if (y < 0) return -1;
  // (m y needs 128 bits; the quotient, the answer, is below m.)
  __extension__ typedef __int128 wide;
  return static_cast<std::int64_t>((static_cast<wide>(m) * y + l + a - 1) / a);
}

}  // namespace acute::detail
