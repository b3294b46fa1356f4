#include <acute/delaunay/cdt.h>

#include <acute/core/errors.h>
#include <acute/predicates/predicates.h>

#include "delaunay/in_place.h"
#include "delaunay/triangulation.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <string>

namespace acute {

namespace {

// For every vertex that was inserted, the smallest input index with that position.
std::vector<int> first_occurrence(const detail::Triangulation& tr, std::size_t n) {
  std::vector<int> first(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(tr.rep(static_cast<int>(i)));
    if (first[r] < 0) first[r] = static_cast<int>(i);
  }
  return first;
}

std::string point_text(const Point2& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x(), p.y());
  return buf;
}

void check_point(const std::string& where, const char* what, std::size_t i, const Point2& p) {
  if (!predicates::validate_coordinate(p.x()) || !predicates::validate_coordinate(p.y()))
    throw InvalidInput(where + ": " + what + " " + std::to_string(i) + " has a coordinate that is not finite or out of the exact range " +
                       point_text(p));
}

/// Faces of `mesh` (whose vertices are added) from triangulation slots, each given as its corners
/// (mesh vertex ids, counter-clockwise) and its slot, in that order, with the connectivity
/// OpenMesh's add_face would give for the same sequence: edges created in order of first use, a
/// face's halfedge its third, an interior vertex's halfedge its outgoing one in the last face
/// round it, a boundary vertex's its outgoing boundary one. The neighbour across each edge comes
/// from the triangulation instead of a search round the vertices (add_face's find_halfedge and
/// boundary checks were 0.23 s of the 1M-triangle square). False, with faces added, where a
/// boundary vertex has two boundary gaps (a pinch: add_face links those in an order of its own),
/// and the caller builds again with add_face.
bool add_faces_from_slots(Mesh& mesh, const detail::Triangulation& tr, const std::vector<std::pair<std::array<int, 3>, int>>& order,
                          const std::vector<int>& vmap) {
  std::vector<int> face_of_slot(static_cast<std::size_t>(tr.num_slots()), -1);
  for (const auto& [corners, t] : order) {
    const auto& tv = tr.tri(t).v;
    int r = 0;
    while (vmap[static_cast<std::size_t>(tv[r])] != corners[0]) ++r;
    HalfedgeHandle he[3];
    for (int i = 0; i < 3; ++i) {
      const VertexHandle a(corners[i]), b(corners[(i + 1) % 3]);
      // The edge corners[i] -> corners[i+1] is opposite triangulation vertex (r + i + 2) % 3.
      const int nb = tr.tri(t).n[(r + i + 2) % 3];
      const int other = nb >= 0 ? face_of_slot[static_cast<std::size_t>(nb)] : -1;
      if (other < 0) {
        he[i] = mesh.new_edge(a, b);
        continue;
      }
      HalfedgeHandle h = mesh.halfedge_handle(FaceHandle(other));
      while (mesh.from_vertex_handle(h) != b) h = mesh.next_halfedge_handle(h);
      he[i] = mesh.opposite_halfedge_handle(h);
    }
    const FaceHandle fh = mesh.new_face();
    mesh.set_halfedge_handle(fh, he[2]);
    for (int i = 0; i < 3; ++i) {
      mesh.set_face_handle(he[i], fh);
      mesh.set_next_halfedge_handle(he[i], he[(i + 1) % 3]);
      mesh.set_halfedge_handle(VertexHandle(corners[i]), he[i]);
    }
    face_of_slot[static_cast<std::size_t>(t)] = fh.idx();
  }
  // Boundary halfedges: each one's next leaves its end vertex along the boundary (turn round that
  // vertex through its faces to the gap), and is its start vertex's halfedge.
  std::vector<char> gaps(mesh.n_vertices(), 0);
  for (auto eh : mesh.edges())
    for (int k = 0; k < 2; ++k) {
      const HalfedgeHandle h = mesh.halfedge_handle(eh, k);
      if (mesh.face_handle(h).is_valid()) continue;
      HalfedgeHandle out = mesh.opposite_halfedge_handle(h);
      do out = mesh.opposite_halfedge_handle(mesh.next_halfedge_handle(mesh.next_halfedge_handle(out)));
      while (mesh.face_handle(out).is_valid());
      mesh.set_next_halfedge_handle(h, out);
      const VertexHandle from = mesh.from_vertex_handle(h);
      if (++gaps[static_cast<std::size_t>(from.idx())] > 1) return false;
      mesh.set_halfedge_handle(from, h);
    }
  return true;
}

}  // namespace

