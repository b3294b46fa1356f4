#include "repair/sector_refan.h"

#include <acute/mesh/geometry.h>
#include <acute/mesh/sectors.h>
#include <acute/ops/insert.h>
#include <acute/ops/remove.h>

#include <algorithm>
#include <cmath>

namespace acute::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
/// The share per triangle a re-fanned sector aims at (equilateral triangles round the apex).
constexpr double kAimDegrees = 60.0;

}  // namespace

std::vector<CrowdedSector> crowded_sectors(const Mesh& mesh, VertexHandle apex, double max_share) {
  std::vector<CrowdedSector> out;
  for_each_sector(mesh, apex, 64, [&](HalfedgeHandle first, const SectorSweep& sector, bool closed) {
    if (sector.how == SectorEnd::Border || (closed && is_input(mesh, apex))) return;
    if (sector.degrees / sector.triangles >= max_share) out.push_back(CrowdedSector{first, sector.degrees, sector.triangles, closed});
  });
  return out;
}

bool refan_sector(Mesh& mesh, VertexHandle apex, const CrowdedSector& sector) {
  const Point2 c = point2(mesh, apex);
  // Everything is read before the first edit (removals invalidate the handles).
  std::vector<VertexHandle> inner;  // far ends of the interior spokes
  const int spokes = sector.closed ? sector.triangles : sector.triangles + 1;  // a wall sector's two walls included
  double length = 0;
  HalfedgeHandle h = sector.first;
  for (int t = 0; t < spokes; ++t) {
    const VertexHandle w = mesh.to_vertex_handle(h);
    length += (point2(mesh, w) - c).norm();
    const bool interior = sector.closed || (t > 0 && t < sector.triangles);
    if (interior && mesh.data(w).kind == VertexKind::Free) inner.push_back(w);
    h = mesh.opposite_halfedge_handle(mesh.prev_halfedge_handle(h));  // the next spoke counter-clockwise
  }
  length /= spokes;
  const Point2 d0 = (point2(mesh, mesh.to_vertex_handle(sector.first)) - c).normalized();
  const double a0 = std::atan2(d0.y(), d0.x());
  const int wanted = std::max(sector.triangles + 1, static_cast<int>(std::lround(sector.degrees / kAimDegrees)));
  const double step = sector.degrees * kPi / 180 / wanted;
  for (VertexHandle w : inner) remove_vertex(mesh, w);
  int inserted = 0;
  // A closed star gets a spoke at every step; a wall sector between its walls only.
  for (int j = sector.closed ? 0 : 1; j < wanted; ++j) {
    const double a = a0 + j * step;
    const Point2 q = c + length * Point2(std::cos(a), std::sin(a));
    const VertexHandle vh = insert_point_from(mesh, q, apex);
    inserted += vh.is_valid() && vh != apex && !is_input(mesh, vh);
  }
  return inserted > 0;
}

}  // namespace acute::detail
