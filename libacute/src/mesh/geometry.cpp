#include <acute/mesh/geometry.h>

#include <cmath>

namespace acute {

Point2 circumcenter(const Point2& a, const Point2& b, const Point2& c) {
  const Point2 ba = b - a, ca = c - a;
  const double d = 2.0 * (ba.x() * ca.y() - ba.y() * ca.x());
  const double b2 = ba.squaredNorm(), c2 = ca.squaredNorm();
  return a + Point2((ca.y() * b2 - ba.y() * c2) / d, (ba.x() * c2 - ca.x() * b2) / d);
}

std::array<double, 3> angle_cosines(const Point2& a, const Point2& b, const Point2& c) {
  const Point2 ab = b - a, bc = c - b, ca = a - c;
  const double lab = ab.norm(), lbc = bc.norm(), lca = ca.norm();
  return {-(ca.dot(ab)) / (lca * lab), -(ab.dot(bc)) / (lab * lbc), -(bc.dot(ca)) / (lbc * lca)};
}

std::array<VertexHandle, 3> face_vertices(const Mesh& mesh, FaceHandle fh) {
  auto h = mesh.halfedge_handle(fh);
  std::array<VertexHandle, 3> v;
  for (int i = 0; i < 3; ++i, h = mesh.next_halfedge_handle(h)) v[i] = mesh.to_vertex_handle(h);
  return v;
}

std::array<Point2, 3> face_points(const Mesh& mesh, FaceHandle fh) {
  const auto v = face_vertices(mesh, fh);
  return {point2(mesh, v[0]), point2(mesh, v[1]), point2(mesh, v[2])};
}

}  // namespace acute
