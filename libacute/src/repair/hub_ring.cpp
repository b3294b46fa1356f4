#include "repair/hub_ring.h"

#include "repair/polar_fan.h"

#include <acute/mesh/geometry.h>
#include <acute/mesh/sectors.h>
#include <acute/ops/delaunay_flips.h>
#include <acute/ops/insert.h>
#include <acute/ops/remove.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace acute::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Each gap of the ring is this much wider than the one before it (from either wall).
constexpr double kGapGrowth = 1.6;
/// The first gap from a strip's wall, in strip angles: its chord then matches the strip's triangles.
constexpr double kFirstGapStrips = 1.5;
/// The first gap from a wall with no strip across it, and the widest gap (radians).
constexpr double kWideGap = 0.5;

/// The angle of the sector across the wall spoke `wall` from `sector` (the one that ends or begins
/// at it), or 0 when there is none (a boundary wall, a partial fan).
double across(const std::vector<SegmentSector>& sectors, const SegmentSector& sector, HalfedgeHandle wall) {
  for (const SegmentSector& s : sectors) {
    if (&s == &sector) continue;
    if (s.first == wall || s.last == wall) return s.radians;
  }
  return 0;
}

/// The strips across a wide sector's two walls: their angles (0 where there is none, or where the
/// sector across is no strip). A sector is ringed when it is no strip and has one across a wall.
struct StripsAcross {
  double first = 0, last = 0;
  bool any() const { return first > 0 || last > 0; }
};

StripsAcross strips_across(const std::vector<SegmentSector>& sectors, const SegmentSector& sector, double strip_below) {
  StripsAcross out;
  if (sector.radians < strip_below) return out;
  const double a = across(sectors, sector, sector.first), b = across(sectors, sector, sector.last);
  if (a < strip_below) out.first = a;
  if (b < strip_below) out.last = b;
  return out;
}

/// Distance from the apex to the first vertex along a wall spoke.
double first_radius(const Mesh& mesh, HalfedgeHandle spoke) {
  return (point2(mesh, mesh.to_vertex_handle(spoke)) - point2(mesh, mesh.from_vertex_handle(spoke))).norm();
}

/// The disk a ring rebuilds reaches this far beyond its walls' first vertices.
constexpr double kReach = 1.1;

/// Moves the first vertex of the wall along u out to radius r: the movable vertices on the wall
/// nearer than that go and one is put at r. False when an input vertex is nearer or an edit failed.
bool push_wall_out(Mesh& sub, VertexHandle apex, const Point2& u, double r) {
  const Point2 c = point2(sub, apex);
  for (;;) {
    const HalfedgeHandle spoke = segment_spoke_along(sub, apex, u);
    if (!spoke.is_valid()) return false;
    const VertexHandle first = sub.to_vertex_handle(spoke);
    const double r_first = first_radius(sub, spoke);
    if (r_first >= r * (1 - 1e-9)) return r_first <= r * (1 + 1e-9) || split_edge(sub, sub.edge_handle(spoke), c + r * u).is_valid();
    if (is_input(sub, first) || !remove_vertex(sub, first)) return false;
  }
}

