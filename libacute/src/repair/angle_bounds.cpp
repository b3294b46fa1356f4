#include <acute/repair/angle_bounds.h>

#include <acute/mesh/geometry.h>
#include <acute/mesh/sectors.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace acute {

namespace {
constexpr double kDeg = 180.0 / 3.14159265358979323846;
/// Degrees: the referee counts angles this close to a bound as on it (meshcheck's ANGLE_TOL).
constexpr double kAngleTolerance = 1e-9;

double angle_at(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 u = a - p, v = b - p;
  return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v)) * kDeg;
}
}  // namespace

std::array<double, 3> angles_deg(const Point2& a, const Point2& b, const Point2& c) {
  return {angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)};
}

std::vector<bool> forced_corner_vertices(const Mesh& mesh, double min_deg) {
  std::vector<bool> forced(mesh.n_vertices(), false);
  const WallTest is_wall = [&](HalfedgeHandle out) { return is_segment_or_boundary(mesh, out); };
  for (auto vh : mesh.vertices()) {
    if (!is_input(mesh, vh)) continue;
    // Every sector starts at a wall spoke with a face on its left.
    for (auto start : mesh.voh_range(vh)) {
      if (mesh.is_boundary(start) || !is_wall(start)) continue;
      if (sweep_sector(mesh, start, is_wall).degrees < min_deg - kAngleTolerance) forced[static_cast<std::size_t>(vh.idx())] = true;
    }
  }
  return forced;
}

double sector_angle(const Mesh& mesh, VertexHandle vh, FaceHandle fh) {
  auto frozen = [&](HalfedgeHandle out) { return mesh.data(mesh.edge_handle(out)).frozen; };
  HalfedgeHandle first;
  for (auto heh : mesh.voh_range(vh))
    if (mesh.face_handle(heh) == fh) first = heh;
  if (!first.is_valid()) return -1;
  // Rewind clockwise to the wall spoke that starts the sector (a spoke with the sector's face on its left).
  HalfedgeHandle h = first;
  for (std::size_t guard = 0;; ++guard) {
    if (frozen(h)) return -1;
    if (is_segment_or_boundary(mesh, h) || guard > 1024) break;
    const HalfedgeHandle o = mesh.opposite_halfedge_handle(h);
    h = mesh.next_halfedge_handle(o);
    if (h == first) break;  // no wall: the full star
  }
  if (mesh.is_boundary(h)) return -1;
  // A frozen spoke ends the sweep too: the fan then leaves the region copy.
  const SectorSweep sector = sweep_sector(mesh, h, [&](HalfedgeHandle out) { return is_segment_or_boundary(mesh, out) || frozen(out); });
  return frozen(sector.end) ? -1 : sector.degrees;
}

bool min_exempt_corner(const Mesh& mesh, VertexHandle vh, FaceHandle fh, double min_deg, const std::vector<bool>& forced) {
  const auto i = static_cast<std::size_t>(vh.idx());
  if (i >= forced.size() || !forced[i]) return false;
  return sector_angle(mesh, vh, fh) < min_deg;
}

namespace {

/// True when fh alone fills the input sector at its corner k (both its edges there are segments).
bool fills_input_sector(const Mesh& mesh, const std::array<VertexHandle, 3>& v, int k) {
  if (!is_input(mesh, v[k])) return false;
  const HalfedgeHandle into = mesh.find_halfedge(v[(k + 2) % 3], v[k]), out = mesh.find_halfedge(v[k], v[(k + 1) % 3]);
  return into.is_valid() && out.is_valid() && is_constrained(mesh, mesh.edge_handle(into)) && is_constrained(mesh, mesh.edge_handle(out));
}

/// The margin of fh under AngleBounds::unsatisfiable_apex_slack_deg when fh is such an apex
/// triangle, else nothing.
std::optional<double> unsatisfiable_apex_margin(const Mesh& mesh, FaceHandle fh, const AngleBounds& bounds, bool exempt_min) {
  const auto p = face_points(mesh, fh);
  const auto a = angles_deg(p[0], p[1], p[2]);
  const auto v = face_vertices(mesh, fh);
  for (int k = 0; k < 3; ++k) {
    // (Its best, isosceles, leaves base angles of (180 - a) / 2: short of max by less than the margin.)
    if (!(a[k] < 180.0 - 2.0 * (bounds.max_deg - bounds.margin_deg)) || !fills_input_sector(mesh, v, k)) continue;
    const double ceiling = 0.5 * (180.0 - a[k]) + bounds.unsatisfiable_apex_slack_deg;
    double margin = ceiling - std::max(a[(k + 1) % 3], a[(k + 2) % 3]);
    if (!exempt_min) margin = std::min(margin, std::min({a[0], a[1], a[2]}) - bounds.min_deg);
    return margin;
  }
  return std::nullopt;
}

}  // namespace

