// Layer: mesh. check_mesh: connectivity, exact orientation, exact local Delaunay property.
#include <acute/mesh/check.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <numeric>
#include <sstream>

namespace acute {

namespace {

/// Collects violation lines up to a cap, counting all of them.
class Collector {
 public:
  Collector(CheckReport& report, std::size_t cap) : report_(report), cap_(cap) {}
  template <class... Args>
  void add(const Args&... parts) {
    ++report_.total;
    if (report_.violations.size() >= cap_) return;
    std::ostringstream os;
    os.precision(17);
    (os << ... << parts);
    report_.violations.push_back(os.str());
  }

 private:
  CheckReport& report_;
  std::size_t cap_;
};

bool deleted(const Mesh& m, VertexHandle h) { return !h.is_valid() || int(h.idx()) >= int(m.n_vertices()) || m.status(h).deleted(); }
bool deleted(const Mesh& m, HalfedgeHandle h) { return !h.is_valid() || int(h.idx()) >= int(m.n_halfedges()) || m.status(h).deleted(); }
bool deleted(const Mesh& m, FaceHandle h) { return !h.is_valid() || int(h.idx()) >= int(m.n_faces()) || m.status(h).deleted(); }

// Connectivity. Returns false when the halfedge structure is too broken to walk triangles safely.
bool check_topology(const Mesh& m, Collector& out) {
  bool walkable = true;
  for (auto heh : m.halfedges()) {
    const auto to = m.to_vertex_handle(heh);
    const auto next = m.next_halfedge_handle(heh), prev = m.prev_halfedge_handle(heh);
    if (deleted(m, to)) out.add("halfedge ", heh.idx(), ": points to a deleted or invalid vertex");
    if (deleted(m, next) || deleted(m, prev)) {
      out.add("halfedge ", heh.idx(), ": next or prev halfedge deleted or invalid");
      walkable = false;
      continue;
    }
    if (m.prev_halfedge_handle(next) != heh || m.next_halfedge_handle(prev) != heh) {
      out.add("halfedge ", heh.idx(), ": next/prev links are not symmetric");
      walkable = false;
    }
    if (m.from_vertex_handle(next) != to) out.add("halfedge ", heh.idx(), ": next halfedge does not start at its target");
    if (m.face_handle(next) != m.face_handle(heh)) out.add("halfedge ", heh.idx(), ": next halfedge is in another face");
    const auto fh = m.face_handle(heh);
    if (fh.is_valid() && deleted(m, fh)) out.add("halfedge ", heh.idx(), ": in deleted face ", fh.idx());
  }
  for (auto eh : m.edges()) {
    if (m.is_boundary(m.halfedge_handle(eh, 0)) && m.is_boundary(m.halfedge_handle(eh, 1)))
      out.add("edge ", eh.idx(), ": has no incident face");
  }
  for (auto fh : m.faces()) {
    const auto h0 = m.halfedge_handle(fh);
    if (deleted(m, h0)) {
      out.add("face ", fh.idx(), ": its halfedge is deleted or invalid");
      walkable = false;
      continue;
    }
    if (m.face_handle(h0) != fh) out.add("face ", fh.idx(), ": its halfedge belongs to another face");
    if (!walkable) continue;
    int n = 0;
    auto h = h0;
    do {
      ++n;
      h = m.next_halfedge_handle(h);
    } while (h != h0 && n < 4);
    if (n != 3) {
      out.add("face ", fh.idx(), ": not a triangle");
      walkable = false;
    }
  }
  if (!walkable) return false;

  // Vertex connectivity: circulating the one-ring from the vertex's halfedge must visit every
  // outgoing halfedge. Several boundary halfedges (gaps between fans) make a pinch vertex, where
  // the region touches itself at a point: valid in a planar triangulation of such a domain.
  std::vector<int> out_degree(m.n_vertices(), 0), out_boundary(m.n_vertices(), 0);
  for (auto heh : m.halfedges()) {
    const auto from = m.from_vertex_handle(heh);
    if (deleted(m, from)) continue;
    ++out_degree[from.idx()];
    if (m.is_boundary(heh)) ++out_boundary[from.idx()];
  }
  for (auto vh : m.vertices()) {
    const int deg = out_degree[vh.idx()];
    const auto h0 = m.halfedge_handle(vh);
    if (!h0.is_valid()) {
      if (deg != 0) out.add("vertex ", vh.idx(), ": has edges but no outgoing halfedge");
      continue;
    }
    if (deleted(m, h0) || m.from_vertex_handle(h0) != vh) {
      out.add("vertex ", vh.idx(), ": its outgoing halfedge is deleted or does not start at it");
      continue;
    }
    if (out_boundary[vh.idx()] > 0 && !m.is_boundary(h0))
      out.add("vertex ", vh.idx(), ": on the boundary but its outgoing halfedge is not a boundary halfedge");
    int n = 0;
    auto h = h0;
    do {
      ++n;
      h = m.next_halfedge_handle(m.opposite_halfedge_handle(h));
    } while (h != h0 && n <= deg);
    if (n != deg) out.add("vertex ", vh.idx(), ": not manifold (one-ring reaches ", n, " of ", deg, " edges)");
  }

  // Duplicate positions: sort, then compare neighbours.
  std::vector<VertexHandle> order;
  order.reserve(m.n_vertices());
  for (auto vh : m.vertices()) order.push_back(vh);
  auto key_less = [&](VertexHandle a, VertexHandle b) {
    const auto &p = m.point(a), &q = m.point(b);
    if (p[0] != q[0]) return p[0] < q[0];
    if (p[1] != q[1]) return p[1] < q[1];
    return a.idx() < b.idx();
  };
  std::sort(order.begin(), order.end(), key_less);
  for (std::size_t i = 1; i < order.size(); ++i) {
    const auto &p = m.point(order[i - 1]), &q = m.point(order[i]);
    if (p[0] == q[0] && p[1] == q[1])
      out.add("vertices ", order[i - 1].idx(), " and ", order[i].idx(), ": same position (", p[0], ", ", p[1], ")");
  }
  return true;
}

void check_geometry(const Mesh& m, Collector& out) {
  for (auto fh : m.faces()) {
    const auto h = m.halfedge_handle(fh);
    const auto a = m.to_vertex_handle(h), b = m.to_vertex_handle(m.next_halfedge_handle(h)),
               c = m.from_vertex_handle(h);
    const Sign s = predicates::orient2d(point2(m, a), point2(m, b), point2(m, c));
    if (s == Sign::Negative)
      out.add("face ", fh.idx(), ": not counter-clockwise (vertices ", a.idx(), ", ", b.idx(), ", ", c.idx(), ")");
    else if (s == Sign::Zero)
      out.add("face ", fh.idx(), ": degenerate, zero area (vertices ", a.idx(), ", ", b.idx(), ", ", c.idx(), ")");
  }
}

void check_delaunay(const Mesh& m, Collector& out) {
  for (auto eh : m.edges()) {
    if (m.is_boundary(eh) || is_constrained(m, eh)) continue;
    const auto h = m.halfedge_handle(eh, 0), o = m.halfedge_handle(eh, 1);
    const auto a = m.from_vertex_handle(h), b = m.to_vertex_handle(h);
    const auto c = m.to_vertex_handle(m.next_halfedge_handle(h));  // face (a, b, c) left of h
    const auto d = m.to_vertex_handle(m.next_halfedge_handle(o));  // apex across the edge
    // incircle's sign is reversed for clockwise (a, b, c); a bad orientation is reported by Geometry.
    Sign s = predicates::incircle(point2(m, a), point2(m, b), point2(m, c), point2(m, d));
    if (predicates::orient2d(point2(m, a), point2(m, b), point2(m, c)) == Sign::Negative) s = -s;
    if (s == Sign::Positive)
      out.add("edge ", eh.idx(), " (vertices ", a.idx(), "-", b.idx(), "): unconstrained, not locally Delaunay (vertex ",
              d.idx(), " inside the circumcircle of ", a.idx(), ", ", b.idx(), ", ", c.idx(), ")");
  }
}

}  // namespace

std::string CheckReport::summary(std::size_t max_lines) const {
  if (ok()) return "ok";
  std::ostringstream os;
  os << total << (total == 1 ? " violation: " : " violations: ");
  const std::size_t n = std::min(max_lines, violations.size());
  for (std::size_t i = 0; i < n; ++i) os << (i ? "; " : "") << violations[i];
  if (total > n) os << "; ...";
  return os.str();
}

CheckReport check_mesh(const Mesh& mesh, CheckLevel level, std::size_t max_violations) {
  CheckReport report;
  Collector out(report, max_violations);
  const bool walkable = check_topology(mesh, out);
  // Higher levels assume triangles with sound links; other topology faults do not stop them.
  if (!walkable || level == CheckLevel::Topology) return report;
  check_geometry(mesh, out);
  if (level == CheckLevel::Geometry) return report;
  check_delaunay(mesh, out);
  return report;
}

}  // namespace acute