/// The walls (unit directions from the apex) to move out to the strips' radius around each ringed
/// sector. A ring's thin apex triangles are Delaunay, as every triangle of a non-obtuse mesh is,
/// only when their circumcircles, disks about as wide as the ring's radius, hold no vertex: a wall
/// of the sector whose first vertex is nearer than the strip's radius must start there too. So
/// must the far wall of a narrow sector across it (a strip's apex triangle stays isosceles; a
/// sector below one_triangle_below holds one triangle, whose legs must nearly agree), and so on.
std::vector<std::pair<Point2, double>> walls_to_push(const Mesh& sub, VertexHandle apex, const std::vector<SegmentSector>& sectors,
                                                     double strip_below, double one_triangle_below) {
  std::vector<std::pair<Point2, double>> out;
  const Point2 c = point2(sub, apex);
  auto direction = [&](HalfedgeHandle spoke) { return (point2(sub, sub.to_vertex_handle(spoke)) - c).normalized(); };
  std::vector<HalfedgeHandle> done;
  for (const SegmentSector& sector : sectors) {
    const StripsAcross strips = strips_across(sectors, sector, strip_below);
    if (!strips.any()) continue;
    double r = 0;
    if (strips.first > 0) r = std::max(r, first_radius(sub, sector.first));
    if (strips.last > 0) r = std::max(r, first_radius(sub, sector.last));
    // Walk from each wall of the sector across narrow sectors, pushing every wall nearer than r.
    std::vector<std::pair<HalfedgeHandle, const SegmentSector*>> todo{{sector.first, &sector}, {sector.last, &sector}};
    while (!todo.empty()) {
      const auto [wall, from] = todo.back();
      todo.pop_back();
      if (std::find(done.begin(), done.end(), wall) != done.end()) continue;
      done.push_back(wall);
      if (first_radius(sub, wall) < 0.95 * r) out.emplace_back(direction(wall), r);
      for (const SegmentSector& next : sectors)
        if (&next != from && (next.first == wall || next.last == wall) && next.radians < one_triangle_below)
          todo.emplace_back(next.first == wall ? next.last : next.first, &next);
    }
  }
  return out;
}

/// Removes the Steiner points (not on segments) inside the sectors at apex narrower than
/// `narrow_below` and nearer than both of the sector's walls' first vertices: such a sector holds
/// one triangle at the apex (a strip's is isosceles), and a point left inside splits it into
/// slivers. (Clearing the apex triangle's whole circumdisk as well, which a point just beyond the
/// walls' radius can lie in, made two CG:SHOP instances worse: the repair moves such points.)
bool clear_narrow_sectors(Mesh& sub, VertexHandle apex, double narrow_below) {
  const Point2 c = point2(sub, apex);
  std::vector<VertexHandle> doomed;
  for (const SegmentSector& sector : segment_sectors(sub, apex)) {
    if (sector.radians >= narrow_below) continue;
    const Point2 pa = point2(sub, sub.to_vertex_handle(sector.first)), pb = point2(sub, sub.to_vertex_handle(sector.last));
    const double ra = (pa - c).norm(), rb = (pb - c).norm();
    const Point2 ua = (pa - c) / ra, ub = (pb - c) / rb;
    for (auto vh : sub.vertices()) {
      if (sub.status(vh).deleted() || sub.data(vh).kind != VertexKind::Free) continue;
      const Point2 d = point2(sub, vh) - c;
      if (d.norm() < std::min(ra, rb) && ua.x() * d.y() - ua.y() * d.x() > 0 && d.x() * ub.y() - d.y() * ub.x() > 0) doomed.push_back(vh);
    }
  }
  return remove_vertices(sub, doomed);
}

}  // namespace

double hub_ring_reach(const Mesh& mesh, VertexHandle apex, double strip_below) {
  double reach = 0;
  const std::vector<SegmentSector> sectors = segment_sectors(mesh, apex);
  for (const SegmentSector& sector : sectors)
    if (strips_across(sectors, sector, strip_below).any())
      reach = std::max({reach, kReach * first_radius(mesh, sector.first), kReach * first_radius(mesh, sector.last)});
  return reach;
}

