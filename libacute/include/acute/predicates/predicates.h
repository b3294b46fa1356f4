// Layer: predicates. Exact geometric predicates on doubles (floating-point filter + adaptive
// exact expansion arithmetic). Every topological decision in libacute goes through these.
// Inputs must be finite; exactness holds for |coordinates| in [2^-142, 2^201] or 0
// (see validate_coordinate).
#pragma once

#include <acute/core/types.h>

namespace acute::predicates {

/// Sign of det[b-a, c-a]: Positive when a, b, c turn counter-clockwise, Zero when collinear.
Sign orient2d(const Point2& a, const Point2& b, const Point2& c);

/// det[b-a, c-a] computed exactly and rounded once (relative error ~1e-16): a measure, e.g. of how
/// far a rounded point lies from a line, never a topological decision (use orient2d for those).
double orient2d_value(const Point2& a, const Point2& b, const Point2& c);

/// det[b-a, c-a] in doubles, with `error` set to a bound on |value - exact| (the orient2d filter's):
/// lets a measure compared with a threshold skip orient2d_value when the bound already decides.
double orient2d_estimate(const Point2& a, const Point2& b, const Point2& c, double& error);

/// Positive when d lies strictly inside the circle through a, b, c (given counter-clockwise),
/// Zero when cocircular, Negative outside. For clockwise a, b, c the sign is reversed.
Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

/// Exact sign of the dot product (p - apex) . (q - apex): classifies the angle p-apex-q.
AngleKind angle_kind(const Point2& apex, const Point2& p, const Point2& q);

/// Where a point lies relative to a closed segment ab (a != b).
enum class SegmentLocation { Outside, OnEndpoint, OnInterior };

/// Exact: is p on the closed segment ab, and where.
SegmentLocation locate_on_segment(const Point2& p, const Point2& a, const Point2& b);

/// How two closed segments ab and cd meet.
enum class SegmentIntersection {
  None,        ///< disjoint
  Proper,      ///< cross at a single point interior to both
  Touching,    ///< meet at a single point that is an endpoint of at least one of them
  Overlapping  ///< collinear with a common part of positive length
};

/// Exact classification of the intersection of closed segments ab and cd.
SegmentIntersection intersect_segments(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

/// Side of the circle with diameter ab for p (Thales): Positive strictly inside (angle apb obtuse),
/// Zero on it, Negative outside. Equivalent to -sign((a-p).(b-p)).
Sign in_diametral_circle(const Point2& a, const Point2& b, const Point2& p);

/// True when x is finite and 0 or of magnitude in [2^-142, 2^201], where the expansions are exact.
bool validate_coordinate(double x);

namespace detail {
/// The naive double determinants, for benchmarks and tests only.
double orient2d_naive(const Point2& a, const Point2& b, const Point2& c);
double incircle_naive(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

/// The exact stages alone (no filter), so tests can exercise expansion arithmetic on any input.
Sign orient2d_exact(const Point2& a, const Point2& b, const Point2& c);
Sign incircle_exact(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

/// Exact sign of (p - apex) . (q - apex): filtered, and the exact stage alone.
Sign dot_sign(const Point2& apex, const Point2& p, const Point2& q);
Sign dot_sign_exact(const Point2& apex, const Point2& p, const Point2& q);
}  // namespace detail

}  // namespace acute::predicates
