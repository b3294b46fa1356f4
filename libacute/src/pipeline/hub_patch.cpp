#include "pipeline/hub_patch.h"

#include <acute/mesh/geometry.h>
#include <acute/mesh/sectors.h>
#include <acute/mesh/segments.h>
#include <acute/ops/insert.h>
#include <acute/ops/remove.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace acute::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
/// The patch's inner radius (the hub's apex triangles) is its outer radius over e^kLogDepth. The
/// patch is denser than the mesh around it (its strips grade out into the wide sectors): la at 2k
/// kept 3,200 -> 3,533 vertices at 0.6 (depth 1.1 before it), 3,443 at 0.45 (with kWallShare 0.6).
constexpr double kLogDepth = 0.45;
/// The log-polar mesh reaches this much further out; its points there are dropped: its outer
/// corners (where the walls meet its outer side at right angles) are then no constraint.
constexpr double kLogOverhang = 0.3;
/// A strip's head point is this many strip heights past its inner side: its triangle on the apex
/// triangle's base then has angles of 50, 50 and 80 degrees.
constexpr double kHeadDepth = 0.6;
/// Of the distance to the nearest feature not at the hub, and of the shortest wall.
constexpr double kFeatureShare = 0.6, kWallShare = 0.6;
/// Largest triangle of the log-polar mesh (radians): the exp map bends a chord of angle a by a / 2.
constexpr double kMaxLogSize = 0.35;
/// The patch's outer triangles at most this many times the mesh's spacing around it.
constexpr double kMaxSeamRatio = 2.0;
/// The patch reaches this much past its strips' apex triangles where the other limits allow...
constexpr double kPastStripApexes = 1.1;
/// (at least this much past them, or not at all)
constexpr double kAtLeastPast = 1.02;
/// ... and then keeps at least this share of the distance to other features and of the walls.
constexpr double kFarShare = 0.9;
/// A patch clears the disk of this many times its radius (its margin blends with the mesh)...
constexpr double kClearMargin = 1.05;
/// ... and two patches' cleared disks keep this share of the distance between their hubs.
constexpr double kHubGap = 0.95;
/// At most this many hubs are patched (each costs a copy of the mesh).
constexpr int kMaxHubs = 16;
/// The most edges a wall's seam is cut into (append_seam_radii).
constexpr int kMaxSeamEdges = 4096;

struct Wall {
  Point2 u;          ///< direction from the hub
  double phi = 0;    ///< angle from the first wall, counter-clockwise
  double length = 0; ///< to the segment's far end
  double first = 0;  ///< to the mesh's first vertex along it, when planned
};

struct HubPlan {
  VertexHandle hub;
  std::vector<Wall> walls;  ///< counter-clockwise, from phi = 0
  /// Round a full fan: the widest sector, from the last wall to the first; the log-polar domain is
  /// cut open in its middle. 0 at a boundary hub.
  double cut_width = 0;
  double narrowest = 0;
  double radius = 0;
  double cap = 0;  ///< the farthest it may reach past its strips' apex triangles
  bool patched = false;
};

