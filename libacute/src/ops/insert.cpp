#include <acute/ops/insert.h>

#include <acute/core/errors.h>
#include <acute/mesh/segments.h>
#include <acute/ops/delaunay_flips.h>
#include <acute/predicates/predicates.h>

#include <cstdint>

namespace acute {

using predicates::orient2d;

Location locate(const Mesh& mesh, const Point2& p, FaceHandle start) {
  Location loc;
  FaceHandle fh = start;
  std::uint32_t rng = 0x9e3779b9u;  // rotates the edge order so the walk cannot cycle
  const std::size_t max_steps = 4 * mesh.n_faces() + 64;
  for (std::size_t step = 0; step < max_steps; ++step) {
    HalfedgeHandle h[3];
    h[0] = mesh.halfedge_handle(fh);
    h[1] = mesh.next_halfedge_handle(h[0]);
    h[2] = mesh.next_halfedge_handle(h[1]);
    Sign o[3];
    for (int i = 0; i < 3; ++i)
      o[i] = orient2d(point2(mesh, mesh.from_vertex_handle(h[i])), point2(mesh, mesh.to_vertex_handle(h[i])), p);
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    const int first = static_cast<int>(rng % 3u);
    int blocked = -1, next = -1;
    for (int k = 0; k < 3; ++k) {
      const int i = (first + k) % 3;
      if (o[i] != Sign::Negative) continue;
      const EdgeHandle eh = mesh.edge_handle(h[i]);
      if (mesh.is_boundary(eh) || is_constrained(mesh, eh)) {
        if (blocked < 0) blocked = i;
      } else {
        next = i;
        break;
      }
    }
    if (next >= 0) {
      fh = mesh.face_handle(mesh.opposite_halfedge_handle(h[next]));
      continue;
    }
    if (blocked >= 0) {
      loc.kind = LocationKind::Blocked;
      loc.face = fh;
      loc.edge = mesh.edge_handle(h[blocked]);
      return loc;
    }
    loc.face = fh;
    int zeros = 0, zi = -1;
    for (int i = 0; i < 3; ++i)
      if (o[i] == Sign::Zero) ++zeros, zi = (zi < 0 ? i : zi);
    if (zeros == 0) {
      loc.kind = LocationKind::InFace;
    } else if (zeros == 1) {
      loc.kind = LocationKind::OnEdge;
      loc.edge = mesh.edge_handle(h[zi]);
    } else {
      // On two edge lines: the vertex they share.
      int zj = -1;
      for (int i = 0; i < 3; ++i)
        if (o[i] == Sign::Zero && i != zi) zj = i;
      loc.kind = LocationKind::OnVertex;
      loc.vertex = (zj == (zi + 1) % 3) ? mesh.to_vertex_handle(h[zi]) : mesh.from_vertex_handle(h[zi]);
    }
    return loc;
  }
  throw InternalError("locate: walk did not terminate (invalid mesh?)");
}

namespace {

/// Splits eh with the new vertex vh (already positioned), copying constraint data to both halves.
void split_with_vertex(Mesh& mesh, EdgeHandle eh, VertexHandle vh) {
  const auto h0 = mesh.halfedge_handle(eh, 0);
  const VertexHandle v0 = mesh.from_vertex_handle(h0), v1 = mesh.to_vertex_handle(h0);
  const auto edge_data = mesh.data(eh);
  mesh.split(eh, vh);
  if (edge_data.segment >= 0) {
    auto& vd = mesh.data(vh);
    vd.kind = VertexKind::OnSegment;
    vd.segment = edge_data.segment;
    vd.marker = edge_data.marker;
  }
  for (auto heh : mesh.voh_range(vh)) {
    const VertexHandle w = mesh.to_vertex_handle(heh);
    auto& ed = mesh.data(mesh.edge_handle(heh));
    ed = (w == v0 || w == v1) ? edge_data : std::decay_t<decltype(ed)>{};
  }
}

/// A point on a segment piece must lie strictly between its ends in each coordinate the segment
/// varies in (see strictly_between_along) and close enough to the segment's exact line to be read
/// back as one of its points (close_enough_to_line); true for edges that are not on a segment.
bool splits_in_order(const Mesh& mesh, EdgeHandle eh, const Point2& p) {
  const int seg = mesh.data(eh).segment;
  if (seg < 0 || static_cast<std::size_t>(seg) >= segment_table(mesh).size()) return true;
  const auto h0 = mesh.halfedge_handle(eh, 0);
  const auto& ends = segment_endpoints(mesh, seg);
  return strictly_between_along(ends, point2(mesh, mesh.from_vertex_handle(h0)), p, point2(mesh, mesh.to_vertex_handle(h0))) &&
         close_enough_to_line(ends, p);
}

VertexHandle restore_around(Mesh& mesh, VertexHandle vh) {
  std::vector<EdgeHandle> queue;
  push_star_edges(mesh, vh, queue);
  restore_delaunay(mesh, queue);
  return vh;
}

}  // namespace

VertexHandle insert_point_from(Mesh& mesh, const Point2& p, VertexHandle from) {
  for (auto fh : mesh.vf_range(from)) {
    const VertexHandle vh = insert_point(mesh, p, fh);
    if (vh.is_valid()) return vh;  // (the mesh changed: the circulator is not used again)
  }
  return VertexHandle();
}

VertexHandle insert_point_after(Mesh& mesh, const Point2& p, VertexHandle previous, VertexHandle anchor) {
  if (previous.is_valid() && !mesh.status(previous).deleted()) {
    const VertexHandle vh = insert_point_from(mesh, p, previous);
    if (vh.is_valid()) return vh;
  }
  return insert_point_from(mesh, p, anchor);
}

VertexHandle insert_point(Mesh& mesh, const Point2& p, FaceHandle start, EdgeHandle* blocked_edge) {
  const Location loc = locate(mesh, p, start);
  switch (loc.kind) {
    case LocationKind::OnVertex: return loc.vertex;
    case LocationKind::Blocked:
      if (blocked_edge) *blocked_edge = loc.edge;
      return VertexHandle();
    case LocationKind::InFace: {
      const VertexHandle vh = mesh.add_vertex(Mesh::Point(p.x(), p.y(), 0.0));
      mesh.split(loc.face, vh);
      for (auto heh : mesh.voh_range(vh)) mesh.data(mesh.edge_handle(heh)) = {};
      return restore_around(mesh, vh);
    }
    case LocationKind::OnEdge: {
      // An unconstrained boundary edge is a frozen border (e.g. of a region copy): never split it.
      if (mesh.data(loc.edge).frozen || (mesh.is_boundary(loc.edge) && !is_constrained(mesh, loc.edge))) {
        if (blocked_edge) *blocked_edge = loc.edge;
        return VertexHandle();
      }
      if (!splits_in_order(mesh, loc.edge, p)) {
        if (blocked_edge) *blocked_edge = loc.edge;
        return VertexHandle();
      }
      const VertexHandle vh = mesh.add_vertex(Mesh::Point(p.x(), p.y(), 0.0));
      split_with_vertex(mesh, loc.edge, vh);
      return restore_around(mesh, vh);
    }
  }
  return VertexHandle();
}

VertexHandle split_edge(Mesh& mesh, EdgeHandle eh, const Point2& p_in) {
  if (mesh.data(eh).frozen) return VertexHandle();
  Point2 p = p_in;
  const int seg = mesh.data(eh).segment;
  if (seg >= 0 && static_cast<std::size_t>(seg) < segment_table(mesh).size()) {
    const auto h0 = mesh.halfedge_handle(eh, 0);
    const Point2 lo = point2(mesh, mesh.from_vertex_handle(h0)), hi = point2(mesh, mesh.to_vertex_handle(h0));
    const auto& ends = segment_endpoints(mesh, seg);
    p = project_on_line(ends, p_in, &lo, &hi);
    // No double strictly between the piece's ends along the segment and near enough its line: the
    // piece is as short as rounding allows, another point would not read back as the segment's.
    if (!splits_in_order(mesh, eh, p)) return VertexHandle();
  }
  // The new triangles (v0, p, x) and (p, v1, x) for each side x must be counter-clockwise.
  for (int side = 0; side < 2; ++side) {
    const auto heh = mesh.halfedge_handle(eh, side);
    if (mesh.is_boundary(heh)) continue;
    const Point2 a = point2(mesh, mesh.from_vertex_handle(heh)), b = point2(mesh, mesh.to_vertex_handle(heh));
    const Point2 x = point2(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(heh)));
    if (orient2d(a, p, x) != Sign::Positive || orient2d(p, b, x) != Sign::Positive) return VertexHandle();
  }
  const VertexHandle vh = mesh.add_vertex(Mesh::Point(p.x(), p.y(), 0.0));
  split_with_vertex(mesh, eh, vh);
  return restore_around(mesh, vh);
}

}  // namespace acute
