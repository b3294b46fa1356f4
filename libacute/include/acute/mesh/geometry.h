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

}  // namespace acute
