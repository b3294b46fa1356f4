// TEMPORARY naive stub, replaced by the adaptive exact implementation.
#include <acute/predicates/predicates.h>
namespace acute::predicates {
namespace detail {
double incircle_naive(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y();
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady);
}
}  // namespace detail
Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  return sign_of(detail::incircle_naive(a, b, c, d));
}
}  // namespace acute::predicates