/// The hub's walls in counter-clockwise order, or empty when vh is no strip hub.
bool plan_walls(const Mesh& mesh, VertexHandle vh, double strip_below, HubPlan& plan) {
  bool partial = false;
  const std::vector<SegmentSector> sectors = segment_sectors(mesh, vh, &partial);
  if (partial || sectors.size() < 2) return false;
  double narrowest = INFINITY, widest = 0;
  for (const SegmentSector& s : sectors) narrowest = std::min(narrowest, s.radians), widest = std::max(widest, s.radians);
  // (A hub whose widest sector holds one triangle at the apex, below twice the min bound, is
  // patched too: its strips' apex triangles and the grading beside them are the same problem.)
  if (!(narrowest < strip_below) || !(widest >= strip_below)) return false;
  // Chain the sectors: start at one no other sector ends at (a boundary hub); round a full fan,
  // start after the widest sector, where the log-polar domain is cut open.
  std::size_t start = sectors.size();
  for (std::size_t i = 0; i < sectors.size(); ++i) {
    bool ends_here = false;
    for (const SegmentSector& t : sectors) ends_here = ends_here || t.last == sectors[i].first;
    if (!ends_here) start = i;
  }
  const bool full = start == sectors.size();
  if (full) {
    std::size_t widest_i = 0;
    for (std::size_t i = 0; i < sectors.size(); ++i)
      if (sectors[i].radians > sectors[widest_i].radians) widest_i = i;
    for (std::size_t j = 0; j < sectors.size(); ++j)
      if (sectors[j].first == sectors[widest_i].last) start = j;
    if (start == sectors.size()) return false;
    plan.cut_width = widest;
  }
  const Point2 c = point2(mesh, vh);
  auto wall_of = [&](HalfedgeHandle spoke, double phi) {
    const auto& ends = segment_endpoints(mesh, mesh.data(mesh.edge_handle(spoke)).segment);
    const Point2 far = (ends[0] - c).squaredNorm() > (ends[1] - c).squaredNorm() ? ends[0] : ends[1];
    return Wall{(far - c).normalized(), phi, (far - c).norm(), (point2(mesh, mesh.to_vertex_handle(spoke)) - c).norm()};
  };
  plan.walls.clear();
  std::size_t i = start;
  double phi = 0;
  plan.walls.push_back(wall_of(sectors[i].first, 0));
  // A full fan's last sector (the widest) closes back on the first wall: not listed twice.
  for (std::size_t n = 0; n + (full ? 1 : 0) < sectors.size(); ++n) {
    phi += sectors[i].radians;
    plan.walls.push_back(wall_of(sectors[i].last, phi));
    std::size_t next = sectors.size();
    for (std::size_t j = 0; j < sectors.size(); ++j)
      if (sectors[j].first == sectors[i].last) next = j;
    if (next == sectors.size()) break;
    i = next;
  }
  if (plan.walls.size() != (full ? sectors.size() : sectors.size() + 1)) return false;
  plan.hub = vh;
  plan.narrowest = narrowest;
  return true;
}

/// The typical edge length of the mesh between radius and 2 radius from the hub: the median by
/// area (each edge weighted by its squared length). A plain median counts edges, and the fine
/// mesh along a needle strip's walls has most of them: around a 0.18-degree strip it was 0.29
/// where the rest of the annulus is 15-20 across, and the patch made that fine met the coarse
/// mesh in a seam of 88 obtuse triangles.
double spacing_around(const Mesh& mesh, VertexHandle hub, double radius) {
  const Point2 c = point2(mesh, hub);
  std::vector<double> lengths;
  double total = 0;  // of the squared lengths
  for (auto v : vertices_near(mesh, hub, 2 * radius))
    for (auto w : mesh.vv_range(v)) {
      const Point2 m = 0.5 * (point2(mesh, v) + point2(mesh, w));
      const double r = (m - c).norm();
      if (r > radius && r < 2 * radius) {
        lengths.push_back((point2(mesh, w) - point2(mesh, v)).norm());
        total += lengths.back() * lengths.back();
      }
    }
  if (lengths.empty()) return 0;
  std::sort(lengths.begin(), lengths.end());
  double below = 0;
  for (const double l : lengths)
    if ((below += l * l) >= 0.5 * total) return l;
  return lengths.back();
}

