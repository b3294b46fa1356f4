// Layer: mesh. Floating-point constructions (circumcentre, off-centre, angles) used to choose
// where to put points. Constructions only: no topological decision is taken from them.
#pragma once

#include <acute/mesh/mesh.h>

#include <array>

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

}  // namespace acute
