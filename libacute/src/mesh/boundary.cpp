// Layer: mesh. Pinch vertices: geometric order of their fans, simple boundary loops through them.
#include <acute/mesh/boundary.h>

#include <acute/predicates/predicates.h>

#include <algorithm>

namespace acute {

namespace {

/// Counter-clockwise order of the directions from c to p and to q, starting at the +x axis (exact).
bool before_ccw(const Point2& c, const Point2& p, const Point2& q) {
  auto upper = [&](const Point2& r) { return r.y() > c.y() || (r.y() == c.y() && r.x() > c.x()); };
  const bool up = upper(p), uq = upper(q);
  if (up != uq) return up;
  return predicates::orient2d(c, p, q) == Sign::Positive;
}

}  // namespace

bool is_pinch_vertex(const Mesh& mesh, VertexHandle vh) {
  int gaps = 0;
  for (auto heh : mesh.voh_range(vh))
    if (mesh.is_boundary(heh) && ++gaps > 1) return true;
  return false;
}

std::size_t order_pinch_vertices(Mesh& mesh) {
  std::size_t n = 0;
  struct Link {
    HalfedgeHandle heh;
    Point2 towards;
    bool incoming;
  };
  std::vector<Link> links;
  for (auto vh : mesh.vertices()) {
    if (!mesh.is_boundary(vh) || !is_pinch_vertex(mesh, vh)) continue;
    ++n;
    links.clear();
    for (auto heh : mesh.voh_range(vh)) {
      if (mesh.is_boundary(heh)) links.push_back({heh, point2(mesh, mesh.to_vertex_handle(heh)), false});
      const auto in = mesh.opposite_halfedge_handle(heh);
      if (mesh.is_boundary(in)) links.push_back({in, point2(mesh, mesh.to_vertex_handle(heh)), true});
    }
    const Point2 c = point2(mesh, vh);
    std::sort(links.begin(), links.end(), [&](const Link& a, const Link& b) { return before_ccw(c, a.towards, b.towards); });
    // Boundary halfedges have the region on their right: counter-clockwise around the vertex an
    // outgoing one opens a gap and the next incoming one closes it. Anything else (overlapping
    // fans or edges) is left for the validation to report.
    const std::size_t k = links.size();
    std::size_t first_out = k;
    for (std::size_t i = 0; i < k && first_out == k; ++i)
      if (!links[i].incoming) first_out = i;
    bool alternates = k % 2 == 0 && first_out < k;
    for (std::size_t i = 0; alternates && i < k; ++i)
      alternates = links[(first_out + i) % k].incoming == (i % 2 == 1);
    if (!alternates) continue;
    for (std::size_t i = 0; i < k; i += 2)
      mesh.set_next_halfedge_handle(links[(first_out + i + 1) % k].heh, links[(first_out + i) % k].heh);
  }
  return n;
}

std::vector<std::vector<VertexHandle>> simple_boundary_loops(const Mesh& mesh) {
  std::vector<std::vector<VertexHandle>> loops;
  std::vector<char> seen(mesh.n_halfedges(), 0);
  std::vector<int> position(mesh.n_vertices(), -1);  // in the walk being split
  std::vector<VertexHandle> walk;
  auto cut = [&](std::size_t from) {  // walk[from..] closes a loop
    loops.emplace_back(walk.begin() + static_cast<std::ptrdiff_t>(from), walk.end());
    for (std::size_t i = from; i < walk.size(); ++i) position[walk[i].idx()] = -1;
    walk.resize(from);
  };
  for (auto start : mesh.halfedges()) {
    if (!mesh.is_boundary(start) || seen[start.idx()] || mesh.status(start).deleted()) continue;
    auto heh = start;
    do {
      seen[heh.idx()] = 1;
      const VertexHandle v = mesh.from_vertex_handle(heh);
      if (position[v.idx()] >= 0) cut(static_cast<std::size_t>(position[v.idx()]));
      position[v.idx()] = static_cast<int>(walk.size());
      walk.push_back(v);
      heh = mesh.next_halfedge_handle(heh);
    } while (heh != start && !seen[heh.idx()]);
    if (!walk.empty()) cut(0);
  }
  return loops;
}

}  // namespace acute
