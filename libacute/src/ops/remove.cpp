#include <acute/ops/remove.h>

#include <acute/core/errors.h>
#include <acute/ops/delaunay_flips.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <array>
#include <vector>

namespace acute {

using predicates::orient2d;

namespace {

/// Triangulates the simple counter-clockwise polygon `poly` by ear clipping with exact tests.
/// Returns false when no ear exists (the polygon is not simple / not counter-clockwise).
bool triangulate_polygon(const Mesh& mesh, std::vector<VertexHandle> poly, std::vector<std::array<VertexHandle, 3>>& out) {
  auto pt = [&](VertexHandle v) { return point2(mesh, v); };
  while (poly.size() > 3) {
    const std::size_t n = poly.size();
    bool clipped = false;
    for (std::size_t i = 0; i < n && !clipped; ++i) {
      const VertexHandle a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
      if (orient2d(pt(a), pt(b), pt(c)) != Sign::Positive) continue;
      bool empty = true;
      for (std::size_t j = 0; j < n && empty; ++j) {
        const VertexHandle q = poly[j];
        if (q == a || q == b || q == c) continue;
        const Point2 pq = pt(q);
        // q in the closed triangle abc blocks the ear.
        if (orient2d(pt(a), pt(b), pq) != Sign::Negative && orient2d(pt(b), pt(c), pq) != Sign::Negative &&
            orient2d(pt(c), pt(a), pq) != Sign::Negative)
          empty = false;
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) return false;
  }
  if (orient2d(pt(poly[0]), pt(poly[1]), pt(poly[2])) != Sign::Positive) return false;
  out.push_back({poly[0], poly[1], poly[2]});
  return true;
}

/// The star of vh: its neighbours in counter-clockwise order. For a boundary vertex the chain
/// starts and ends at its two boundary neighbours.
std::vector<VertexHandle> star_ring(const Mesh& mesh, VertexHandle vh) {
  std::vector<VertexHandle> ring;
  HalfedgeHandle start;
  for (auto heh : mesh.voh_range(vh))
    if (!mesh.is_boundary(heh) && mesh.is_boundary(mesh.opposite_halfedge_handle(heh))) start = heh;
  if (!start.is_valid()) start = mesh.halfedge_handle(vh);
  HalfedgeHandle h = start;
  do {
    ring.push_back(mesh.to_vertex_handle(h));
    if (mesh.is_boundary(h)) break;
    h = mesh.opposite_halfedge_handle(mesh.prev_halfedge_handle(h));
  } while (h != start);
  return ring;
}

struct RemovalPlan {
  std::vector<std::array<VertexHandle, 3>> triangles;
  VertexHandle u, w;  ///< the segment neighbours re-joined (invalid for a free vertex)
  Mesh::EdgeData segment_data;
};

bool plan_removal(const Mesh& mesh, VertexHandle vh, RemovalPlan& plan) {
  std::vector<VertexHandle> ring = star_ring(mesh, vh);
  const bool boundary = mesh.is_boundary(vh);
  {  // a vertex seen twice around vh (a pinched star) has no simple polygon to fill
    std::vector<VertexHandle> sorted = ring;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
  }
  // Constrained spokes: none (free vertex) or exactly two on the same segment.
  std::vector<std::size_t> constrained;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto heh = mesh.find_halfedge(vh, ring[i]);
    if (is_constrained(mesh, mesh.edge_handle(heh))) {
      constrained.push_back(i);
      plan.segment_data = mesh.data(mesh.edge_handle(heh));
    }
  }
  if (boundary) {
    if (constrained.size() != 2 || constrained[0] != 0 || constrained[1] != ring.size() - 1) return false;
    plan.u = ring.front();
    plan.w = ring.back();
    return ring.size() >= 3 ? triangulate_polygon(mesh, ring, plan.triangles) : false;
  }
  if (constrained.empty()) return ring.size() >= 3 && triangulate_polygon(mesh, ring, plan.triangles);
  if (constrained.size() != 2) return false;
  // Interior constraint through vh: two polygons, each closed by the re-joined segment.
  const std::size_t i = constrained[0], j = constrained[1];
  plan.u = ring[i];
  plan.w = ring[j];
  std::vector<VertexHandle> left(ring.begin() + static_cast<std::ptrdiff_t>(i), ring.begin() + static_cast<std::ptrdiff_t>(j) + 1);
  std::vector<VertexHandle> right(ring.begin() + static_cast<std::ptrdiff_t>(j), ring.end());
  right.insert(right.end(), ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(i) + 1);
  if (left.size() < 3 || right.size() < 3) return false;
  return triangulate_polygon(mesh, left, plan.triangles) && triangulate_polygon(mesh, right, plan.triangles);
}

}  // namespace

OpVerdict can_remove_vertex(const Mesh& mesh, VertexHandle vh) {
  if (is_input(mesh, vh)) return OpVerdict::InputVertex;
  if (mesh.status(vh).deleted() || mesh.is_isolated(vh)) return OpVerdict::Topology;
  RemovalPlan plan;
  return plan_removal(mesh, vh, plan) ? OpVerdict::Ok : OpVerdict::WouldInvert;
}

bool remove_vertex(Mesh& mesh, VertexHandle vh) {
  if (is_input(mesh, vh) || mesh.status(vh).deleted() || mesh.is_isolated(vh)) return false;
  RemovalPlan plan;
  if (!plan_removal(mesh, vh, plan)) return false;
  // Ring edges on the mesh boundary vanish with the star and are re-created: keep their data.
  std::vector<std::pair<std::array<VertexHandle, 2>, Mesh::EdgeData>> ring_edges;
  for (auto heh : mesh.voh_range(vh)) {
    if (mesh.is_boundary(heh)) continue;
    const auto link = mesh.next_halfedge_handle(heh);
    const EdgeHandle eh = mesh.edge_handle(link);
    if (is_constrained(mesh, eh))
      ring_edges.push_back({{mesh.from_vertex_handle(link), mesh.to_vertex_handle(link)}, mesh.data(eh)});
  }
  mesh.delete_vertex(vh, false);
  std::vector<EdgeHandle> queue;
  for (const auto& t : plan.triangles) {
    const FaceHandle fh = mesh.add_face(t[0], t[1], t[2]);
    if (!fh.is_valid()) throw InternalError("remove_vertex: re-triangulation rejected by the mesh");
    for (auto eh : mesh.fe_range(fh)) queue.push_back(eh);
  }
  for (const auto& [ends, data] : ring_edges) {
    const auto heh = mesh.find_halfedge(ends[0], ends[1]);
    if (heh.is_valid()) mesh.data(mesh.edge_handle(heh)) = data;
  }
  if (plan.u.is_valid()) {
    const auto heh = mesh.find_halfedge(plan.u, plan.w);
    if (heh.is_valid()) mesh.data(mesh.edge_handle(heh)) = plan.segment_data;
  }
  restore_delaunay(mesh, queue);
  return true;
}

bool remove_vertices(Mesh& mesh, const std::vector<VertexHandle>& vertices) {
  std::vector<VertexHandle> left = vertices, later, ring, marked;
  std::vector<char> taken(mesh.n_vertices(), 0);  // a neighbour of a vertex removed this round
  // A removal that fails may succeed once its neighbours are gone: rounds until none goes.
  for (bool progress = true; progress && !left.empty();) {
    progress = false;
    for (auto w : marked) taken[static_cast<std::size_t>(w.idx())] = 0;  // not the whole mesh per round
    marked.clear();
    later.clear();
    for (VertexHandle vh : left) {
      if (mesh.status(vh).deleted()) continue;
      if (taken[static_cast<std::size_t>(vh.idx())]) {
        later.push_back(vh);
        continue;
      }
      ring.clear();
      for (auto w : mesh.vv_range(vh)) ring.push_back(w);
      if (remove_vertex(mesh, vh)) {
        progress = true;
        for (auto w : ring) taken[static_cast<std::size_t>(w.idx())] = 1;
        marked.insert(marked.end(), ring.begin(), ring.end());
      } else {
        later.push_back(vh);
      }
    }
    std::swap(left, later);
  }
  return left.empty();
}

OpVerdict can_collapse(const Mesh& mesh, HalfedgeHandle v0v1) {
  const VertexHandle v0 = mesh.from_vertex_handle(v0v1), v1 = mesh.to_vertex_handle(v0v1);
  const auto& d0 = mesh.data(v0);
  if (d0.kind == VertexKind::Input) return OpVerdict::InputVertex;
  const int seg = mesh.data(mesh.edge_handle(v0v1)).segment;
  if (d0.kind == VertexKind::OnSegment && seg != d0.segment) return OpVerdict::OffSegment;
  if (d0.kind == VertexKind::Free && (seg >= 0 || mesh.is_boundary(v0))) return OpVerdict::Boundary;
  if (!const_cast<Mesh&>(mesh).is_collapse_ok(v0v1)) return OpVerdict::Topology;
  const Point2 p1 = point2(mesh, v1);
  for (auto heh : mesh.voh_range(v0)) {
    if (mesh.is_boundary(heh)) continue;
    const VertexHandle b = mesh.to_vertex_handle(heh), c = mesh.to_vertex_handle(mesh.next_halfedge_handle(heh));
    if (b == v1 || c == v1) continue;  // faces that vanish
    if (orient2d(p1, point2(mesh, b), point2(mesh, c)) != Sign::Positive) return OpVerdict::WouldInvert;
  }
  return OpVerdict::Ok;
}

void collapse(Mesh& mesh, HalfedgeHandle v0v1) {
  const VertexHandle v1 = mesh.to_vertex_handle(v0v1);
  // The two edges merged on each side keep the constraint if either had one.
  std::vector<std::pair<VertexHandle, Mesh::EdgeData>> keep;
  for (auto heh : {v0v1, mesh.opposite_halfedge_handle(v0v1)}) {
    if (mesh.is_boundary(heh)) continue;
    const auto n = mesh.next_halfedge_handle(heh), p = mesh.prev_halfedge_handle(heh);
    const VertexHandle apex = mesh.to_vertex_handle(n);
    const auto& dn = mesh.data(mesh.edge_handle(n));
    const auto& dp = mesh.data(mesh.edge_handle(p));
    if (dn.segment >= 0 || dp.segment >= 0) keep.emplace_back(apex, dn.segment >= 0 ? dn : dp);
  }
  mesh.collapse(v0v1);
  for (const auto& [apex, data] : keep) {
    const auto heh = mesh.find_halfedge(v1, apex);
    if (heh.is_valid()) mesh.data(mesh.edge_handle(heh)) = data;
  }
  std::vector<EdgeHandle> queue;
  push_star_edges(mesh, v1, queue);
  restore_delaunay(mesh, queue);
}

}  // namespace acute
