#include "cvt/narrow_sectors.h"

#include <acute/mesh/geometry.h>
#include <acute/mesh/sectors.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace acute::detail {

namespace {

constexpr int kSweepBudget = 100000;

/// The strip sector starting counter-clockwise at wall spoke `out`, or an invalid end halfedge.
SectorSweep strip_sector_from(const Mesh& mesh, HalfedgeHandle out) {
  if (mesh.is_boundary(out)) return SectorSweep();
  const WallTest wall = [&](HalfedgeHandle h) { return is_segment_or_boundary(mesh, h); };
  SectorSweep s = sweep_sector(mesh, out, wall, kSweepBudget);
  if (s.how != SectorEnd::Wall || !(s.radians < kStripSector)) return SectorSweep();
  return s;
}

}  // namespace

bool bounds_strip_sector(const Mesh& mesh, HalfedgeHandle out) {
  if (!is_segment_or_boundary(mesh, out)) return false;
  if (strip_sector_from(mesh, out).end.is_valid()) return true;
  // The sector clockwise from `out`: the one that ends at it.
  const VertexHandle v = mesh.from_vertex_handle(out);
  for (auto h : mesh.voh_range(v)) {
    if (h == out || !is_segment_or_boundary(mesh, h)) continue;
    const SectorSweep s = strip_sector_from(mesh, h);
    if (s.end == out) return true;
  }
  return false;
}

double StripApex::triangle_radius(double size_at_apex) const { return std::min(reach, size_at_apex / std::sin(narrowest)); }

StripApex strip_apex(const Mesh& mesh, VertexHandle vh) {
  StripApex out;
  double shortest = std::numeric_limits<double>::infinity();
  const Point2 v = point2(mesh, vh);
  int walls = 0;
  for (auto h : mesh.voh_range(vh)) {
    if (!is_segment_or_boundary(mesh, h)) continue;
    ++walls;
    shortest = std::min(shortest, (point2(mesh, mesh.to_vertex_handle(h)) - v).norm());
    const SectorSweep s = strip_sector_from(mesh, h);
    if (s.end.is_valid() && (out.narrowest == 0 || s.radians < out.narrowest)) out.narrowest = s.radians;
  }
  // A lone strip (the domain's only sector at a boundary vertex: a needle's tip) is rebuilt by the
  // repair's polar fan out to half its shorter wall, its walls' vertices inside that removed (debug2's
  // 10,000 tips: 10% of its start). Elsewhere (a hub with a wide sector beside its strips) a third.
  const bool lone = walls == 2 && mesh.is_boundary(vh);
  if (out.narrowest > 0) out.reach = shortest / (lone ? 2.0 : 3.0);
  return out;
}

void append_strip_samples(const Mesh& mesh, std::vector<Point2>& points, std::vector<double>& values, int max_per_wall) {
  for (auto vh : mesh.vertices()) {
    if (mesh.status(vh).deleted()) continue;
    double r0 = -1;  // computed at the first strip sector of vh
    const Point2 v = point2(mesh, vh);
    for (auto out : mesh.voh_range(vh)) {
      if (!is_segment_or_boundary(mesh, out)) continue;
      const SectorSweep s = strip_sector_from(mesh, out);
      if (!s.end.is_valid()) continue;
      if (r0 < 0) r0 = strip_apex(mesh, vh).reach;
      const Point2 a = point2(mesh, mesh.to_vertex_handle(out)), b = point2(mesh, mesh.to_vertex_handle(s.end));
      const double la = (a - v).norm(), lb = (b - v).norm(), reach = std::min(la, lb);
      if (!(r0 > 0) || !(reach > r0)) continue;
      const double sin_theta = std::sin(s.radians);
      // Geometric radii: each step as long as the strip is wide there (fewer when that is too many).
      double growth = 1.0 + sin_theta;
      const double steps = std::log(reach / r0) / std::log(growth);
      if (steps > max_per_wall) growth = std::pow(reach / r0, 1.0 / max_per_wall);
      const Point2 ua = (a - v) / la, ub = (b - v) / lb;
      for (double r = r0; r <= reach; r *= growth) {
        const Point2 pa = v + r * ua, pb = v + r * ub;
        points.push_back(pa), values.push_back(distance_to_segment(pa, v, b));
        points.push_back(pb), values.push_back(distance_to_segment(pb, v, a));
      }
    }
  }
}

}  // namespace acute::detail
