#include <acute/ops/delaunay_flips.h>

#include <acute/ops/flip.h>

namespace acute {

std::size_t restore_delaunay(Mesh& mesh, std::vector<EdgeHandle>& queue, std::vector<VertexHandle>* touched) {
  std::size_t flips = 0;
  while (!queue.empty()) {
    const EdgeHandle eh = queue.back();
    queue.pop_back();
    if (!eh.is_valid() || mesh.status(eh).deleted() || is_locally_delaunay(mesh, eh)) continue;
    if (can_flip(mesh, eh) != OpVerdict::Ok) continue;  // cannot happen for a strictly non-Delaunay edge
    const auto h0 = mesh.halfedge_handle(eh, 0), h1 = mesh.halfedge_handle(eh, 1);
    mesh.flip(eh);
    ++flips;
    if (touched)  // the new diagonal's ends, and the old one's (opposite it now)
      for (auto h : {h0, h1}) {
        touched->push_back(mesh.to_vertex_handle(h));
        touched->push_back(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
      }
    // The four edges of the new quadrilateral may have become non-Delaunay.
    queue.push_back(mesh.edge_handle(mesh.next_halfedge_handle(h0)));
    queue.push_back(mesh.edge_handle(mesh.prev_halfedge_handle(h0)));
    queue.push_back(mesh.edge_handle(mesh.next_halfedge_handle(h1)));
    queue.push_back(mesh.edge_handle(mesh.prev_halfedge_handle(h1)));
  }
  return flips;
}

std::size_t make_delaunay(Mesh& mesh) {
  std::vector<EdgeHandle> queue;
  queue.reserve(mesh.n_edges());
  for (auto eh : mesh.edges()) queue.push_back(eh);
  return restore_delaunay(mesh, queue);
}

void push_star_edges(const Mesh& mesh, VertexHandle vh, std::vector<EdgeHandle>& queue) {
  for (auto heh : mesh.voh_range(vh)) {
    queue.push_back(mesh.edge_handle(heh));
    if (!mesh.is_boundary(heh)) queue.push_back(mesh.edge_handle(mesh.next_halfedge_handle(heh)));
  }
}

}  // namespace acute
