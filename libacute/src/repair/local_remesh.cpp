#include "repair/local_remesh.h"

#include <acute/mesh/geometry.h>
#include <acute/mesh/sectors.h>
#include <acute/ops/delaunay_flips.h>
#include <acute/ops/insert.h>
#include <acute/ops/relocate.h>
#include <acute/ops/remove.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace acute::detail {

namespace {

/// Divides constrained, non-frozen edges longer than 1.5 h into equal pieces of about h.
bool divide_segments(Mesh& sub, double h) {
  std::vector<std::array<VertexHandle, 2>> long_edges;
  for (auto eh : sub.edges()) {
    if (sub.status(eh).deleted() || !is_constrained(sub, eh) || sub.data(eh).frozen) continue;
    const auto heh = sub.halfedge_handle(eh, 0);
    const VertexHandle a = sub.from_vertex_handle(heh), b = sub.to_vertex_handle(heh);
    if ((point2(sub, b) - point2(sub, a)).norm() > 1.5 * h) long_edges.push_back({a, b});
  }
  bool changed = false;
  for (const auto& [a, b] : long_edges) {
    const Point2 pa = point2(sub, a), pb = point2(sub, b);
    const int n = std::max(2, static_cast<int>(std::lround((pb - pa).norm() / h)));
    VertexHandle from = a;
    for (int k = 1; k < n; ++k) {
      const auto heh = sub.find_halfedge(from, b);
      if (!heh.is_valid()) break;
      const VertexHandle m = split_edge(sub, sub.edge_handle(heh), pa + (static_cast<double>(k) / n) * (pb - pa));
      if (!m.is_valid()) break;
      from = m;
      changed = true;
    }
  }
  return changed;
}

/// Dart throwing inside the current triangles: candidates kept 0.7 h from every vertex and
/// accepted point, and 0.35 h from every constrained or border edge.
bool scatter_interior(Mesh& sub, double h, std::mt19937& rng) {
  struct Dart {
    Point2 p;
    VertexHandle corner;  // a vertex of the triangle it was drawn in: the walk starts beside it
  };
  std::vector<Point2> taken;
  for (auto vh : sub.vertices())
    if (!sub.status(vh).deleted()) taken.push_back(point2(sub, vh));
  std::vector<std::array<Point2, 2>> walls;
  for (auto eh : sub.edges())
    if (!sub.status(eh).deleted() && (is_constrained(sub, eh) || sub.is_boundary(eh))) {
      const auto heh = sub.halfedge_handle(eh, 0);
      walls.push_back({point2(sub, sub.from_vertex_handle(heh)), point2(sub, sub.to_vertex_handle(heh))});
    }
  const double cell = 0.5 * std::sqrt(3.0) * h * h;  // area per vertex of an equilateral mesh
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Dart> darts;
  for (auto fh : sub.faces()) {
    if (sub.status(fh).deleted()) continue;
    const auto p = face_points(sub, fh);
    const double area = 0.5 * std::abs(signed_area2(p[0], p[1], p[2]));
    const int tries = 1 + static_cast<int>(4.0 * area / cell);
    const VertexHandle corner = *sub.fv_range(fh).begin();
    for (int t = 0; t < tries; ++t) {
      double u = unit(rng), v = unit(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const Point2 q = p[0] + u * (p[1] - p[0]) + v * (p[2] - p[0]);
      bool ok = true;
      for (const auto& w : taken) ok = ok && (q - w).norm() >= 0.7 * h;
      for (const auto& w : walls) ok = ok && distance_to_segment(q, w[0], w[1]) >= 0.35 * h;
      if (!ok) continue;
      taken.push_back(q);
      darts.push_back({q, corner});
    }
  }
  bool changed = false;
  for (const auto& d : darts) {
    const VertexHandle vh = insert_point_from(sub, d.p, d.corner);
    if (vh.is_valid()) changed = changed || !is_input(sub, vh);
  }
  return changed;
}

/// Moves every free vertex to the area-weighted centroid of its star's triangle centroids.
void lloyd_sweeps(Mesh& sub, int sweeps) {
  std::vector<EdgeHandle> queue;
  for (int s = 0; s < sweeps; ++s) {
    for (auto vh : sub.vertices()) {
      if (sub.status(vh).deleted() || sub.data(vh).kind != VertexKind::Free || sub.is_boundary(vh)) continue;
      Point2 c(0, 0);
      double weight = 0;
      for (auto fh : sub.vf_range(vh)) {
        const auto p = face_points(sub, fh);
        const double a = std::abs(signed_area2(p[0], p[1], p[2]));
        c += a * (p[0] + p[1] + p[2]) / 3.0;
        weight += a;
      }
      if (!(weight > 0)) continue;
      c /= weight;
      if (can_relocate(sub, vh, c) != OpVerdict::Ok) continue;
      relocate(sub, vh, c);
      queue.clear();
      push_star_edges(sub, vh, queue);
      restore_delaunay(sub, queue);
    }
  }
}

/// A domain sector at a vertex between consecutive walls, counter-clockwise from u[0] to u[1].
struct Sector {
  Point2 u[2];
  double angle = 0;
};

/// The sectors at vh narrower than max_angle (radians) whose fan lies wholly inside sub.
std::vector<Sector> narrow_sectors(const Mesh& sub, VertexHandle vh, double max_angle) {
  std::vector<Sector> out;
  const Point2 p = point2(sub, vh);
  for (const SegmentSector& s : segment_sectors(sub, vh))
    if (s.radians < max_angle)
      out.push_back(Sector{{(point2(sub, sub.to_vertex_handle(s.first)) - p).normalized(), (point2(sub, sub.to_vertex_handle(s.last)) - p).normalized()},
                           s.radians});
  return out;
}

/// Rebuilds `sectors` (narrow sectors at apex) with common radii. keep_interior_walls: a wall with
/// faces on both sides (an interior segment) keeps its vertices, which then set the radii (one
/// such wall at most); otherwise every wall is divided at the geometric radii of the narrowest
/// sector, so that sectors sharing a wall agree on its points.
bool rebuild_sectors(Mesh& sub, VertexHandle apex, const std::vector<Sector>& sectors, int rings, bool keep_interior_walls);

}  // namespace

bool rebuild_wedge(Mesh& sub, VertexHandle apex, int rings) {
  constexpr double kPi = 3.14159265358979323846;
  if (rings < 3) return false;
  bool rebuilt = false;
  for (const Sector& sector : narrow_sectors(sub, apex, kPi / 3)) rebuilt = rebuild_sectors(sub, apex, {sector}, rings, true) || rebuilt;
  return rebuilt;
}

bool rebuild_hub(Mesh& sub, VertexHandle apex, int rings) {
  constexpr double kPi = 3.14159265358979323846;
  if (rings < 3) return false;
  const std::vector<Sector> sectors = narrow_sectors(sub, apex, kPi / 3);
  return !sectors.empty() && rebuild_sectors(sub, apex, sectors, rings, false);
}

bool has_narrow_sector(const Mesh& sub, VertexHandle vh) {
  constexpr double kPi = 3.14159265358979323846;
  return is_input(sub, vh) && !narrow_sectors(sub, vh, kPi / 3).empty();
}

namespace {

bool rebuild_sectors(Mesh& sub, VertexHandle apex, const std::vector<Sector>& sectors, int rings, bool keep_interior_walls) {
  const Point2 c = point2(sub, apex);
  auto wall_at_apex = [&](const Point2& u) {
    HalfedgeHandle wall;
    for (auto heh : sub.voh_range(apex))
      if (is_constrained(sub, sub.edge_handle(heh)) && (point2(sub, sub.to_vertex_handle(heh)) - c).normalized().dot(u) > 1 - 1e-12) wall = heh;
    return wall;
  };
  // The walls of every sector, each once (neighbouring sectors share one).
  std::vector<Point2> walls;
  for (const Sector& sector : sectors)
    for (const Point2& u : sector.u)
      if (std::none_of(walls.begin(), walls.end(), [&](const Point2& w) { return w.dot(u) > 1 - 1e-12; })) walls.push_back(u);
  std::vector<VertexHandle> kept;
  int kept_wall = -1;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const HalfedgeHandle h = wall_at_apex(walls[w]);
    if (!h.is_valid()) return false;
    if (!keep_interior_walls || sub.is_boundary(h) || sub.is_boundary(sub.opposite_halfedge_handle(h))) continue;
    // An interior segment kept as it is (removing its vertices would coarsen the other side).
    if (kept_wall >= 0) return false;  // two interior walls: not rebuilt this way
    kept_wall = static_cast<int>(w);
    // Walk the wall outwards while its vertices are movable.
    HalfedgeHandle step = h;
    for (int guard = 0; guard < 1024; ++guard) {
      const VertexHandle x = sub.to_vertex_handle(step);
      if (is_input(sub, x)) break;
      kept.push_back(x);
      HalfedgeHandle next;
      for (auto heh : sub.voh_range(x))
        if (heh != sub.opposite_halfedge_handle(step) && is_constrained(sub, sub.edge_handle(heh)) &&
            sub.data(sub.edge_handle(heh)).segment == sub.data(sub.edge_handle(step)).segment)
          next = heh;
      if (!next.is_valid()) break;
      step = next;
    }
  }
  auto is_kept = [&](VertexHandle vh) { return std::find(kept.begin(), kept.end(), vh) != kept.end(); };
  // (A choice of vertices to remove, not a topological decision: the slack takes in the points
  // of the walls, which rounding puts a hair to either side.)
  auto in_sector = [&](const Point2& q) {
    const Point2 d = q - c;
    const double slack = 1e-9 * d.norm();
    for (const Sector& sector : sectors) {
      const Point2* u = sector.u;
      if (u[0].x() * d.y() - u[0].y() * d.x() >= -slack && d.x() * u[1].y() - d.y() * u[1].x() >= -slack) return true;
    }
    return false;
  };
  // Radius of the rebuilt part: short of the nearest vertex in the sectors that stays.
  double reach = INFINITY;
  for (auto vh : sub.vertices()) {
    if (sub.status(vh).deleted() || vh == apex || !in_sector(point2(sub, vh))) continue;
    if (is_input(sub, vh)) reach = std::min(reach, (point2(sub, vh) - c).norm());
  }
  if (!std::isfinite(reach)) return false;
  double narrowest = INFINITY;
  for (const Sector& sector : sectors) narrowest = std::min(narrowest, sector.angle);
  std::vector<double> radius;
  if (kept_wall >= 0) {
    for (auto vh : kept) {
      const double r = (point2(sub, vh) - c).norm();
      if (r < reach) radius.push_back(r);
    }
    std::sort(radius.begin(), radius.end());
    if (radius.size() < 2) return false;
  } else {
    // Geometric radii, the last ring a step short of the reach.
    const double growth = wedge_growth(narrowest);
    radius.resize(static_cast<std::size_t>(rings));
    radius.back() = reach / growth;
    for (int k = rings - 2; k >= 0; --k) radius[static_cast<std::size_t>(k)] = radius[static_cast<std::size_t>(k) + 1] / growth;
  }
  std::vector<VertexHandle> doomed;
  for (auto vh : sub.vertices())
    if (!sub.status(vh).deleted() && !is_input(sub, vh) && !is_kept(vh) && in_sector(point2(sub, vh)) && (point2(sub, vh) - c).norm() < reach)
      doomed.push_back(vh);
  if (doomed.empty()) return false;
  if (!remove_vertices(sub, doomed)) return false;  // something in the way: leave it to other candidates

