// Layer: mesh. Whole-mesh helpers: boundary constraints, compaction.
#include <acute/mesh/mesh.h>

#include <unordered_set>
#include <vector>

namespace acute {

int mark_boundary_as_constrained(Mesh& mesh) {
  // Walk each boundary loop so that segment ids (and input indices) are consecutive along it.
  std::vector<char> seen(mesh.n_halfedges(), 0);
  int n_segments = 0;
  int n_inputs = 0;
  for (auto start : mesh.halfedges()) {
    if (!mesh.is_boundary(start) || seen[start.idx()]) continue;
    auto heh = start;
    do {
      seen[heh.idx()] = 1;
      auto& ed = mesh.data(mesh.edge_handle(heh));
      ed.segment = n_segments++;
      auto& vd = mesh.data(mesh.from_vertex_handle(heh));
      if (vd.kind != VertexKind::Input) {
        vd.kind = VertexKind::Input;
        vd.input_index = n_inputs++;
      }
      vd.segment = -1;
      heh = mesh.next_halfedge_handle(heh);
    } while (heh != start && !seen[heh.idx()]);
  }
  return n_segments;
}

std::vector<VertexHandle> vertices_near(const Mesh& mesh, VertexHandle centre, double radius) {
  const Point2 c = point2(mesh, centre);
  std::vector<VertexHandle> out, frontier{centre};
  std::unordered_set<int> seen{centre.idx()};
  while (!frontier.empty()) {
    const VertexHandle v = frontier.back();
    frontier.pop_back();
    for (auto w : mesh.vv_range(v)) {
      if (seen.count(w.idx()) || (point2(mesh, w) - c).norm() >= radius) continue;
      seen.insert(w.idx());
      if (is_input(mesh, w)) continue;
      out.push_back(w);
      frontier.push_back(w);
    }
  }
  return out;
}

std::vector<VertexHandle> with_rings(const Mesh& mesh, std::vector<VertexHandle> seeds, int rings, std::vector<char>& seen) {
  if (seen.size() < mesh.n_vertices()) seen.resize(mesh.n_vertices(), 0);
  for (VertexHandle vh : seeds) seen[static_cast<std::size_t>(vh.idx())] = 1;
  std::size_t begin = 0;
  for (int r = 0; r < rings; ++r) {
    const std::size_t end = seeds.size();
    for (std::size_t i = begin; i < end; ++i)
      for (auto w : mesh.vv_range(seeds[i]))
        if (!seen[static_cast<std::size_t>(w.idx())]) {
          seen[static_cast<std::size_t>(w.idx())] = 1;
          seeds.push_back(w);
        }
    begin = end;
  }
  for (VertexHandle vh : seeds) seen[static_cast<std::size_t>(vh.idx())] = 0;
  return seeds;
}

bool collect_garbage(Mesh& mesh) {
  auto any_deleted = [&](auto range) {
    for (auto h : range)
      if (mesh.status(h).deleted()) return true;
    return false;
  };
  if (!any_deleted(mesh.all_vertices()) && !any_deleted(mesh.all_edges()) && !any_deleted(mesh.all_faces())) return false;
  mesh.garbage_collection();
  return true;
}

Mesh compacted(const Mesh& mesh) {
  Mesh out;
  out.reserve(mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
  std::vector<VertexHandle> vmap(mesh.n_vertices());
  for (auto vh : mesh.vertices()) {  // skips deleted elements
    const auto nvh = out.add_vertex(mesh.point(vh));
    out.data(nvh) = mesh.data(vh);
    vmap[vh.idx()] = nvh;
  }
  for (auto fh : mesh.faces()) {
    // fv_range starts at the face halfedge's target: keep that vertex order.
    std::vector<VertexHandle> f;
    for (auto fv : mesh.fv_range(fh)) f.push_back(vmap[fv.idx()]);
    out.add_face(f);
  }
  order_pinch_vertices(out);
  for (auto eh : mesh.edges()) {
    const auto h = mesh.halfedge_handle(eh, 0);
    const auto a = vmap[mesh.from_vertex_handle(h).idx()], b = vmap[mesh.to_vertex_handle(h).idx()];
    if (!a.is_valid() || !b.is_valid()) continue;
    const auto nh = out.find_halfedge(a, b);
    if (nh.is_valid()) out.data(out.edge_handle(nh)) = mesh.data(eh);  // edges without faces are dropped
  }
  return out;
}

}  // namespace acute
