// TEMPORARY naive stub, replaced by the adaptive exact implementation.
#include <acute/predicates/predicates.h>
namespace acute::predicates {
namespace detail {
double orient2d_naive(const Point2& a, const Point2& b, const Point2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}
}  // namespace detail
Sign orient2d(const Point2& a, const Point2& b, const Point2& c) { return sign_of(detail::orient2d_naive(a, b, c)); }
}  // namespace acute::predicates