  // Wall points from the outermost inwards: each split shortens the wall edge at the apex.
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (static_cast<int>(w) == kept_wall) continue;
    for (std::size_t k = radius.size(); k-- > 0;) {
      const HalfedgeHandle wall = wall_at_apex(walls[w]);
      if (!wall.is_valid()) return false;
      if ((point2(sub, sub.to_vertex_handle(wall)) - c).norm() <= radius[k]) continue;
      split_edge(sub, sub.edge_handle(wall), c + radius[k] * walls[w]);
    }
  }
  // The middle row on each sector's bisector, between consecutive rings.
  for (const Sector& sector : sectors) {
    const Point2 bisector = (sector.u[0] + sector.u[1]).normalized();
    const double half = 0.5 * sector.angle;
    for (std::size_t k = 0; k + 1 < radius.size(); ++k) {
      const Point2 q = c + (0.5 * (radius[k] + radius[k + 1]) * std::cos(half)) * bisector;
      insert_point_from(sub, q, apex);
    }
  }
  make_delaunay(sub);
  return true;
}

}  // namespace

double movable_edge_median(const Mesh& sub) {
  std::vector<double> lengths;
  for (auto eh : sub.edges()) {
    if (sub.status(eh).deleted()) continue;
    const auto heh = sub.halfedge_handle(eh, 0);
    const VertexHandle a = sub.from_vertex_handle(heh), b = sub.to_vertex_handle(heh);
    if (is_input(sub, a) && is_input(sub, b)) continue;
    lengths.push_back((point2(sub, b) - point2(sub, a)).norm());
  }
  if (lengths.empty()) return 0;
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
  return lengths[lengths.size() / 2];
}

