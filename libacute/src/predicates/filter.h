// Layer: predicates (private). Forward error bounds of the floating-point filters.
//
// Each filter evaluates the determinant in doubles from the rounded coordinate differences and
// accepts the sign when |det| exceeds C * perm, where perm is the same polynomial with every
// monomial replaced by its absolute value, evaluated in doubles. With u = 2^-53 and no
// under/overflow (guaranteed by the coordinate range), a monomial computed through k roundings
// carries a relative error of at most gamma_k = k u / (1 - k u), so |det_fp - det| <= gamma_k *
// perm_exact. Computing perm itself from rounded differences through r further roundings gives
// perm_exact <= perm_fp / (1 - u)^(d + r), d = degree; the final product C * perm_fp rounds once
// more. Hence C >= gamma_k / (1 - u)^(d + r + 1) suffices:
//   orient2d and dot products: k = 4 (2 differences, 1 product, 1 sum), d = 2, r = 2:
//     gamma_4 / (1 - u)^5 = 4u + 36u^2 + O(u^3)            ->  C = (4 + 64u) u
//   incircle: k = 11 (2+1+1 for the lift, 2+1+1 for the 2x2 minor, 1 product, 2 final sums),
//     d = 4. perm is replaced by its upper bound P = alift*blift + alift*clift + blift*clift
//     (AM-GM, see incircle.cpp). A lift in exact differences is <= its double value / (1 - u)^4
//     (2 roundings of the differences, 2 of the evaluation), so P <= P_fp / (1 - u)^(8 + 3),
//     3 for evaluating P; with the final product:
//     gamma_11 / (1 - u)^12 = 11u + 253u^2 + O(u^3)           ->  C = (11 + 512u) u
#pragma once

namespace acute::predicates::detail {

inline constexpr double kUnitRoundoff = 1.0 / 9007199254740992.0;  // 2^-53
inline constexpr double kOrient2dBound = (4.0 + 64.0 * kUnitRoundoff) * kUnitRoundoff;
inline constexpr double kDot2dBound = kOrient2dBound;
inline constexpr double kIncircleBound = (11.0 + 512.0 * kUnitRoundoff) * kUnitRoundoff;

}  // namespace acute::predicates::detail