/// The wall's radii in the seam, between the patch's outermost wall vertex (radii sorted from the
/// outermost) and the mesh's first vertex left beyond the cleared disk (the spoke's far end): the
/// clearing margin took the wall's vertices there, and along a strip that gap is many strip widths
/// long (a 0.044-degree strip of a CG:SHOP example: 86 against 1.3; the repair stalled at 34 bad
/// triangles beside the one wall edge). Edges from the patch's last wall edge to the mesh's next one
/// beyond, their lengths in arithmetic progression; none where the gap is no longer than them.
void append_seam_radii(const Mesh& mesh, HalfedgeHandle spoke, std::vector<double>& radii) {
  if (radii.empty()) return;
  const VertexHandle hub = mesh.from_vertex_handle(spoke), far = mesh.to_vertex_handle(spoke);
  const Point2 c = point2(mesh, hub), f = point2(mesh, far);
  const double outer = radii.front(), gap = (f - c).norm() - outer;
  const double near_edge = outer - (radii.size() > 1 ? radii[1] : 0.0);
  // The wall's next edge beyond the far vertex (same segment, away from the hub), else the near one.
  double far_edge = near_edge;
  const int segment = mesh.data(mesh.edge_handle(spoke)).segment;
  for (auto h : mesh.voh_range(far)) {
    const VertexHandle w = mesh.to_vertex_handle(h);
    if (w == hub || mesh.data(mesh.edge_handle(h)).segment != segment) continue;
    if ((point2(mesh, w) - c).norm() > (f - c).norm()) far_edge = (point2(mesh, w) - f).norm();
  }
  if (!(near_edge > 0) || !(gap > 0)) return;
  // (At most kMaxSeamEdges: a needle strip's wall edges at the seam can be 1e-5 of the gap.)
  const int n = static_cast<int>(std::min<double>(std::round(2.0 * gap / (near_edge + far_edge)), kMaxSeamEdges));
  if (n < 2) return;
  const double total = 0.5 * n * (near_edge + far_edge);  // the progression's sum
  double r = outer;
  for (int k = 0; k + 1 < n; ++k) {
    r += gap * (near_edge + (far_edge - near_edge) * (k + 0.5) / n) / total;
    radii.push_back(r);
  }
}

bool insert_patch(Mesh& mesh, const HubPlan& plan, const Mesh& log_mesh, double s_inner) {
  const Point2 c = point2(mesh, plan.hub);
  const std::size_t walls = plan.walls.size();
  const double tol = 1e-12 * 2 * kPi;
  // Round a full fan, the cut's second side (y = the cut + 2 pi) is its first one again.
  const double cut_again = plan.walls.back().phi + 0.5 * plan.cut_width;
  std::vector<std::vector<double>> wall_radii(walls);
  std::vector<std::pair<double, double>> free_points;  // (phi, s)
  for (auto v : log_mesh.vertices()) {
    if (log_mesh.status(v).deleted()) continue;
    const Point2 q = point2(log_mesh, v);
    if (q.x() > kLogDepth) continue;
    const double s = s_inner + q.x(), phi = q.y();
    bool on_wall = false;
    if (log_mesh.data(v).kind != VertexKind::Free) {
      for (std::size_t i = 0; i < walls; ++i)
        if (std::abs(phi - plan.walls[i].phi) <= tol) {
          on_wall = true;
          wall_radii[i].push_back(std::exp(s));
        }
      if (plan.cut_width > 0 && std::abs(phi - cut_again) <= tol) continue;
    }
    if (!on_wall) free_points.emplace_back(phi, s);
  }
  // Wall points, outermost first: each split shortens the wall's spoke at the hub.
  for (std::size_t i = 0; i < walls; ++i) {
    const Point2 u = plan.walls[i].u;
    std::sort(wall_radii[i].rbegin(), wall_radii[i].rend());
    HalfedgeHandle spoke = segment_spoke_along(mesh, plan.hub, u);
    if (!spoke.is_valid()) return false;
    append_seam_radii(mesh, spoke, wall_radii[i]);
    std::sort(wall_radii[i].rbegin(), wall_radii[i].rend());
    for (double r : wall_radii[i]) {
      if ((point2(mesh, mesh.to_vertex_handle(spoke)) - c).norm() <= r) return false;
      const VertexHandle m = split_edge(mesh, mesh.edge_handle(spoke), c + r * u);
      if (!m.is_valid()) return false;
      spoke = mesh.find_halfedge(plan.hub, m);
      if (!spoke.is_valid()) return false;
    }
  }
  std::sort(free_points.begin(), free_points.end());
  const double phi0 = std::atan2(plan.walls[0].u.y(), plan.walls[0].u.x());
  VertexHandle last;
  for (const auto& [phi, s] : free_points) {
    const Point2 q = c + std::exp(s) * Point2(std::cos(phi0 + phi), std::sin(phi0 + phi));
    const VertexHandle vh = insert_point_after(mesh, q, last, plan.hub);
    if (!vh.is_valid()) return false;
    last = vh;
  }
  return true;  // (every insertion and split restores the Delaunay property around it)
}

