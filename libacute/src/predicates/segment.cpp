// TEMPORARY naive stub, replaced by the exact implementation.
#include <acute/predicates/predicates.h>
#include <algorithm>
#include <cmath>
namespace acute::predicates {
AngleKind angle_kind(const Point2& apex, const Point2& p, const Point2& q) {
  const double d = (p - apex).dot(q - apex);
  return d > 0 ? AngleKind::Acute : (d < 0 ? AngleKind::Obtuse : AngleKind::Right);
}
SegmentLocation locate_on_segment(const Point2& p, const Point2& a, const Point2& b) {
  if (p == a || p == b) return SegmentLocation::OnEndpoint;
  if (orient2d(a, b, p) != Sign::Zero) return SegmentLocation::Outside;
  const bool inside = (p - a).dot(b - a) > 0 && (p - b).dot(a - b) > 0;
  return inside ? SegmentLocation::OnInterior : SegmentLocation::Outside;
}
SegmentIntersection intersect_segments(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const Sign o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o1 == Sign::Zero && o2 == Sign::Zero) {
    // collinear
    const Point2 u = b - a;
    double t0 = 0, t1 = u.dot(u), s0 = (c - a).dot(u), s1 = (d - a).dot(u);
    if (s0 > s1) std::swap(s0, s1);
    const double lo = std::max(t0, s0), hi = std::min(t1, s1);
    if (lo < hi) return SegmentIntersection::Overlapping;
    if (lo == hi) return SegmentIntersection::Touching;
    return SegmentIntersection::None;
  }
  if (o1 == o2 || o3 == o4) return SegmentIntersection::None;
  if (o1 == Sign::Zero || o2 == Sign::Zero || o3 == Sign::Zero || o4 == Sign::Zero) return SegmentIntersection::Touching;
  return SegmentIntersection::Proper;
}
Sign in_diametral_circle(const Point2& a, const Point2& b, const Point2& p) { return -sign_of((a - p).dot(b - p)); }
bool validate_coordinate(double x) {
  if (!std::isfinite(x)) return false;
  if (x == 0) return true;
  const double ax = std::fabs(x);
  return ax >= std::ldexp(1.0, -142) && ax <= std::ldexp(1.0, 201);
}
}  // namespace acute::predicates
