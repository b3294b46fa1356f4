// Domains with sharp corners for the repair's wedge tests, and the CVT start they are meshed from.
#pragma once

#include <acute/mesh/geometry.h>
#include <acute/mesher.h>

#include <cmath>

namespace acute::test {

inline Point2 polar(double r, double deg) {
  constexpr double kPi = 3.14159265358979323846;
  return Point2(r * std::cos(deg * kPi / 180), r * std::sin(deg * kPi / 180));
}

/// A triangle with a sharp apex at the origin (apex angle in degrees), legs of length 10.
inline Domain sharp_wedge(double apex_deg) {
  Domain d;
  d.points = {Point2(0, 0), polar(10, 0), polar(10, apex_deg)};
  d.segments = {{0, 1}, {1, 2}, {2, 0}};
  return d;
}

/// A 20 x 20 square with a wedge between two interior segments (length 8) at its centre.
inline Domain wedge_between_segments(double apex_deg) {
  Domain d;
  d.points = {Point2(-10, -10), Point2(10, -10), Point2(10, 10), Point2(-10, 10), Point2(0, 0), polar(8, 0), polar(8, apex_deg)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {4, 6}};
  return d;
}

/// The CVT start of the pipeline (no repair) at about `vertices` vertices.
inline Mesh cvt_mesh(const Domain& domain, std::size_t vertices) {
  MeshOptions options;
  options.method = Method::Cvt;
  options.target_vertices = vertices;
  return generate_mesh(domain, options).mesh;
}

/// The live vertex exactly at p, or an invalid handle.
inline VertexHandle vertex_at(const Mesh& mesh, const Point2& p) {
  for (auto vh : mesh.vertices())
    if (!mesh.status(vh).deleted() && point2(mesh, vh) == p) return vh;
  return VertexHandle();
}

}  // namespace acute::test
