// Layer: predicates. incircle: floating-point filter, then exact expansion evaluation.
#include <acute/predicates/predicates.h>

#include <cmath>

#include "predicates/expansion.h"
#include "predicates/filter.h"

namespace acute::predicates {

namespace detail {

double incircle_naive(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y();
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady);
}

namespace {

using Diff = Expansion<2>;

// lift(p - d) * det[q - d, r - d], exactly.
Expansion<512> lifted_minor(const Diff& px, const Diff& py, const Diff& qx, const Diff& qy, const Diff& rx,
                            const Diff& ry) {
  const auto lift = sum(product(px, px), product(py, py));
  const auto minor = difference(product(qx, ry), product(rx, qy));
  return product(lift, minor);
}

}  // namespace

// Exact: differences are expansions of <= 2 components (one when exact, e.g. on grids), so the
// cost adapts to the input. Worst case 1536 components, all on the stack.
[[gnu::noinline]] Sign incircle_exact(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const Diff adx = diff(a.x(), d.x()), ady = diff(a.y(), d.y());
  const Diff bdx = diff(b.x(), d.x()), bdy = diff(b.y(), d.y());
  const Diff cdx = diff(c.x(), d.x()), cdy = diff(c.y(), d.y());
  const auto ta = lifted_minor(adx, ady, bdx, bdy, cdx, cdy);
  const auto tb = lifted_minor(bdx, bdy, cdx, cdy, adx, ady);
  const auto tc = lifted_minor(cdx, cdy, adx, ady, bdx, bdy);
  return static_cast<Sign>(sum(sum(ta, tb), tc).sign());
}

}  // namespace detail

Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  // perm = sum of |monomials| <= alift*blift + alift*clift + blift*clift, because
  // |bdx*cdy| + |cdx*bdy| <= (blift + clift) / 2 (AM-GM), and so on cyclically. Cheaper than the
  // exact permanent (no absolute values, 2 products instead of 3) and only slightly looser.
  const double perm = alift * (blift + clift) + blift * clift;
  const double bound = detail::kIncircleBound * perm;
  // Branch-free sign when certified: the only branch (to the exact stage) is almost never taken,
  // so it predicts well even when the signs themselves are random.
  if (std::fabs(det) > bound) return static_cast<Sign>(1 - 2 * static_cast<int>(std::signbit(det)));
  return detail::incircle_exact(a, b, c, d);
}

}  // namespace acute::predicates