/// An acute mesh of the log-polar domain, its overhang (x > kLogDepth) excepted. The repair is
/// sometimes slow on the right-angled corners where the walls meet the inner side; a fresh seed
/// usually is not: a few attempts of at most kAttemptIterations repair iterations each (a
/// successful one takes 10-20 and some 0.05-0.5 s; a stuck one 0.2 s per iteration). No attempt
/// runs under a clock, so a patch is the same with or without a time limit and on any machine
/// (a clock-cut CVT made runs under --time-limit differ by a few patch vertices, and sometimes
/// fail); past the `deadline` no attempt starts.
bool mesh_log_domain(const Domain& domain, MeshOptions options, unsigned seed, std::chrono::steady_clock::time_point deadline, Mesh& out) {
  constexpr int kAttempts = 3;
  constexpr int kAttemptIterations = 25;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    options.seed = seed + static_cast<unsigned>(attempt);
    options.max_iterations = kAttemptIterations;
    options.time_limit_s = 0;
    MeshResult r;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      r = generate_mesh(domain, options);
    } catch (const std::exception&) {
      return false;
    }
    bool usable = r.status == MeshStatus::Ok || r.remaining.size() < 100;
    for (const BadTriangle& t : r.remaining) usable = usable && std::max({t.corners[0].x(), t.corners[1].x(), t.corners[2].x()}) > kLogDepth;
    if (std::getenv("ACUTE_TRACE"))
      std::fprintf(stderr, "  log-polar mesh, seed %u: %zu vertices, %zu bad, %d iterations, %.2f s%s\n", options.seed, r.mesh.n_vertices(), r.remaining.size(),
                   r.iterations, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), usable ? "" : " (not usable)");
    if (usable) {
      out = std::move(r.mesh);
      return true;
    }
  }
  return false;
}

}  // namespace