bool remesh_region(Mesh& sub, double h, std::uint32_t seed) {
  if (!(h > 0)) return false;
  // The re-sampled region must stay about the size it is: at a spacing far below the region's
  // extent (the median edge of a cluster around a feature 1e-6 of its size) the darts and segment
  // pieces would number millions, and dart throwing is quadratic in them.
  double points = 0;
  std::size_t vertices = 0;
  for (auto vh : sub.vertices()) vertices += !sub.status(vh).deleted();
  for (auto fh : sub.faces())
    if (!sub.status(fh).deleted()) {
      const auto p = face_points(sub, fh);
      points += 0.5 * std::abs(signed_area2(p[0], p[1], p[2])) / (0.5 * std::sqrt(3.0) * h * h);
    }
  for (auto eh : sub.edges())
    if (!sub.status(eh).deleted() && is_constrained(sub, eh)) {
      const auto heh = sub.halfedge_handle(eh, 0);
      points += (point2(sub, sub.to_vertex_handle(heh)) - point2(sub, sub.from_vertex_handle(heh))).norm() / h;
    }
  if (!(points <= 4.0 * static_cast<double>(vertices) + 64.0)) return false;
  bool removed = false;
  for (int pass = 0; pass < 2; ++pass)
    for (auto vh : sub.vertices())
      if (!sub.status(vh).deleted() && !is_input(sub, vh)) removed = remove_vertex(sub, vh) || removed;
  if (!removed) return false;
  std::mt19937 rng(seed);
  divide_segments(sub, h);
  scatter_interior(sub, h, rng);
  make_delaunay(sub);
  lloyd_sweeps(sub, 4);
  return true;
}

}  // namespace acute::detail
