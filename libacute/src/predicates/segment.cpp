// Layer: predicates. Exact tests derived from orient2d and from the exact sign of a dot product.
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <cmath>

#include "predicates/expansion.h"
#include "predicates/filter.h"

namespace acute::predicates {

namespace detail {

[[gnu::noinline]] Sign dot_sign_exact(const Point2& apex, const Point2& p, const Point2& q) {
  const Expansion<2> pax = diff(p.x(), apex.x()), pay = diff(p.y(), apex.y());
  const Expansion<2> qax = diff(q.x(), apex.x()), qay = diff(q.y(), apex.y());
  return static_cast<Sign>(sum(product(pax, qax), product(pay, qay)).sign());
}

Sign dot_sign(const Point2& apex, const Point2& p, const Point2& q) {
  const double left = (p.x() - apex.x()) * (q.x() - apex.x());
  const double right = (p.y() - apex.y()) * (q.y() - apex.y());
  const double dot = left + right;
  const double bound = kDot2dBound * (std::fabs(left) + std::fabs(right));
  if (std::fabs(dot) > bound) return static_cast<Sign>(1 - 2 * static_cast<int>(std::signbit(dot)));  // as in orient2d
  return dot_sign_exact(apex, p, q);
}

}  // namespace detail

namespace {

// On a line through distinct a and b, x (or y when the line is vertical) is a strictly monotone
// parameter, so comparing that coordinate orders collinear points exactly.
int dominant_axis(const Point2& a, const Point2& b) { return a.x() != b.x() ? 0 : 1; }

}  // namespace

AngleKind angle_kind(const Point2& apex, const Point2& p, const Point2& q) {
  switch (detail::dot_sign(apex, p, q)) {
    case Sign::Positive: return AngleKind::Acute;
    case Sign::Zero: return AngleKind::Right;
    case Sign::Negative: break;
  }
  return AngleKind::Obtuse;
}

Sign in_diametral_circle(const Point2& a, const Point2& b, const Point2& p) { return -detail::dot_sign(p, a, b); }

SegmentLocation locate_on_segment(const Point2& p, const Point2& a, const Point2& b) {
  if (p == a || p == b) return SegmentLocation::OnEndpoint;
  if (a == b || orient2d(a, b, p) != Sign::Zero) return SegmentLocation::Outside;
  const int k = dominant_axis(a, b);
  const double lo = std::min(a[k], b[k]), hi = std::max(a[k], b[k]);
  return lo < p[k] && p[k] < hi ? SegmentLocation::OnInterior : SegmentLocation::Outside;
}

SegmentIntersection intersect_segments(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  // Degenerate segments are points: they can only touch.
  if (a == b) return locate_on_segment(a, c, d) != SegmentLocation::Outside ? SegmentIntersection::Touching
                                                                            : SegmentIntersection::None;
  if (c == d) return locate_on_segment(c, a, b) != SegmentLocation::Outside ? SegmentIntersection::Touching
                                                                            : SegmentIntersection::None;
  const Sign o_c = orient2d(a, b, c), o_d = orient2d(a, b, d);
  if (o_c == Sign::Zero && o_d == Sign::Zero) {
    // All four collinear: intersect the parameter intervals exactly.
    const int k = dominant_axis(a, b);
    const double lo = std::max(std::min(a[k], b[k]), std::min(c[k], d[k]));
    const double hi = std::min(std::max(a[k], b[k]), std::max(c[k], d[k]));
    if (lo < hi) return SegmentIntersection::Overlapping;
    return lo == hi ? SegmentIntersection::Touching : SegmentIntersection::None;
  }
  if (o_c != Sign::Zero && o_c == o_d) return SegmentIntersection::None;
  const Sign o_a = orient2d(c, d, a), o_b = orient2d(c, d, b);
  if (o_a != Sign::Zero && o_a == o_b) return SegmentIntersection::None;
  // The supporting lines cross at one point which lies on both closed segments.
  if (o_a == Sign::Zero || o_b == Sign::Zero || o_c == Sign::Zero || o_d == Sign::Zero)
    return SegmentIntersection::Touching;
  return SegmentIntersection::Proper;
}

bool validate_coordinate(double x) {
  if (!std::isfinite(x)) return false;
  if (x == 0) return true;
  const double m = std::fabs(x);
  return m >= 0x1p-142 && m <= 0x1p201;
}

}  // namespace acute::predicates