std::vector<Point2> patch_strip_hubs(Mesh& mesh, const MeshOptions& options, double seconds) {
  const double strip_below = options.min_angle_deg * kPi / 180;
  if (!(strip_below > 0)) return {};
  const bool trace = std::getenv("ACUTE_TRACE") != nullptr;
  const auto deadline = seconds > 0 ? std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                                              std::chrono::duration<double>(seconds))
                                    : std::chrono::steady_clock::time_point::max();
  std::vector<HubPlan> plans;
  std::vector<Point2> input_points;  // features too, on a segment or not (collected once: no O(n) pass per hub)
  for (auto v : mesh.vertices())
    if (!mesh.status(v).deleted() && is_input(mesh, v)) input_points.push_back(point2(mesh, v));
  // The narrowest strips first: when there are more than kMaxHubs, they are the ones patched.
  std::vector<HubPlan> candidates;
  for (auto vh : mesh.vertices()) {
    if (mesh.status(vh).deleted() || !is_input(mesh, vh)) continue;
    HubPlan plan;
    if (plan_walls(mesh, vh, strip_below, plan)) candidates.push_back(std::move(plan));
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const HubPlan& a, const HubPlan& b) { return a.narrowest < b.narrowest; });
  for (HubPlan& plan : candidates) {
    const Point2 c = point2(mesh, plan.hub);
    double radius = INFINITY;
    for (const Wall& w : plan.walls) radius = std::min(radius, kWallShare * w.length);
    for (const auto& ends : segment_table(mesh))
      if (ends[0] != c && ends[1] != c) radius = std::min(radius, kFeatureShare * distance_to_segment(c, ends[0], ends[1]));
    // Input points on no segment are features too (a CG:SHOP instance's point 83 from a hub: the
    // patch, 530 wide, was meshed through it).
    for (const Point2& q : input_points)
      if (q != c) radius = std::min(radius, kFeatureShare * (q - c).norm());
    if (!(radius > 0) || !std::isfinite(radius)) continue;
    plan.radius = radius;
    // The walls' and other features' limit for reaching past the strips' apex triangles: nearer
    // to them than the usual share, but still short of them.
    static_assert(kWallShare == kFeatureShare, "the cap scales both shares");
    plan.cap = radius * kFarShare / kFeatureShare;
    plans.push_back(std::move(plan));
    if (static_cast<int>(plans.size()) >= kMaxHubs) break;
  }
  std::vector<Point2> patched;
  const std::size_t vertices_before = mesh.n_vertices();
  for (HubPlan& plan : plans) {
    double spacing = spacing_around(mesh, plan.hub, plan.radius);
    if (!(spacing > 0)) continue;
    // The log-polar mesh's triangles at its outer side are at least floor_size (in the log
    // domain) across, r floor_size physically: on a fine mesh that is many times its spacing there,
    // and the seam then leaves hundreds of bad triangles for the repair to grind through (clusters
    // at 200k vertices: 16 times, 18 slow repair iterations). The disk shrinks until its outer
    // triangles are at most kMaxSeamRatio times the spacing around it (its strips are then as wide
    // as the mesh's triangles there, which the size field resolves).
    const double floor_size = std::min(2 * plan.narrowest, kMaxLogSize);
    for (int k = 0; k < 3; ++k) {
      const double outer = std::clamp(spacing / plan.radius, floor_size, kMaxLogSize);
      if (outer * plan.radius <= kMaxSeamRatio * spacing) break;
      plan.radius = kMaxSeamRatio * spacing / outer;
      spacing = spacing_around(mesh, plan.hub, plan.radius);
      if (!(spacing > 0)) break;
    }
    if (!(spacing > 0)) continue;
    // The CVT start cuts a strip's walls where the strip is as wide as the size there, which can
    // be beyond the seam's radius: the wall edge left between the patch and that first vertex is
    // a sliver as wide as the strip, beside the coarse mesh of the apex triangle's wide side, that
    // the repair cannot grade (a 0.27-degree strip of a CG:SHOP instance: 23 obtuse triangles).
    // The patch then reaches past the strips' apex triangles, where the walls and features allow.
    double strip_apexes = 0;
    for (std::size_t i = 0; i + 1 < plan.walls.size(); ++i)
      if (plan.walls[i + 1].phi - plan.walls[i].phi < strip_below) strip_apexes = std::max({strip_apexes, plan.walls[i].first, plan.walls[i + 1].first});
    if (const double past = std::min(kPastStripApexes * strip_apexes, plan.cap); past > plan.radius && past > kAtLeastPast * strip_apexes) {
      plan.radius = past;
      spacing = spacing_around(mesh, plan.hub, plan.radius);
      if (!(spacing > 0)) continue;
    }
    // Two hubs' disks (with the margins they clear) must not overlap: the second patch would
    // remove part of the first (a CG:SHOP instance's hubs 200 apart had patches of 120 each). Nor
    // may the first take the gap: a hub still to come keeps up to half of it. (Squeezed to half
    // its radius, a patch ends inside its strips, short of their apex triangles, and the repair
    // stalls at that seam: 15 obtuse triangles on a 0.18-degree strip 200 from a 6-degree one.)
    double room = plan.radius;
    for (const HubPlan& other : plans) {
      const bool before = &other < &plan;  // planned before: patched with its radius, or not at all
      if (&other == &plan || (before && !other.patched)) continue;
      const double gap = kHubGap * (point2(mesh, plan.hub) - point2(mesh, other.hub)).norm() / kClearMargin;
      room = std::min(room, gap - (before ? other.radius : std::min(other.radius, 0.5 * gap)));
    }
    if (room < plan.radius) {
      if (!(room > 0)) continue;
      plan.radius = room;
      spacing = spacing_around(mesh, plan.hub, plan.radius);
      if (!(spacing > 0)) continue;
    }
    // The log-polar domain: x = ln(r / r_inner), y = phi. The walls are its horizontal segments
    // from the inner side x = 0 (the apex triangles' bases) to x = kLogDepth (the patch's radius);
    // the two outermost lines reach on over the overhang to its outer side.
    Domain log_domain;
    std::vector<double> lines;  // the walls' y, and round a full fan the cut's two sides
    for (const Wall& w : plan.walls) lines.push_back(w.phi);
    if (plan.cut_width > 0) {
      lines.insert(lines.begin(), -0.5 * plan.cut_width);
      lines.push_back(plan.walls.back().phi + 0.5 * plan.cut_width);
    }
    const int n = static_cast<int>(lines.size());
    for (double y : lines) log_domain.points.emplace_back(0.0, y);
    for (int i = 0; i < n; ++i)
      log_domain.points.emplace_back(i == 0 || i == n - 1 ? kLogDepth + kLogOverhang : kLogDepth, lines[static_cast<std::size_t>(i)]);
    for (int i = 0; i < n; ++i) log_domain.segments.push_back({i, n + i});
    for (int i = 0; i + 1 < n; ++i) log_domain.segments.push_back({i, i + 1});
    log_domain.segments.push_back({n, 2 * n - 1});
    // Each strip's head: a point on its midline past its inner side, where the apex triangle's
    // base and the two right-angled corners beside it need one (the repair is slow to find it).
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
      const double h = lines[i + 1] - lines[i];
      if (h < strip_below) log_domain.points.emplace_back(kHeadDepth * h, lines[i] + 0.5 * h);
    }
    log_domain.point_markers.assign(log_domain.points.size(), 0);
    log_domain.segment_markers.assign(log_domain.segments.size(), 0);
    log_domain.name = "hub patch";
    MeshOptions lo;
    lo.method = Method::Acute;
    lo.min_angle_deg = options.min_angle_deg + 2;
    lo.max_angle_deg = options.max_angle_deg - 3;
    lo.gradation = options.gradation;
    // The physical size r h(x) at most the mesh's spacing around the disk: h <= (spacing / R) e^(kLogDepth - x),
    // so the patch grades toward the hub only where its strips need it (a uniform spacing / R tripled
    // the vertices of la's disks). Never below twice the narrowest strip, never above kMaxLogSize.
    const double outer_size = spacing / plan.radius;
    lo.max_size = kMaxLogSize;
    lo.size_cap = [outer_size, floor_size](const Point2& q) { return std::clamp(outer_size * std::exp(kLogDepth - q.x()), floor_size, kMaxLogSize); };
    Mesh log_mesh;
    if (!mesh_log_domain(log_domain, lo, options.seed, deadline, log_mesh)) {
      if (trace) std::fprintf(stderr, "hub patch (%.6g, %.6g): no acute log-polar mesh, hub left as it was\n", point2(mesh, plan.hub).x(), point2(mesh, plan.hub).y());
      continue;
    }
    if (trace) {
      std::fprintf(stderr, "hub patch (%.6g, %.6g): radius %.4g, spacing %.4g, log size %.4g at its outer side, %zu log vertices; sectors (degrees)", point2(mesh, plan.hub).x(),
                   point2(mesh, plan.hub).y(), plan.radius, spacing, std::clamp(outer_size, floor_size, kMaxLogSize), log_mesh.n_vertices());
      for (std::size_t i = 0; i + 1 < lines.size(); ++i) std::fprintf(stderr, " %.3g", (lines[i + 1] - lines[i]) * 180 / kPi);
      std::fprintf(stderr, "\n");
    }
    Mesh backup = mesh;
    const std::vector<VertexHandle> doomed = vertices_near(mesh, plan.hub, kClearMargin * plan.radius);
    if (!remove_vertices(mesh, doomed) || !insert_patch(mesh, plan, log_mesh, std::log(plan.radius) - kLogDepth)) {
      if (trace) std::fprintf(stderr, "hub patch: insertion failed, hub left as it was\n");
      mesh = std::move(backup);
      continue;
    }
    patched.push_back(point2(mesh, plan.hub));
    plan.patched = true;
  }
  if (!patched.empty()) collect_garbage(mesh);
  if (trace && !plans.empty()) std::fprintf(stderr, "hub patches: %zu of %zu hubs, %zu vertices before, %zu after\n", patched.size(), plans.size(), vertices_before, mesh.n_vertices());
  return patched;
}

}  // namespace acute::detail
