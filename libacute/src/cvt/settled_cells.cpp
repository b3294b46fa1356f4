#include "cvt/settled_cells.h"

#include <acute/mesh/segments.h>

#include <array>
#include <cmath>

namespace acute::detail {

namespace {

/// The six neighbours of vh in counter-clockwise order when it is a free interior vertex of degree
/// six with no constrained edge in its star; false otherwise.
bool hexagon_star(const Mesh& mesh, VertexHandle vh, std::array<VertexHandle, 6>& ring) {
  if (mesh.status(vh).deleted() || mesh.data(vh).kind != VertexKind::Free || mesh.is_boundary(vh)) return false;
  std::size_t k = 0;
  for (auto heh : mesh.voh_ccw_range(vh)) {
    if (k == 6) return false;
    if (is_constrained(mesh, mesh.edge_handle(heh)) || is_constrained(mesh, mesh.edge_handle(mesh.next_halfedge_handle(heh)))) return false;
    ring[k++] = mesh.to_vertex_handle(heh);
  }
  return k == 6;
}

}  // namespace

std::vector<double> settled_cells(const Mesh& mesh, const SizeField& field, double max_move, std::vector<double>& h) {
  const std::size_t nv = mesh.n_vertices();
  const bool uniform = field.is_uniform();
  h.assign(nv, field.max_value());
  if (!uniform) {
    int hint = -1;  // vertices are in spatial order: each walk starts where the last one ended
    for (auto vh : mesh.vertices())
      if (!mesh.status(vh).deleted()) h[static_cast<std::size_t>(vh.idx())] = field.eval(point2(mesh, vh), hint);
  }
  std::vector<double> spacing(nv, 0.0);
  constexpr double kSin60 = 0.86602540378443865, kCos60 = 0.5;
  constexpr double kExact = 1e-9;  // relative: lattice points are placed by a few roundings of their coordinates
  std::array<VertexHandle, 6> ring;
  std::array<Point2, 6> d;
  for (auto vh : mesh.vertices()) {
    if (!hexagon_star(mesh, vh, ring)) continue;
    const Point2 v = point2(mesh, vh);
    for (std::size_t k = 0; k < 6; ++k) d[k] = point2(mesh, ring[k]) - v;
    const double s2 = d[0].squaredNorm();
    bool regular = s2 > 0;
    for (std::size_t k = 0; k < 6 && regular; ++k) {
      // The next spoke is this one turned by 60 degrees.
      const Point2& a = d[k];
      const Point2 turned(kCos60 * a.x() - kSin60 * a.y(), kSin60 * a.x() + kCos60 * a.y());
      regular = (d[(k + 1) % 6] - turned).squaredNorm() <= kExact * kExact * s2;
    }
    if (!regular) continue;
    const double h0 = h[static_cast<std::size_t>(vh.idx())];
    double move = 0;
    if (!uniform) {
      // Least-squares slope of h over the star: the spokes' second moment is 3 s^2 times the identity.
      Point2 slope(0, 0);
      for (std::size_t k = 0; k < 6; ++k) slope += (h[static_cast<std::size_t>(ring[k].idx())] - h0) * d[k];
      slope /= 3.0 * s2;
      move = (5.0 / 18.0) * s2 * slope.norm() / (h0 * h0);
    }
    if (move <= 0.5 * max_move) spacing[static_cast<std::size_t>(vh.idx())] = std::sqrt(s2);
  }
  return spacing;
}

double settled_cell_energy(double s, double h) {
  const double r = s / h;
  return (5.0 * std::sqrt(3.0) / 72.0) * (r * r) * (r * r);
}

}  // namespace acute::detail
