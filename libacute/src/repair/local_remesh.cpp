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

/// The area per vertex of an equilateral mesh of edge s.
double equilateral_cell(double s) { return 0.5 * std::sqrt(3.0) * s * s; }

/// A wall of a region copy: a constrained or border edge, by its ends.
struct Wall {
  VertexHandle end[2];
  Point2 p[2];
};

std::vector<Wall> region_walls(const Mesh& sub) {
  std::vector<Wall> walls;
  for (auto eh : sub.edges())
    if (!sub.status(eh).deleted() && (is_constrained(sub, eh) || sub.is_boundary(eh))) {
      const auto heh = sub.halfedge_handle(eh, 0);
      const VertexHandle a = sub.from_vertex_handle(heh), b = sub.to_vertex_handle(heh);
      walls.push_back({{a, b}, {point2(sub, a), point2(sub, b)}});
    }
  return walls;
}

/// The spacing a re-sampled region aims at: h, finer near the features that stay, growing away
/// from each at kGrading per unit length: s(x) = min(h, min_v lfs(v) + kGrading |x - v|) over the
/// vertices v left after the removal (Input vertices and the frozen ring), lfs(v) the distance
/// from v to the nearest other vertex or wall (constrained or border edge) not at v. Without it a
/// region holding an input point 1e-3 of h from a segment was re-sampled at h along that segment,
/// leaving one flat triangle no later step could open.
class Spacing {
 public:
  static constexpr double kGrading = 0.5;

  Spacing(const Mesh& sub, const std::vector<Wall>& walls, double h) : h_(h) {
    std::vector<VertexHandle> vertices;
    for (auto vh : sub.vertices())
      if (!sub.status(vh).deleted()) vertices.push_back(vh);
    for (auto v : vertices) {
      const Point2 p = point2(sub, v);
      double d2 = h * h;
      for (auto w : vertices)
        if (w != v) d2 = std::min(d2, (point2(sub, w) - p).squaredNorm());
      for (const Wall& w : walls)
        if (w.end[0] != v && w.end[1] != v) d2 = std::min(d2, distance2_to_segment(p, w.p[0], w.p[1]));
      const double lfs = std::sqrt(d2);
      if (lfs < h) sites_.push_back({p, lfs});
    }
  }

  double at(const Point2& q) const {
    double s = h_;
    for (const Site& site : sites_) s = std::min(s, site.lfs + kGrading * (q - site.p).norm());
    return s;
  }
  double cap() const { return h_; }

  /// A lower bound of s over triangle p (the distance from each site to the triangle).
  double lower_bound(const std::array<Point2, 3>& p) const {
    double s = h_;
    for (const Site& site : sites_) {
      const double a0 = signed_area2(p[0], p[1], site.p), a1 = signed_area2(p[1], p[2], site.p), a2 = signed_area2(p[2], p[0], site.p);
      const bool inside = (a0 >= 0 && a1 >= 0 && a2 >= 0) || (a0 <= 0 && a1 <= 0 && a2 <= 0);
      const double d = inside ? 0.0
                              : std::sqrt(std::min({distance2_to_segment(site.p, p[0], p[1]), distance2_to_segment(site.p, p[1], p[2]),
                                                    distance2_to_segment(site.p, p[2], p[0])}));
      s = std::min(s, site.lfs + kGrading * d);
    }
    return s;
  }

 private:
  struct Site {
    Point2 p;
    double lfs;
  };
  double h_;
  std::vector<Site> sites_;  ///< only the vertices finer than h
};

