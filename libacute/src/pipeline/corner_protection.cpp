#include "pipeline/corner_protection.h"

#include <acute/mesh/geometry.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace acute::detail {

namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

double angle_at(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 u = a - p, v = b - p;
  return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v)) * kDeg;
}

double distance_to_segment(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

struct Sector {
  HalfedgeHandle first, last;  ///< the wall spokes out of the apex (counter-clockwise from first)
  double angle = 0;
};

}  // namespace

CornerProtection protect_narrow_corners(const Domain& domain, const Mesh& cdt, double max_sector_deg, double size) {
  CornerProtection out;
  out.domain = domain;
  if (domain.convex_hull) return out;
  auto is_wall = [&](HalfedgeHandle h) { return is_constrained(cdt, cdt.edge_handle(h)) || cdt.is_boundary(cdt.opposite_halfedge_handle(h)); };

  // The narrow sectors of every input vertex, both walls constrained.
  std::vector<std::pair<VertexHandle, std::vector<Sector>>> corners;
  for (auto vh : cdt.vertices()) {
    if (!is_input(cdt, vh)) continue;
    const Point2 c = point2(cdt, vh);
    std::vector<Sector> narrow;
    for (auto start : cdt.voh_range(vh)) {
      if (cdt.is_boundary(start) || !is_wall(start)) continue;
      Sector s;
      s.first = start;
      HalfedgeHandle h = start;
      for (std::size_t guard = 0; guard < 4096; ++guard) {
        const HalfedgeHandle back = cdt.prev_halfedge_handle(h);
        s.angle += angle_at(c, point2(cdt, cdt.to_vertex_handle(h)), point2(cdt, cdt.from_vertex_handle(back)));
        h = cdt.opposite_halfedge_handle(back);
        if (is_wall(h) || h == start || cdt.is_boundary(h)) break;
      }
      s.last = h;
      if (h == start || !is_constrained(cdt, cdt.edge_handle(start)) || !is_constrained(cdt, cdt.edge_handle(h))) continue;
      if (s.angle < max_sector_deg && s.angle > 0) narrow.push_back(s);
    }
    if (!narrow.empty()) corners.emplace_back(vh, std::move(narrow));
  }
  if (corners.empty()) return out;

  // Segments re-derived from the CDT's constrained edges (a segment with input points inside it is
  // a chain of edges), each between two input points; cuts are added per edge.
  std::vector<std::array<int, 2>> edges;
  std::vector<int> edge_marker;
  std::map<int, std::size_t> edge_index;  // CDT edge idx -> position in edges
  for (auto eh : cdt.edges()) {
    if (!is_constrained(cdt, eh)) continue;
    const auto h = cdt.halfedge_handle(eh, 0);
    const int a = cdt.data(cdt.from_vertex_handle(h)).input_index, b = cdt.data(cdt.to_vertex_handle(h)).input_index;
    if (a < 0 || b < 0) return out;  // (only input points expected; leave the domain alone otherwise)
    edge_index[eh.idx()] = edges.size();
    edges.push_back({a, b});
    edge_marker.push_back(cdt.data(eh).marker);
  }
  // Per edge, the cut points along it as (distance from the edge's first end, point index).
  std::vector<std::vector<std::pair<double, int>>> cuts(edges.size());
  std::vector<std::array<int, 2>> chords;

  Domain& d = out.domain;
  for (auto& [vh, sectors] : corners) {
    const Point2 c = point2(cdt, vh);
    const int ci = cdt.data(vh).input_index;
    // Room: below 0.4 of every wall edge and 0.45 of the distance to features not incident to c.
    double room = INFINITY;
    for (const auto& s : sectors)
      for (auto h : {s.first, s.last}) room = std::min(room, 0.4 * (point2(cdt, cdt.to_vertex_handle(h)) - c).norm());
    for (std::size_t i = 0; i < domain.points.size(); ++i)
      if (static_cast<int>(i) != ci && domain.points[i] != c) room = std::min(room, 0.45 * (domain.points[i] - c).norm());
    for (const auto& e : edges) {
      const Point2 &a = domain.points[static_cast<std::size_t>(e[0])], &b = domain.points[static_cast<std::size_t>(e[1])];
      if (a == c || b == c) continue;
      room = std::min(room, 0.45 * distance_to_segment(c, a, b));
    }
    double narrowest = 180;
    for (const auto& s : sectors) narrowest = std::min(narrowest, s.angle);
    double r = room;
    if (size > 0) r = std::min(r, std::min(3.0 * size, size / (2.0 * std::sin(0.5 * narrowest / kDeg))));
    if (!(r > 0) || !std::isfinite(r)) continue;

    std::map<int, int> cut_of_edge;  // CDT edge idx -> new point index
    auto cut_on = [&](HalfedgeHandle h) {
      const EdgeHandle eh = cdt.edge_handle(h);
      const auto found = cut_of_edge.find(eh.idx());
      if (found != cut_of_edge.end()) return found->second;
      const Point2 far = point2(cdt, cdt.to_vertex_handle(h));
      const double len = (far - c).norm();
      const Point2 q = c + (r / len) * (far - c);
      const int index = static_cast<int>(d.points.size());
      d.points.push_back(q);
      if (!d.point_markers.empty()) d.point_markers.push_back(cdt.data(eh).marker);
      const std::size_t k = edge_index.at(eh.idx());
      const bool from_first = domain.points[static_cast<std::size_t>(edges[k][0])] == c;
      cuts[k].emplace_back(from_first ? r : len - r, index);
      cut_of_edge[eh.idx()] = index;
      return index;
    };
    for (const auto& s : sectors) {
      chords.push_back({cut_on(s.first), cut_on(s.last)});
      ++out.sectors;
    }
    ++out.corners;
  }

  d.segments.clear();
  const bool markers = !domain.segment_markers.empty();
  d.segment_markers.clear();
  for (std::size_t k = 0; k < edges.size(); ++k) {
    auto& along = cuts[k];
    std::sort(along.begin(), along.end());
    int prev = edges[k][0];
    for (const auto& [t, index] : along) {
      d.segments.push_back({prev, index});
      if (markers) d.segment_markers.push_back(edge_marker[k]);
      prev = index;
    }
    d.segments.push_back({prev, edges[k][1]});
    if (markers) d.segment_markers.push_back(edge_marker[k]);
  }
  for (const auto& ch : chords) {
    d.segments.push_back(ch);
    if (markers) d.segment_markers.push_back(0);
  }
  return out;
}

}  // namespace acute::detail
