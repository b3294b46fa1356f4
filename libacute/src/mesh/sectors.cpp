#include <acute/mesh/sectors.h>

#include <cmath>

namespace acute {

namespace {
constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;
}  // namespace

bool is_segment_or_boundary(const Mesh& mesh, HalfedgeHandle spoke) {
  const EdgeHandle eh = mesh.edge_handle(spoke);
  return is_constrained(mesh, eh) || mesh.is_boundary(eh);
}

SectorSweep sweep_sector(const Mesh& mesh, HalfedgeHandle start, const WallTest& is_wall, int max_triangles) {
  SectorSweep s;
  s.end = start;
  if (mesh.is_boundary(start)) {
    s.how = SectorEnd::Border;
    return s;
  }
  const Point2 p = point2(mesh, mesh.from_vertex_handle(start));
  HalfedgeHandle h = start;
  while (s.triangles < max_triangles) {
    const HalfedgeHandle back = mesh.prev_halfedge_handle(h);  // ends at the vertex
    const Point2 u = point2(mesh, mesh.to_vertex_handle(h)) - p, v = point2(mesh, mesh.from_vertex_handle(back)) - p;
    const double angle = std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
    s.radians += angle;
    s.degrees += angle * kDegPerRad;
    ++s.triangles;
    h = mesh.opposite_halfedge_handle(back);  // the next spoke counter-clockwise
    s.end = h;
    if (h == start) {
      s.how = SectorEnd::Closed;
      return s;
    }
    if (is_wall(h)) {
      s.how = SectorEnd::Wall;
      return s;
    }
    if (mesh.is_boundary(h)) {
      s.how = SectorEnd::Border;
      return s;
    }
  }
  s.how = SectorEnd::Unfinished;
  return s;
}

std::vector<SegmentSector> segment_sectors(const Mesh& mesh, VertexHandle vh, bool* partial) {
  std::vector<SegmentSector> out;
  if (partial) *partial = false;
  const WallTest is_segment = [&](HalfedgeHandle spoke) { return is_constrained(mesh, mesh.edge_handle(spoke)); };
  for (auto spoke : mesh.voh_range(vh)) {
    if (!is_segment(spoke) || mesh.is_boundary(spoke)) continue;
    const SectorSweep sweep = sweep_sector(mesh, spoke, is_segment, 4096);
    if (sweep.how == SectorEnd::Wall)
      out.push_back(SegmentSector{spoke, sweep.end, sweep.radians});
    else if (partial)
      *partial = true;
  }
  return out;
}

void for_each_sector(const Mesh& mesh, VertexHandle vh, int max_triangles, const SectorVisitor& visit) {
  HalfedgeHandle start;
  for (auto heh : mesh.voh_range(vh))
    if (!mesh.is_boundary(heh) && is_segment_or_boundary(mesh, heh)) start = heh;
  const bool closed = !start.is_valid();
  if (closed) {
    if (mesh.is_boundary(vh)) return;
    start = mesh.halfedge_handle(vh);
  }
  const WallTest is_wall = [&](HalfedgeHandle spoke) { return !closed && is_segment_or_boundary(mesh, spoke); };
  int budget = max_triangles;
  for (HalfedgeHandle h = start;;) {
    const SectorSweep sector = sweep_sector(mesh, h, is_wall, budget);
    if (sector.how == SectorEnd::Unfinished) return;
    budget -= sector.triangles;
    visit(h, sector, closed);
    h = sector.end;
    if (h == start || mesh.is_boundary(h)) return;
  }
}

HalfedgeHandle segment_spoke_along(const Mesh& mesh, VertexHandle vh, const Point2& u) {
  const Point2 c = point2(mesh, vh);
  for (auto spoke : mesh.voh_range(vh))
    if (is_constrained(mesh, mesh.edge_handle(spoke)) && (point2(mesh, mesh.to_vertex_handle(spoke)) - c).normalized().dot(u) > 1 - 1e-12) return spoke;
  return HalfedgeHandle();
}

}  // namespace acute