// (The CVT start slides wall vertices freely: its strip apex triangles are seldom isosceles.)
bool equalise_strip_apexes(Mesh& sub, VertexHandle apex, double strip_below, bool outward) {
  const Point2 c = point2(sub, apex);
  // One strip per pass, the sectors found afresh: removing a wall vertex re-triangulates the apex's
  // star, so the spokes of a strip found before may be gone (two strips side by side share a wall).
  bool changed = false;
  for (int pass = 0, edited = 1; edited && pass < 64; ++pass) {
    edited = 0;
    for (const SegmentSector& strip : segment_sectors(sub, apex)) {
      if (strip.radians >= strip_below) continue;
      HalfedgeHandle near_spoke = strip.first, far_spoke = strip.last;
      double r_near = first_radius(sub, near_spoke), r_far = first_radius(sub, far_spoke);
      if (r_far < r_near) std::swap(near_spoke, far_spoke), std::swap(r_near, r_far);
      // (Outward, the roles swap: the vertex replaced is the nearer, the radius kept the farther.)
      if (outward) std::swap(near_spoke, far_spoke), std::swap(r_near, r_far);
      const VertexHandle far_vertex = sub.to_vertex_handle(far_spoke);
      const double ratio = outward ? r_near / r_far : r_far / r_near;
      if (is_input(sub, far_vertex) || ratio <= 1 + 1e-9 || (outward && ratio >= 1.5)) continue;
      const Point2 u = (point2(sub, far_vertex) - c) / r_far;
      if (ratio < 1.5) {
        if (!remove_vertex(sub, far_vertex)) return false;
        // The wall's spoke now runs to the next vertex along it.
        far_spoke = segment_spoke_along(sub, apex, u);
        if (!far_spoke.is_valid()) return false;
        if (outward && first_radius(sub, far_spoke) <= r_near * (1 + 1e-9)) return false;  // the next wall vertex is nearer
      }
      // Radii only ever drop (outward: rise) to one already at a wall, so strips sharing walls
      // settle in a few passes.
      if (!split_edge(sub, sub.edge_handle(far_spoke), c + r_near * u).is_valid()) return false;
      changed = true;
      edited = 1;
      break;
    }
  }
  return changed;
}

bool apex_with_middle_point(Mesh& sub, VertexHandle apex, double strip_below, double one_triangle_below, bool outward) {
  equalise_strip_apexes(sub, apex, one_triangle_below, outward);  // (false also when already equal)
  const Point2 c = point2(sub, apex);
  std::vector<Point2> points;
  for (const SegmentSector& sector : segment_sectors(sub, apex)) {
    if (sector.radians < strip_below || sector.radians >= one_triangle_below) continue;
    const VertexHandle a = sub.to_vertex_handle(sector.first), b = sub.to_vertex_handle(sector.last);
    const double ra = first_radius(sub, sector.first), rb = first_radius(sub, sector.last);
    if (std::abs(ra - rb) > 1e-9 * std::max(ra, rb)) continue;  // not equalised (outward, a radius twice another's)
    const double r = 0.5 * (ra + rb);
    const double half = 0.5 * sector.radians;
    const Point2 bisector = ((point2(sub, a) - c).normalized() + (point2(sub, b) - c).normalized()).normalized();
    constexpr double kQuarterPi = 0.78539816339744830962;
    points.push_back(c + r * (std::cos(half) + std::sin(half) * std::tan(kQuarterPi + 0.5 * half)) * bisector);
  }
  bool inserted = false;
  for (const Point2& q : points) {
    const VertexHandle vh = insert_point_from(sub, q, apex);
    inserted = inserted || (vh.is_valid() && !is_input(sub, vh));
  }
  return inserted;
}

std::vector<double> plan_ring_gaps(double sector, double strip_first, double strip_last, double gap_floor) {
  // Gaps from both walls, each side growing, until they fill the sector; then scaled to fit.
  std::vector<double> from_a, from_b;
  std::vector<bool> added_at_a;  // which side each gap was added on, in order
  double next_a = strip_first > 0 ? kFirstGapStrips * strip_first : kWideGap;
  double next_b = strip_last > 0 ? kFirstGapStrips * strip_last : kWideGap;
  double total = 0;
  while (total < sector) {
    added_at_a.push_back(next_a <= next_b);
    if (next_a <= next_b) {
      from_a.push_back(next_a), total += next_a, next_a = std::min(next_a * kGapGrowth, kWideGap);
    } else {
      from_b.push_back(next_b), total += next_b, next_b = std::min(next_b * kGapGrowth, kWideGap);
    }
  }
  // Scaled to fit, the gaps shrink by up to the last one's share: under a max bound below 90 that
  // can leave apex gaps too narrow for it. The last gaps added go until the narrowest fits (each
  // side's gaps only grow, so the narrowest is a side's first).
  auto narrowest_scaled = [&] {
    const double a = from_a.empty() ? INFINITY : from_a.front(), b = from_b.empty() ? INFINITY : from_b.front();
    return std::min(a, b) * sector / total;
  };
  while (added_at_a.size() > 1 && narrowest_scaled() < gap_floor) {
    std::vector<double>& side = added_at_a.back() ? from_a : from_b;
    total -= side.back();
    side.pop_back();
    added_at_a.pop_back();
  }
  std::vector<double> gaps = from_a;
  gaps.insert(gaps.end(), from_b.rbegin(), from_b.rend());
  for (double& g : gaps) g *= sector / total;
  return gaps;
}