Mesh build_cdt(const Domain& domain, const CdtOptions& options, CdtStats* stats_out) {
  Mesh mesh;
  detail::build_cdt_into(mesh, domain, options, stats_out);
  return mesh;
}

void detail::build_cdt_into(Mesh& mesh, const Domain& domain, const CdtOptions& options, CdtStats* stats_out) {
  const std::string where = domain.name.empty() ? std::string("domain") : domain.name;
  CdtStats stats;
  const std::size_t n = domain.points.size();
  for (std::size_t i = 0; i < n; ++i) check_point(where, "point", i, domain.points[i]);
  for (std::size_t h = 0; h < domain.holes.size(); ++h) check_point(where, "hole", h, domain.holes[h]);
  for (std::size_t s = 0; s < domain.segments.size(); ++s)
    for (int e : domain.segments[s])
      if (e < 0 || static_cast<std::size_t>(e) >= n)
        throw InvalidInput(where + ": segment " + std::to_string(s) + " uses point " + std::to_string(e) + ", there are " +
                           std::to_string(n));

  // Duplicates are found by the insertion itself (the located triangle has that vertex).
  detail::Triangulation tr(domain.points);
  tr.split_crossings = options.crossing == CrossingSegments::Split;
  if (!tr.insert_points(detail::brio_hilbert_order(domain.points)))
    throw InvalidInput(where + ": domain encloses no area (fewer than 3 points or all collinear)");
  const std::vector<int> first = first_occurrence(tr, n);
  for (std::size_t i = 0; i < n; ++i) stats.merged_duplicates += tr.rep(static_cast<int>(i)) != static_cast<int>(i) ? 1 : 0;

  // With crossings split, a repeated segment would be inserted again along its exact line beside
  // the first copy's chain through rounded crossing points, and cross it: keep the first copy.
  std::vector<char> repeated(domain.segments.size(), 0);
  if (tr.split_crossings) {
    std::vector<std::pair<std::uint64_t, std::size_t>> keys;
    keys.reserve(domain.segments.size());
    for (std::size_t s = 0; s < domain.segments.size(); ++s) {
      const auto a = static_cast<std::uint32_t>(tr.rep(domain.segments[s][0])), b = static_cast<std::uint32_t>(tr.rep(domain.segments[s][1]));
      keys.emplace_back((static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b), s);
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t k = 1; k < keys.size(); ++k)
      if (keys[k].first == keys[k - 1].first) repeated[keys[k].second] = 1;
  }
  for (std::size_t s = 0; s < domain.segments.size(); ++s) {
    const int a = tr.rep(domain.segments[s][0]);
    const int b = tr.rep(domain.segments[s][1]);
    if (a == b) {
      stats.warnings.push_back("segment " + std::to_string(s) + " has zero length, ignored");
      continue;
    }
    if (repeated[s]) continue;
    try {
      tr.insert_segment(a, b, static_cast<int>(s));
    } catch (const InvalidInput& e) {
      throw InvalidInput(where + ": " + e.what());
    }
  }
  // Post-condition: every segment is a chain of constrained edges (cheap: the degrees along the
  // chains). Segments split at rounded crossing points are not on their input line any more.
  {
    std::vector<char> split(domain.segments.size(), 0);
    for (int s : tr.split_segment_ids) split[static_cast<std::size_t>(s)] = 1;
    if (!tr.overlapping_segments.empty()) {
      // Overlapping segments share edges: one split bends all of them (union-find over overlaps).
      std::vector<int> parent(domain.segments.size());
      std::iota(parent.begin(), parent.end(), 0);
      auto root = [&](int x) {
        while (parent[static_cast<std::size_t>(x)] != x) x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
        return x;
      };
      for (const auto& [x, y] : tr.overlapping_segments) parent[static_cast<std::size_t>(root(x))] = root(y);
      std::vector<char> group_split(domain.segments.size(), 0);
      for (std::size_t s = 0; s < split.size(); ++s)
        if (split[s]) group_split[static_cast<std::size_t>(root(static_cast<int>(s)))] = 1;
      for (std::size_t s = 0; s < split.size(); ++s) split[s] = group_split[static_cast<std::size_t>(root(static_cast<int>(s)))];
    }
    for (std::size_t s = 0; s < domain.segments.size(); ++s) {
      const int a = tr.rep(domain.segments[s][0]), b = tr.rep(domain.segments[s][1]);
      if (a == b || split[s] || repeated[s]) continue;
      const int at = tr.find_missing_segment(a, b);
      if (at >= 0)
        throw InternalError(where + ": build_cdt lost segment " + std::to_string(s) + " " + point_text(tr.point(a)) + "-" +
                            point_text(tr.point(b)) + " at " + point_text(tr.point(at)));
    }
  }
  stats.points_on_segments = tr.points_on_segments;
  stats.crossings_split = tr.crossings_split;

  // Domain: flood from the outside (ghosts) across unconstrained edges, then from each hole.
  const int slots = tr.num_slots();
  std::vector<char> removed(static_cast<std::size_t>(slots), 0);
  std::vector<int> stack;
  auto flood = [&](int start) {
    removed[static_cast<std::size_t>(start)] = 1;
    stack.push_back(start);
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        if (tr.segment(t, i) >= 0) continue;
        const int nb = tr.tri(t).n[i];
        if (removed[static_cast<std::size_t>(nb)]) continue;
        removed[static_cast<std::size_t>(nb)] = 1;
        stack.push_back(nb);
      }
    }
  };
  for (int t = 0; t < slots; ++t) {
    if (!tr.alive(t) || !tr.is_ghost(t) || removed[static_cast<std::size_t>(t)]) continue;
    if (domain.convex_hull)
      removed[static_cast<std::size_t>(t)] = 1;  // -c: the hull acts as a segment
    else
      flood(t);
  }
  for (const Point2& h : domain.holes) {
    const int t = tr.locate(h);
    if (tr.is_ghost(t) || removed[static_cast<std::size_t>(t)]) continue;
    flood(t);
  }

  // Hand over as an acute::Mesh.
  const int nv = tr.num_vertices();
  std::vector<int> vmap(static_cast<std::size_t>(nv), -1);
  std::size_t nf = 0;
  for (int t = 0; t < slots; ++t) {
    if (!tr.alive(t) || removed[static_cast<std::size_t>(t)]) continue;
    ++nf;
    for (int v : tr.tri(t).v) vmap[static_cast<std::size_t>(v)] = 0;
  }
  if (nf == 0) throw InvalidInput(where + ": domain encloses no area");
  if (mesh.n_vertices() > 0) mesh = Mesh();
  std::size_t used = 0;
  for (int v : vmap) used += v == 0 ? 1 : 0;
  mesh.reserve(used, used + nf + 1, nf);
  for (int v = 0; v < nv; ++v) {
    if (vmap[static_cast<std::size_t>(v)] < 0) {
      if (static_cast<std::size_t>(v) < n && tr.rep(v) == v) ++stats.dropped_points;
      continue;
    }
    const Point2& p = tr.point(v);
    const VertexHandle vh = mesh.add_vertex(Mesh::Point(p.x(), p.y(), 0.0));
    vmap[static_cast<std::size_t>(v)] = vh.idx();
    auto& d = mesh.data(vh);
    d.kind = VertexKind::Input;
    if (static_cast<std::size_t>(v) < n) {
      const int in = first[static_cast<std::size_t>(v)];
      d.input_index = in;
      if (static_cast<std::size_t>(in) < domain.point_markers.size()) d.marker = domain.point_markers[static_cast<std::size_t>(in)];
    }
  }
  // Faces in the order of their smallest vertex (each from that corner): with spatially ordered
  // points the faces, edges and half-edges then lie in memory as the vertices do, which the
  // whole-mesh sweeps of the optimiser and the repair walk coherently.
  // A counting sort by the smallest corner, then the few faces of each corner by their other two
  // (the order of a lexicographic sort, at a fraction of its cost for a million faces).
  std::vector<std::pair<std::array<int, 3>, int>> order(nf);  // (rotated corners, slot)
  {
    std::vector<int> start(used + 1, 0);
    auto rotated = [&](int t) {
      const auto& tv = tr.tri(t).v;
      const int m[3] = {vmap[static_cast<std::size_t>(tv[0])], vmap[static_cast<std::size_t>(tv[1])], vmap[static_cast<std::size_t>(tv[2])]};
      const int r = m[0] < m[1] ? (m[0] < m[2] ? 0 : 2) : (m[1] < m[2] ? 1 : 2);
      return std::array<int, 3>{m[r], m[(r + 1) % 3], m[(r + 2) % 3]};
    };
    for (int t = 0; t < slots; ++t)
      if (tr.alive(t) && !removed[static_cast<std::size_t>(t)]) ++start[static_cast<std::size_t>(rotated(t)[0]) + 1];
    for (std::size_t v = 0; v < used; ++v) start[v + 1] += start[v];
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < slots; ++t) {
      if (!tr.alive(t) || removed[static_cast<std::size_t>(t)]) continue;
      const std::array<int, 3> c = rotated(t);
      order[static_cast<std::size_t>(fill[static_cast<std::size_t>(c[0])]++)] = {c, t};
    }
    for (std::size_t v = 0; v < used; ++v)
      std::sort(order.begin() + start[v], order.begin() + start[v + 1]);
  }
  if (!add_faces_from_slots(mesh, tr, order, vmap)) {
    // A pinched boundary vertex: the same faces through add_face.
    Mesh again;
    again.reserve(used, used + nf + 1, nf);
    for (auto vh : mesh.vertices()) again.data(again.add_vertex(mesh.point(vh))) = mesh.data(vh);
    for (const auto& entry : order) {
      const auto& c = entry.first;
      if (!again.add_face(VertexHandle(c[0]), VertexHandle(c[1]), VertexHandle(c[2])).is_valid())
        throw InternalError("build_cdt: OpenMesh refused triangle " + std::to_string(entry.second));
    }
    mesh = std::move(again);
  }
  std::vector<char> present(domain.segments.size(), 0);
  for (std::size_t f = 0; f < order.size(); ++f) {
    const int t = order[f].second;
    const auto& tv = tr.tri(t).v;
    const VertexHandle vh[3] = {VertexHandle(vmap[static_cast<std::size_t>(tv[0])]), VertexHandle(vmap[static_cast<std::size_t>(tv[1])]),
                                VertexHandle(vmap[static_cast<std::size_t>(tv[2])])};
    const FaceHandle fh(static_cast<int>(f));
    if (tr.segment(t, 0) < 0 && tr.segment(t, 1) < 0 && tr.segment(t, 2) < 0) continue;
    for (auto heh : mesh.fh_range(fh)) {
      const VertexHandle from = mesh.from_vertex_handle(heh);
      const int i = from == vh[0] ? 2 : (from == vh[1] ? 0 : 1);  // edge v[i+1] -> v[i+2]
      const int s = tr.segment(t, i);
      if (s < 0) continue;
      auto& ed = mesh.data(mesh.edge_handle(heh));
      ed.segment = s;
      ed.marker = static_cast<std::size_t>(s) < domain.segment_markers.size() ? domain.segment_markers[static_cast<std::size_t>(s)] : 0;
      present[static_cast<std::size_t>(s)] = 1;
    }
  }
  std::size_t dropped_segments = 0;
  for (std::size_t s = 0; s < present.size(); ++s) {
    if (present[s] || repeated[s] || domain.segments[s][0] == domain.segments[s][1] ||
        tr.rep(domain.segments[s][0]) == tr.rep(domain.segments[s][1]))
      continue;
    if (++dropped_segments <= 5)
      stats.warnings.push_back("segment " + std::to_string(s) + " has no domain on either side, dropped");
  }
  if (dropped_segments > 5)
    stats.warnings.push_back(std::to_string(dropped_segments) + " segments in all have no domain on either side, dropped");
  if (stats_out) *stats_out = std::move(stats);
}

std::vector<std::array<int, 3>> delaunay_triangles(const std::vector<Point2>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) check_point("delaunay_triangles", "point", i, points[i]);
  detail::Triangulation tr(points);
  std::vector<std::array<int, 3>> out;
  if (!tr.insert_points(detail::brio_hilbert_order(points))) return out;
  const std::vector<int> first = first_occurrence(tr, points.size());
  out.reserve(static_cast<std::size_t>(tr.num_slots()));
  for (int t = 0; t < tr.num_slots(); ++t) {
    if (!tr.alive(t) || tr.is_ghost(t)) continue;
    const auto& v = tr.tri(t).v;
    out.push_back({first[static_cast<std::size_t>(v[0])], first[static_cast<std::size_t>(v[1])], first[static_cast<std::size_t>(v[2])]});
  }
  return out;
}

}  // namespace acute