/// Divides constrained, non-frozen edges into pieces of about the local spacing (the integral of
/// 1 / s along the edge rounded, at least 2, for edges where it exceeds 1.5).
bool divide_segments(Mesh& sub, const Spacing& spacing) {
  std::vector<std::array<VertexHandle, 2>> edges;
  for (auto eh : sub.edges()) {
    if (sub.status(eh).deleted() || !is_constrained(sub, eh) || sub.data(eh).frozen) continue;
    const auto heh = sub.halfedge_handle(eh, 0);
    edges.push_back({sub.from_vertex_handle(heh), sub.to_vertex_handle(heh)});
  }
  constexpr int kSteps = 256;
  std::vector<double> cumulative(kSteps + 1);
  bool changed = false;
  for (const auto& [a, b] : edges) {
    const Point2 pa = point2(sub, a), pb = point2(sub, b);
    const double length = (pb - pa).norm();
    cumulative[0] = 0;
    for (int k = 0; k < kSteps; ++k)
      cumulative[k + 1] = cumulative[k] + (length / kSteps) / spacing.at(pa + ((k + 0.5) / kSteps) * (pb - pa));
    const double total = cumulative[kSteps];
    if (!(total > 1.5)) continue;
    const int n = std::max(2, static_cast<int>(std::lround(total)));
    VertexHandle from = a;
    int step = 0;
    for (int k = 1; k < n; ++k) {
      // The parameter where the integral reaches k / n of its total (linear within a step).
      const double target = total * k / n;
      while (step < kSteps - 1 && cumulative[step + 1] < target) ++step;
      const double piece = cumulative[step + 1] - cumulative[step];
      const double t = (step + (piece > 0 ? std::clamp((target - cumulative[step]) / piece, 0.0, 1.0) : 0.5)) / kSteps;
      const auto heh = sub.find_halfedge(from, b);
      if (!heh.is_valid()) break;
      const VertexHandle m = split_edge(sub, sub.edge_handle(heh), pa + t * (pb - pa));
      if (!m.is_valid()) break;
      from = m;
      changed = true;
    }
  }
  return changed;
}