double triangle_margin(const Mesh& mesh, FaceHandle fh, const AngleBounds& bounds, bool exempt_min) {
  const auto p = face_points(mesh, fh);
  auto margin_of = [&](const std::array<double, 3>& a) {
    const double lo = std::min({a[0], a[1], a[2]}), hi = std::max({a[0], a[1], a[2]});
    double margin = bounds.max_deg - hi;
    if (!exempt_min) margin = std::min(margin, lo - bounds.min_deg);
    return margin;
  };
  // The polynomial angles are within 2e-6 degrees of atan2's: away from the bad-or-not threshold
  // they decide the same, and only near it is the referee's formula worth its cost.
  const double fast = margin_of({approx_angle_deg(p[0], p[1], p[2]), approx_angle_deg(p[1], p[2], p[0]), approx_angle_deg(p[2], p[0], p[1])});
  if (bounds.unsatisfiable_apex_slack_deg >= 0 && fast < bounds.margin_deg) {
    if (const auto relaxed = unsatisfiable_apex_margin(mesh, fh, bounds, exempt_min)) return *relaxed;
  }
  if (std::abs(fast - bounds.margin_deg) > 1e-4) return fast;
  const auto a = angles_deg(p[0], p[1], p[2]);
  double margin = margin_of(a);
  if (exempt_min || margin >= bounds.margin_deg) return margin;
  // An input corner of the min bound's own angle, to rounding, filled by this one triangle: its
  // angle is the input's and no edit can widen it. The referee accepts angles down to min - 1e-9,
  // so such an angle is in bounds; asking it for the margin too made a 30-degree corner (30 + 4e-15
  // in doubles) unsatisfiable: 8 s of restarts and a "bounds not met" for a mesh the referee passes.
  const auto v = face_vertices(mesh, fh);
  margin = bounds.max_deg - std::max({a[0], a[1], a[2]});
  for (int k = 0; k < 3; ++k) {
    double m = a[k] - bounds.min_deg;
    if (m < bounds.margin_deg && m >= -kAngleTolerance && fills_input_sector(mesh, v, k)) m = bounds.margin_deg;
    margin = std::min(margin, m);
  }
  return margin;
}

namespace {

/// True when every angle of abc is clearly (by 1e-3 degrees) inside the bounds: squared cosines
/// against squared thresholds, no square root and no arctangent. False decides nothing.
bool clearly_within(const std::array<Point2, 3>& p, const AngleBounds& bounds, bool exempt_min) {
  // The cosine thresholds of the last bounds seen (one set per run: not two cosines per triangle).
  struct Thresholds {
    double min_deg = -1, max_deg = -1, c_min = 0, c_max = 0;
  };
  thread_local Thresholds th;
  if (th.min_deg != bounds.min_deg || th.max_deg != bounds.max_deg) {
    constexpr double kRad = 3.14159265358979323846 / 180.0;
    th = {bounds.min_deg, bounds.max_deg, std::cos((bounds.min_deg + 1e-3) * kRad), std::cos((bounds.max_deg - 1e-3) * kRad)};
  }
  const double c_max = th.c_max, c_min = th.c_min;
  if (!(c_max >= 0) || (!exempt_min && !(c_min > 0))) return false;  // unusual bounds: the full test
  for (int i = 0; i < 3; ++i) {
    const Point2 u = p[(i + 1) % 3] - p[i], v = p[(i + 2) % 3] - p[i];
    const double dot = u.dot(v), lengths = u.squaredNorm() * v.squaredNorm();
    // Below max: cos > c_max. At least min: cos < c_min (always so when the cosine is <= 0).
    if (!(dot > 0) || !(dot * dot > c_max * c_max * lengths)) return false;
    if (!exempt_min && !(dot * dot < c_min * c_min * lengths)) return false;
  }
  return true;
}

}  // namespace

bool is_bad_triangle(const Mesh& mesh, FaceHandle fh, const AngleBounds& bounds, const std::vector<bool>& forced) {
  bool exempt = false;
  for (auto vh : mesh.fv_range(fh)) {
    const auto i = static_cast<std::size_t>(vh.idx());
    exempt = exempt || (i < forced.size() && forced[i]);
  }
  if (clearly_within(face_points(mesh, fh), bounds, exempt)) return false;
  return triangle_margin(mesh, fh, bounds, exempt) < bounds.margin_deg;
}

bool closes_strip_apex(const Mesh& mesh, VertexHandle vh, const std::vector<bool>& forced, double strip_below_deg) {
  if (mesh.data(vh).kind != VertexKind::OnSegment) return false;
  constexpr double kPi = 3.14159265358979323846;
  auto is_forced = [&](VertexHandle v) {
    const auto i = static_cast<std::size_t>(v.idx());
    return i < forced.size() && forced[i];
  };
  for (auto spoke : mesh.voh_range(vh)) {
    const VertexHandle apex = mesh.to_vertex_handle(spoke);
    if (!is_input(mesh, apex) || !is_forced(apex) || !is_constrained(mesh, mesh.edge_handle(spoke))) continue;
    // The strip on either side of the wall (apex, vh), whatever lies inside it now (a split of the
    // apex triangle's base leaves it a fan of two). Walls are segments only: in a region copy the
    // frozen border's edges are boundary edges too, and bound no strip; a fan that reaches the
    // border is partial and left out.
    const HalfedgeHandle wall = mesh.opposite_halfedge_handle(spoke);
    for (const SegmentSector& s : segment_sectors(mesh, apex))
      if ((s.first == wall || s.last == wall) && s.radians < strip_below_deg * kPi / 180) return true;
  }
  return false;
}

}  // namespace acute
