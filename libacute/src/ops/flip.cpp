#include <acute/ops/flip.h>

#include <acute/predicates/predicates.h>

namespace acute {

using predicates::orient2d;

const char* to_string(OpVerdict verdict) {
  switch (verdict) {
    case OpVerdict::Ok: return "ok";
    case OpVerdict::Boundary: return "boundary";
    case OpVerdict::Constrained: return "constrained";
    case OpVerdict::InputVertex: return "input vertex";
    case OpVerdict::Topology: return "topology";
    case OpVerdict::WouldInvert: return "would invert";
    case OpVerdict::OffSegment: return "off segment";
  }
  return "?";
}

OpVerdict can_flip(const Mesh& mesh, EdgeHandle eh) {
  if (mesh.is_boundary(eh)) return OpVerdict::Boundary;
  if (is_constrained(mesh, eh)) return OpVerdict::Constrained;
  if (!mesh.is_flip_ok(eh)) return OpVerdict::Topology;
  const auto h0 = mesh.halfedge_handle(eh, 0), h1 = mesh.halfedge_handle(eh, 1);
  const Point2 v0 = point2(mesh, mesh.from_vertex_handle(h0)), v1 = point2(mesh, mesh.to_vertex_handle(h0));
  const Point2 vl = point2(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h0)));
  const Point2 vr = point2(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h1)));
  if (orient2d(vl, v0, vr) != Sign::Positive || orient2d(vr, v1, vl) != Sign::Positive) return OpVerdict::WouldInvert;
  return OpVerdict::Ok;
}

void flip(Mesh& mesh, EdgeHandle eh) { mesh.flip(eh); }

bool is_locally_delaunay(const Mesh& mesh, EdgeHandle eh) {
  if (mesh.is_boundary(eh) || is_constrained(mesh, eh)) return true;
  const auto h0 = mesh.halfedge_handle(eh, 0), h1 = mesh.halfedge_handle(eh, 1);
  const Point2 v0 = point2(mesh, mesh.from_vertex_handle(h0)), v1 = point2(mesh, mesh.to_vertex_handle(h0));
  const Point2 vl = point2(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h0)));
  const Point2 vr = point2(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h1)));
  return predicates::incircle(v0, v1, vl, vr) != Sign::Positive;
}

}  // namespace acute