bool rebuild_hub_ring(Mesh& sub, VertexHandle apex, double strip_below, double max_angle) {
  const double gap_floor = apex_gap_floor(max_angle);
  equalise_strip_apexes(sub, apex, strip_below);
  for (const auto& [u, r] : walls_to_push(sub, apex, segment_sectors(sub, apex), strip_below, 2 * strip_below))
    if (!push_wall_out(sub, apex, u, r)) return false;
  if (!clear_narrow_sectors(sub, apex, 2 * strip_below)) return false;
  const Point2 c = point2(sub, apex);
  // Every ring is planned before any edit: the edits re-triangulate the apex's star, so the
  // sectors' spoke handles would not survive them.
  struct RingPlan {
    std::vector<Point2> ring;
    Point2 ua, ub;  ///< the walls' directions, counter-clockwise from ua to ub
    double angle = 0, reach = 0;
  };
  std::vector<RingPlan> plans;
  const std::vector<SegmentSector> sectors = segment_sectors(sub, apex);
  for (const SegmentSector& sector : sectors) {
    const StripsAcross strips = strips_across(sectors, sector, strip_below);
    if (!strips.any()) continue;
    const Point2 pa = point2(sub, sub.to_vertex_handle(sector.first)), pb = point2(sub, sub.to_vertex_handle(sector.last));
    const double ra = (pa - c).norm(), rb = (pb - c).norm();
    const std::vector<double> gaps = plan_ring_gaps(sector.radians, strips.first, strips.last, gap_floor);
    if (gaps.size() < 2) continue;
    // Ring radius along the sector: ra near wall a, rb near wall b, geometric in between.
    RingPlan plan;
    const double alpha_a = std::atan2(pa.y() - c.y(), pa.x() - c.x());
    double phi = 0;
    for (std::size_t k = 0; k + 1 < gaps.size(); ++k) {
      phi += gaps[k];
      const double t = phi / sector.radians;
      const double r = ra * std::pow(rb / ra, std::clamp((t - 0.25) / 0.5, 0.0, 1.0));
      plan.ring.push_back(c + r * Point2(std::cos(alpha_a + phi), std::sin(alpha_a + phi)));
    }
    plan.ua = (pa - c) / ra, plan.ub = (pb - c) / rb;
    plan.angle = sector.radians;
    plan.reach = kReach * std::max(ra, rb);
    plans.push_back(std::move(plan));
  }
  for (const RingPlan& plan : plans) {
    // The Steiner points of the sector near the apex go (those on segments stay).
    auto in_sector = [&](const Point2& q) {
      const Point2 d = q - c;
      const double ca = plan.ua.x() * d.y() - plan.ua.y() * d.x(), cb = d.x() * plan.ub.y() - d.y() * plan.ub.x();
      return plan.angle <= kPi ? (ca > 0 && cb > 0) : (ca > 0 || cb > 0);
    };
    std::vector<VertexHandle> doomed;
    for (auto vh : sub.vertices())
      if (!sub.status(vh).deleted() && sub.data(vh).kind == VertexKind::Free && (point2(sub, vh) - c).norm() < plan.reach &&
          in_sector(point2(sub, vh)))
        doomed.push_back(vh);
    if (!remove_vertices(sub, doomed)) return false;
    // Each point located from the faces of the one before, then from the apex's (the walk never
    // crosses a wall, so it must start on the sector's side).
    VertexHandle last;
    for (const Point2& q : plan.ring) {
      const VertexHandle vh = insert_point_after(sub, q, last, apex);
      if (!vh.is_valid() || sub.data(vh).kind != VertexKind::Free) return false;
      last = vh;
    }
  }
  if (!plans.empty()) make_delaunay(sub);
  return !plans.empty();
}

}  // namespace acute::detail