/// Dart throwing inside the current triangles: candidates kept 0.7 of the mean of their spacing
/// and a point's from every vertex and accepted point, and 0.35 of theirs from every constrained
/// or border edge. The triangles are first cut in four until each is at most four times an
/// equilateral mesh's area per vertex at the least spacing over it, so that a graded region gets
/// its darts where it is fine without drawing millions where it is coarse. Returns false (nothing
/// inserted) when the region would get more than max_points points; true otherwise, also when no
/// dart fitted (a channel one triangle wide).
bool scatter_interior(Mesh& sub, const Spacing& spacing, const std::vector<Wall>& walls, std::mt19937& rng, double max_points) {
  struct Piece {
    std::array<Point2, 3> p;
    VertexHandle corner;  // a vertex of the face it was cut from: the insertion walk starts there
    double least = 0;     // a lower bound of the spacing over it
  };
  std::vector<Piece> stack, pieces;
  for (auto fh : sub.faces())
    if (!sub.status(fh).deleted()) stack.push_back({face_points(sub, fh), *sub.fv_range(fh).begin()});
  double points = 0;
  while (!stack.empty()) {
    Piece piece = stack.back();
    stack.pop_back();
    const auto& p = piece.p;
    const double area = 0.5 * std::abs(signed_area2(p[0], p[1], p[2]));
    piece.least = spacing.lower_bound(p);
    if (area > 4 * equilateral_cell(piece.least) && piece.least > 1e-3 * spacing.cap()) {
      const Point2 m01 = 0.5 * (p[0] + p[1]), m12 = 0.5 * (p[1] + p[2]), m20 = 0.5 * (p[2] + p[0]);
      for (const auto& q : {std::array<Point2, 3>{p[0], m01, m20}, {m01, p[1], m12}, {m20, m12, p[2]}, {m01, m12, m20}})
        stack.push_back({q, piece.corner});
      continue;
    }
    points += area / equilateral_cell(spacing.at((p[0] + p[1] + p[2]) / 3.0));
    if (points > max_points) return false;
    pieces.push_back(piece);
  }
  struct Taken {
    Point2 p;
    double s;
  };
  std::vector<Taken> taken;
  for (auto vh : sub.vertices())
    if (!sub.status(vh).deleted()) taken.push_back({point2(sub, vh), spacing.at(point2(sub, vh))});
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::pair<Point2, VertexHandle>> darts;
  for (const Piece& piece : pieces) {
    const auto& p = piece.p;
    // Darts at the density of the least spacing, each kept with the probability (least / s)^2.
    const int tries = 1 + static_cast<int>(4.0 * 0.5 * std::abs(signed_area2(p[0], p[1], p[2])) / equilateral_cell(piece.least));
    for (int t = 0; t < tries; ++t) {
      double u = unit(rng), v = unit(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const Point2 q = p[0] + u * (p[1] - p[0]) + v * (p[2] - p[0]);
      const double sq = spacing.at(q);
      if (unit(rng) * sq * sq > piece.least * piece.least) continue;
      bool ok = true;
      for (const auto& w : taken) ok = ok && (q - w.p).norm() >= 0.35 * (sq + w.s);
      for (const Wall& w : walls) ok = ok && distance_to_segment(q, w.p[0], w.p[1]) >= 0.35 * sq;
      if (!ok) continue;
      taken.push_back({q, sq});
      darts.emplace_back(q, piece.corner);
    }
  }
  for (const auto& [q, corner] : darts) insert_point_from(sub, q, corner);
  return true;
}

/// Moves every free vertex to the centroid of its star's triangle centroids, each weighted by its
/// area and the density s^-4 at its centroid (a CVT's cells grow as the density's -1/4 power).
void lloyd_sweeps(Mesh& sub, const Spacing& spacing, int sweeps) {
  std::vector<EdgeHandle> queue;
  for (int s = 0; s < sweeps; ++s) {
    for (auto vh : sub.vertices()) {
      if (sub.status(vh).deleted() || sub.data(vh).kind != VertexKind::Free || sub.is_boundary(vh)) continue;
      Point2 c(0, 0);
      double weight = 0;
      for (auto fh : sub.vf_range(vh)) {
        const auto p = face_points(sub, fh);
        const Point2 centroid = (p[0] + p[1] + p[2]) / 3.0;
        const double size = spacing.at(centroid) / spacing.cap();
        const double a = std::abs(signed_area2(p[0], p[1], p[2])) / (size * size * size * size);
        c += a * centroid;
        weight += a;
      }
      if (!(weight > 0) || !std::isfinite(weight)) continue;
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
  // pieces would number millions, and dart throwing is quadratic in them. A cheap bound at the
  // uniform spacing first, then the graded count (finer: the spacing only goes down near
  // features), at most eight times the vertices the region has.
  double points = 0;
  std::size_t vertices = 0;
  for (auto vh : sub.vertices()) vertices += !sub.status(vh).deleted();
  for (auto fh : sub.faces())
    if (!sub.status(fh).deleted()) {
      const auto p = face_points(sub, fh);
      points += 0.5 * std::abs(signed_area2(p[0], p[1], p[2])) / equilateral_cell(h);
    }
  for (auto eh : sub.edges())
    if (!sub.status(eh).deleted() && is_constrained(sub, eh)) {
      const auto heh = sub.halfedge_handle(eh, 0);
      points += (point2(sub, sub.to_vertex_handle(heh)) - point2(sub, sub.from_vertex_handle(heh))).norm() / h;
    }
  if (!(points <= 8.0 * static_cast<double>(vertices) + 128.0)) return false;
  bool removed = false;
  for (int pass = 0; pass < 2; ++pass)
    for (auto vh : sub.vertices())
      if (!sub.status(vh).deleted() && !is_input(sub, vh)) removed = remove_vertex(sub, vh) || removed;
  if (!removed) return false;
  std::mt19937 rng(seed);
  // (The walls once: dividing the segments adds pieces on the same lines, at the same distances.)
  const std::vector<Wall> walls = region_walls(sub);
  const Spacing spacing(sub, walls, h);
  divide_segments(sub, spacing);
  if (!scatter_interior(sub, spacing, walls, rng, 8.0 * static_cast<double>(vertices) + 128.0)) return false;
  make_delaunay(sub);
  lloyd_sweeps(sub, spacing, 4);
  return true;
}

}  // namespace acute::detail
