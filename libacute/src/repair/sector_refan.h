// Layer: repair (internal). A vertex whose sector holds too few triangles for the max bound (a
// segment vertex with two right triangles on its straight side, an interior vertex of degree
// four) cannot be mended by moving vertices: the sector needs more spokes. No single split gives
// it one without making a vertex of degree four, so every candidate of the cluster search scored
// worse than the right angle it would replace (two CG:SHOP instances stalled at 90.000 degrees).
#pragma once

#include <acute/mesh/mesh.h>

#include <vector>

namespace acute::detail {

/// A sector at `apex` whose angle phi (degrees) split among its `triangles` faces reaches
/// `max_share` degrees or more: `first` is the spoke it starts from counter-clockwise (a wall, or
/// any spoke of a closed star); phi = 360 for a closed star.
struct CrowdedSector {
  HalfedgeHandle first;
  double degrees = 0;
  int triangles = 0;
  bool closed = false;
};

/// The sectors of `apex` (between segment or boundary spokes; the whole star when it has none)
/// whose share per triangle is at least max_share degrees. A fan cut by a border of the mesh (a
/// region copy's frozen ring) is no sector. Empty for an input vertex's closed star.
std::vector<CrowdedSector> crowded_sectors(const Mesh& mesh, VertexHandle apex, double max_share);

/// Re-fans one such sector: its interior spokes' far vertices that may go (not input, not on a
/// segment) are removed, and points are inserted at the mean spoke length from apex, at equal
/// angles, so that the sector holds about one triangle per 60 degrees (at least one more than
/// before). The search relocates afterwards. Returns false when nothing was inserted.
bool refan_sector(Mesh& mesh, VertexHandle apex, const CrowdedSector& sector);

}  // namespace acute::detail
