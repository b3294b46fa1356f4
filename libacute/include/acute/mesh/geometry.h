// Layer: mesh. Floating-point constructions (circumcentre, off-centre, angles) used to choose
// where to put points. Constructions only: no topological decision is taken from them.
#pragma once

#include <acute/mesh/mesh.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace acute {

/// Circumcentre of triangle abc (non-degenerate), computed relative to a for accuracy.
Point2 circumcenter(const Point2& a, const Point2& b, const Point2& c);

/// Cosines of the angles of abc at a, b, c.
std::array<double, 3> angle_cosines(const Point2& a, const Point2& b, const Point2& c);

/// The three corners of face fh, counter-clockwise, and their positions.
std::array<VertexHandle, 3> face_vertices(const Mesh& mesh, FaceHandle fh);
std::array<Point2, 3> face_points(const Mesh& mesh, FaceHandle fh);

/// Twice the signed area of abc (floating point; for measures, not decisions).
inline double signed_area2(const Point2& a, const Point2& b, const Point2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/// The point of segment ab nearest to p (a when the segment is a point).
inline Point2 nearest_on_segment(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return a + t * d;
}

/// Squared distance from p to segment ab, and the distance.
inline double distance2_to_segment(const Point2& p, const Point2& a, const Point2& b) {
  return (p - nearest_on_segment(p, a, b)).squaredNorm();
}
inline double distance_to_segment(const Point2& p, const Point2& a, const Point2& b) {
  return std::sqrt(distance2_to_segment(p, a, b));
}

/// Angle (degrees) at a between b and c to about 1e-6 degrees, at a fraction of atan2's cost: for
/// comparing and choosing, never for a bound verdict (angles_deg of the repair rounds as the
/// referee does). atan on [0, 1] by Abramowitz & Stegun 4.4.49 (|error| <= 2e-8 rad), folded.
inline double approx_angle_deg(const Point2& a, const Point2& b, const Point2& c) {
  constexpr double kDeg = 57.29577951308232;
  constexpr double kHalfPi = 1.5707963267948966, kPi = 3.141592653589793;
  const Point2 u = b - a, v = c - a;
  const double y = std::abs(u.x() * v.y() - u.y() * v.x()), x = u.dot(v), ax = std::abs(x);
  if (!(y > 0) && !(ax > 0)) return 0;
  const bool steep = y > ax;
  const double t = steep ? ax / y : y / ax, t2 = t * t;
  double r = t * (1 + t2 * (-0.3333314528 + t2 * (0.1999355085 + t2 * (-0.1420889944 + t2 * (0.1065626393 +
                    t2 * (-0.0752896400 + t2 * (0.0429096138 + t2 * (-0.0161657367 + t2 * 0.0028662257))))))));
  if (steep) r = kHalfPi - r;
  if (x < 0) r = kPi - r;
  return r * kDeg;
}

}  // namespace acute
