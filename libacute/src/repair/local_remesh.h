// Private to the repair layer: re-sampling a region copy from scratch. Where no single local
// operation improves a stubborn cluster (the one-triangle-wide strip of a sharp wedge, a segment
// vertex left with two right triangles), a fresh arrangement of the region's movable vertices at
// the local spacing often does; the repair keeps it only when it scores better.
#pragma once

#include <acute/mesh/mesh.h>

#include <cmath>
#include <cstdint>

namespace acute::detail {

/// Removes the movable vertices of `sub` (everything not Input; the frozen ring of a region copy is
/// Input), then re-samples it at a spacing of h graded down to the features that stay
/// (min(h, lfs(v) + 0.5 |x - v|) over the vertices left, lfs their distance to the nearest other
/// vertex or wall): constrained non-frozen edges divided by the integral of 1 / spacing, interior
/// points by dart throwing (randomised by seed, kept 0.7 of the spacing from vertices and 0.35 from
/// walls), then a few density-weighted Lloyd sweeps with Delaunay restoration. Returns false when
/// the region would need more than about 8 points per vertex it has, or nothing could be removed;
/// sub is then to be discarded.
bool remesh_region(Mesh& sub, double h, std::uint32_t seed);

/// Rebuilds the sharp corner at `apex` (an Input vertex of sub whose domain sector between two
/// consecutive walls is narrower than 60 degrees and lies wholly inside sub): the movable vertices in
/// the sector closer than the nearest fixed one are removed, and the sector is refilled with a
/// graded strip two rows wide: points at radii r_1 < ... < r_K (K = rings >= 3) on both walls (r_{k+1} = r_k (1 +
/// 2 sin(theta/2) / sqrt 3), the side of equilateral triangles two rows across) and a middle row on
/// the bisector between consecutive radii. The apex triangle is isosceles, and every base vertex
/// gets three triangles. Returns false when there is no such sector or nothing was rebuilt.
bool rebuild_wedge(Mesh& sub, VertexHandle apex, int rings);

/// Every sector narrower than 60 degrees at `apex` rebuilt at once, as rebuild_wedge does one, with
/// common radii (the growth of the narrowest sector) on all their walls, interior segments
/// included: those are divided at the radii too, so a wedge between two interior segments (or one
/// whose interior wall is too coarse for a graded strip) is rebuilt, and sectors sharing a wall
/// agree on its points. The faces on the far side of a divided interior wall are left to the
/// repair (slivers there when the wedge is much narrower than the spacing: see clusters.poly).
bool rebuild_hub(Mesh& sub, VertexHandle apex, int rings);

/// Radial growth of a graded strip in a sector of theta radians: the step r (g - 1) is the side of
/// the equilateral triangles two rows across it (rebuild_wedge, rebuild_hub, build_polar_fan).
inline double wedge_growth(double theta) { return 1.0 + 2.0 * std::sin(0.5 * theta) / std::sqrt(3.0); }

/// Whether vh has a sector rebuild_wedge would rebuild (narrower than 60 degrees, wholly in sub).
bool has_narrow_sector(const Mesh& sub, VertexHandle vh);

/// Median length of the edges at movable (non-Input) vertices of sub; 0 when there are none.
double movable_edge_median(const Mesh& sub);

}  // namespace acute::detail
