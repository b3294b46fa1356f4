#include <acute/ops/relocate.h>

#include <acute/mesh/segments.h>
#include <acute/predicates/predicates.h>

#include <algorithm>

namespace acute {

bool keeps_segment_order(const Mesh& mesh, VertexHandle vh, const Point2& p) {
  const int seg = mesh.data(vh).segment;
  Point2 w[2];
  int n = 0;
  for (auto heh : mesh.voh_range(vh))
    if (mesh.data(mesh.edge_handle(heh)).segment == seg && n < 2) w[n++] = point2(mesh, mesh.to_vertex_handle(heh));
  if (n < 2) return false;
  // In the chain's order between the neighbours, equal where they agree: exact comparisons, no
  // tolerance. (The neighbours differ in every coordinate that must advance strictly, so their
  // difference gives the segment's dominant axis.)
  return in_chain_order(w[1] - w[0], w[0], p, w[1]);
}

OpVerdict can_relocate(const Mesh& mesh, VertexHandle vh, const Point2& p) {
  const auto& data = mesh.data(vh);
  if (data.kind == VertexKind::Input) return OpVerdict::InputVertex;
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return OpVerdict::WouldInvert;
  if (data.kind == VertexKind::OnSegment) {
    if (!keeps_segment_order(mesh, vh, p)) return OpVerdict::OffSegment;
    if (data.segment >= 0 && static_cast<std::size_t>(data.segment) < segment_table(mesh).size() &&
        !close_enough_to_line(segment_endpoints(mesh, data.segment), p))
      return OpVerdict::OffSegment;
  }
  for (auto heh : mesh.voh_range(vh)) {
    // A border vertex on no segment (none is expected: border edges are segments) would move the
    // domain's boundary with it.
    if (mesh.is_boundary(heh) && data.kind != VertexKind::OnSegment) return OpVerdict::Boundary;
    if (mesh.is_boundary(heh)) continue;
    const Point2 b = point2(mesh, mesh.to_vertex_handle(heh));
    const Point2 c = point2(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(heh)));
    if (predicates::orient2d(p, b, c) != Sign::Positive) return OpVerdict::WouldInvert;
  }
  return OpVerdict::Ok;
}

void relocate(Mesh& mesh, VertexHandle vh, const Point2& p) { set_point2(mesh, vh, p); }

}  // namespace acute
