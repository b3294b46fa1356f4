#include "repair/polar_fan.h"

#include "repair/local_remesh.h"

#include <acute/mesh/geometry.h>
#include <acute/mesh/quality.h>
#include <acute/mesh/sectors.h>
#include <acute/ops/delaunay_flips.h>
#include <acute/ops/insert.h>
#include <acute/ops/remove.h>

#include <algorithm>
#include <cmath>

namespace acute::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The mesh's wall spacing at the fan's radius may be at most this many lattice steps (la's
/// 4-degree hub, where a nearby segment keeps the disk small: 39; fans that help: up to about 6).
constexpr double kMaxSpacingRatio = 8;

double distance_to_edge(const Point2& c, const Point2& a, const Point2& b) {
  const Point2 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((c - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (a + t * d - c).norm();
}

bool is_wall(const Mesh& mesh, HalfedgeHandle spoke) { return is_constrained(mesh, mesh.edge_handle(spoke)); }

struct FanSector {
  Point2 u0;         ///< direction of the wall it begins at, counter-clockwise
  double angle = 0;  ///< radians
};

/// The sectors at vh between consecutive walls; empty when a fan is partial (a region border) or
/// vh has fewer than two walls. Directions, not handles: the fan's rebuild removes wall vertices.
std::vector<FanSector> wall_sectors(const Mesh& mesh, VertexHandle vh) {
  bool partial = false;
  std::vector<FanSector> out;
  for (const SegmentSector& s : segment_sectors(mesh, vh, &partial))
    out.push_back(FanSector{(point2(mesh, mesh.to_vertex_handle(s.first)) - point2(mesh, vh)).normalized(), s.radians});
  if (partial) return {};  // (one wall alone sweeps round to itself: partial too)
  return out;
}

}  // namespace

std::vector<SharpCorner> find_sharp_corners(const Mesh& mesh, double max_sector) {
  std::vector<SharpCorner> out;
  for (auto apex : mesh.vertices()) {
    if (mesh.status(apex).deleted() || !is_input(mesh, apex)) continue;
    const std::vector<FanSector> sectors = wall_sectors(mesh, apex);
    if (sectors.empty()) continue;
    double narrowest = INFINITY;
    for (const FanSector& s : sectors) narrowest = std::min(narrowest, s.angle);
    if (!(narrowest < max_sector) || narrowest <= 0) continue;
    const double g = wedge_growth(narrowest);
    const Point2 c = point2(mesh, apex);
    double radius = INFINITY;
    std::vector<int> wall_segments;
    std::vector<std::pair<double, double>> wall_edges;  // (r_from, r_to) of every wall edge walked
    for (auto spoke : mesh.voh_range(apex)) {
      if (!is_wall(mesh, spoke)) continue;
      const int segment = mesh.data(mesh.edge_handle(spoke)).segment;
      wall_segments.push_back(segment);
      // Walk the wall outwards to its far input vertex. The fan reaches where its radial step
      // catches up with the wall's own spacing (or half way to the far end).
      HalfedgeHandle h = spoke;
      bool spaced = false;
      for (int guard = 0; guard < 100000; ++guard) {
        const VertexHandle from = mesh.from_vertex_handle(h), to = mesh.to_vertex_handle(h);
        const double r_from = (point2(mesh, from) - c).norm(), r_to = (point2(mesh, to) - c).norm();
        // (An edge up to an input vertex says nothing of the mesh's spacing: in a given mesh of
        // `acute repair` every wall edge is one.)
        if (!is_input(mesh, to)) wall_edges.emplace_back(r_from, r_to);
        if (!spaced && r_from > 0 && r_from * (g - 1) >= r_to - r_from) {
          radius = std::min(radius, r_from);
          spaced = true;
        }
        if (is_input(mesh, to)) {
          radius = std::min(radius, 0.5 * r_to);
          break;
        }
        HalfedgeHandle next;
        for (auto out_h : mesh.voh_range(to))
          if (mesh.to_vertex_handle(out_h) != from && mesh.data(mesh.edge_handle(out_h)).segment == segment) next = out_h;
        if (!next.is_valid()) break;
        h = next;
      }
    }
    if (!std::isfinite(radius)) continue;
    // Every other feature stays well outside the disk: segments not at the apex, input vertices.
    for (bool shrunk = true; shrunk;) {
      shrunk = false;
      std::vector<VertexHandle> disk = vertices_near(mesh, apex, radius);
      disk.push_back(apex);
      for (auto v : disk)
        for (auto fh : mesh.vf_range(v))
          for (auto heh : mesh.fh_range(fh)) {
            const EdgeHandle eh = mesh.edge_handle(heh);
            const VertexHandle a = mesh.from_vertex_handle(heh), b = mesh.to_vertex_handle(heh);
            double d = INFINITY;
            if (is_input(mesh, a) && a != apex) d = (point2(mesh, a) - c).norm();
            if ((is_constrained(mesh, eh) || mesh.is_boundary(eh)) && a != apex && b != apex &&
                std::find(wall_segments.begin(), wall_segments.end(), mesh.data(eh).segment) == wall_segments.end())
              d = std::min(d, distance_to_edge(c, point2(mesh, a), point2(mesh, b)));
            if (0.7 * d < radius) radius = 0.7 * d, shrunk = true;
          }
    }
    // Where another feature keeps the disk small, the lattice's outer ring is much finer than the
    // mesh around it, and no smoothing blends the two (la's 4-degree hub: 39 times finer).
    double spacing = INFINITY;
    for (const auto& [r_from, r_to] : wall_edges)
      if (r_from < radius && radius <= r_to) spacing = std::min(spacing, r_to - r_from);
    if (std::isfinite(spacing) && spacing > kMaxSpacingRatio * radius * (g - 1)) continue;
    if (vertices_near(mesh, apex, radius).empty()) continue;
    out.push_back(SharpCorner{apex, radius, narrowest});
  }
  return out;
}

double apex_gap_floor(double max_angle) {
  constexpr double kMargin = 1.05;  // at max 85: gaps of 10.5 degrees or more, base angles at most 84.75
  return kMargin * std::max(0.0, narrowest_feasible_corner(max_angle));
}

bool build_polar_fan(Mesh& sub, VertexHandle apex, double radius, int rings, double max_angle) {
  const std::vector<FanSector> sectors = wall_sectors(sub, apex);
  if (sectors.empty() || rings < 2) return false;
  double narrowest = INFINITY;
  for (const FanSector& s : sectors) narrowest = std::min(narrowest, s.angle);
  const double g = wedge_growth(narrowest), gap_floor = apex_gap_floor(max_angle);
  const Point2 c = point2(sub, apex);

  std::vector<VertexHandle> doomed;
  for (auto vh : sub.vertices())
    if (!sub.status(vh).deleted() && !is_input(sub, vh) && (point2(sub, vh) - c).norm() < radius) doomed.push_back(vh);
  if (doomed.empty()) return false;
  if (!remove_vertices(sub, doomed)) return false;

  // Radii of the even rays (walls included), a[0] < a[1] < ..., and of the odd rays, b[k] between
  // a[k] and a[k + 1]: a log-polar lattice from a[1] outwards, the outermost a step short of the
  // radius. The innermost even ring is closer in: the triangle on the chord a[0] a[0]' (the apex
  // triangle's base) and b[0] is then acute, its base angles half of what the apex triangle leaves.
  const auto K = static_cast<std::size_t>(rings);
  std::vector<double> a(K), b(K - 1);
  a[K - 1] = radius / g;
  for (std::size_t k = K - 1; k-- > 1;) a[k] = a[k + 1] / g;
  for (std::size_t k = 0; k + 1 < K; ++k) b[k] = a[k + 1] / std::sqrt(g);
  a[0] = b[0] / (std::cos(0.5 * narrowest) + std::sin(0.5 * narrowest) * std::tan(0.25 * kPi + 0.25 * narrowest));

  // Wall points, outermost first: each split shortens the wall's spoke at the apex.
  std::vector<HalfedgeHandle> walls;
  for (auto spoke : sub.voh_range(apex))
    if (is_wall(sub, spoke)) walls.push_back(spoke);
  std::vector<Point2> directions;
  for (HalfedgeHandle spoke : walls) directions.push_back((point2(sub, sub.to_vertex_handle(spoke)) - c).normalized());
  for (std::size_t w = 0; w < walls.size(); ++w) {
    HalfedgeHandle spoke = walls[w];
    const Point2 u = directions[w];
    for (std::size_t k = a.size(); k-- > 0;) {
      if ((point2(sub, sub.to_vertex_handle(spoke)) - c).norm() <= a[k]) continue;
      const VertexHandle m = split_edge(sub, sub.edge_handle(spoke), c + a[k] * u);
      if (!m.is_valid()) return false;
      spoke = sub.find_halfedge(apex, m);
      if (!spoke.is_valid()) return false;
    }
  }
  // Rays inside each sector: alternately at the radii (even) and at their geometric midpoints (odd).
  // Each point is located from the faces of the one before (its neighbour on the ray or across the
  // gap), then from the apex: walking from the apex every time crossed the whole fan, quadratic in
  // its points where a wide sector beside a very narrow one gets thousands.
  VertexHandle last;
  auto insert = [&](const Point2& q) {
    const VertexHandle vh = insert_point_after(sub, q, last, apex);
    if (vh.is_valid()) last = vh;
    return vh.is_valid();
  };
  for (const FanSector& s : sectors) {
    const Point2 u0 = s.u0;
    // The apex triangles' base angles are (pi - gap) / 2: below the max bound only for gaps wider
    // than pi - 2 max. Rounding gives gaps down to 3/4 of the narrowest sector (a sector of 16.5
    // degrees beside one of 11: two of 8.25, base angles 85.9); fewer and wider ones where a max
    // bound below 90 needs it (the narrowest sector's own apex triangle is forced).
    int gaps = std::max(1, static_cast<int>(std::lround(s.angle / narrowest)));
    while (gaps > 1 && s.angle / gaps < gap_floor) --gaps;
    const double step = 0.5 * s.angle / gaps;
    const double psi0 = std::atan2(u0.y(), u0.x());
    for (int j = 1; j < 2 * gaps; ++j) {
      const Point2 dir(std::cos(psi0 + j * step), std::sin(psi0 + j * step));
      for (double rho : j % 2 == 0 ? a : b)
        if (!insert(c + rho * dir)) return false;
    }
  }
  make_delaunay(sub);
  return true;
}

}  // namespace acute::detail
