#include <acute/ops/relocate.h>

#include <acute/predicates/predicates.h>

namespace acute {

OpVerdict can_relocate(const Mesh& mesh, VertexHandle vh, const Point2& p) {
  const auto& data = mesh.data(vh);
  if (data.kind == VertexKind::Input) return OpVerdict::InputVertex;
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return OpVerdict::WouldInvert;
  if (data.kind == VertexKind::OnSegment) {
    // p must stay strictly between the two neighbours along the segment.
    for (auto heh : mesh.voh_range(vh)) {
      if (mesh.data(mesh.edge_handle(heh)).segment != data.segment) continue;
      const Point2 w = point2(mesh, mesh.to_vertex_handle(heh));
      const Point2 here = point2(mesh, vh);
      if ((p - w).dot(here - w) <= 0) return OpVerdict::OffSegment;
    }
  }
  for (auto heh : mesh.voh_range(vh)) {
    if (mesh.is_boundary(heh)) continue;
    const Point2 b = point2(mesh, mesh.to_vertex_handle(heh));
    const Point2 c = point2(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(heh)));
    if (predicates::orient2d(p, b, c) != Sign::Positive) return OpVerdict::WouldInvert;
  }
  return OpVerdict::Ok;
}

void relocate(Mesh& mesh, VertexHandle vh, const Point2& p) { set_point2(mesh, vh, p); }

}  // namespace acute
