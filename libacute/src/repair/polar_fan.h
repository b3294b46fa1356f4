// Private to the repair layer: a log-polar lattice at a sharp input corner. A sector narrower than
// 60 degrees whose walls are longer than the local spacing is a strip that the CVT start fills one
// triangle wide, and a one-row strip at an apex always leaves a wall vertex with two triangles on a
// straight segment (90 + 90 degrees). The fan replaces the movable vertices near the apex by points
// on rays at half the narrowest sector's angle, alternately at the radii r_k = R / g^k and at their
// geometric midpoints: near-equilateral triangles at every scale, every wall vertex with three
// triangles per sector and every interior one with six.
#pragma once

#include <acute/mesh/mesh.h>

#include <vector>

namespace acute::detail {

struct SharpCorner {
  VertexHandle apex;    ///< an Input vertex of the big mesh
  double radius = 0;    ///< of the disk the fan fills: short of every other feature
  double narrowest = 0; ///< the narrowest sector at the apex, radians
};

/// Input vertices of `mesh` with a sector narrower than max_sector (radians) whose fan would be at
/// least a few rings deep, with the radius of that fan: where the lattice's radial step reaches
/// the wall spacing of the mesh, at most half the distance to the far end of a wall, and 0.7 of the
/// distance to every other segment or input vertex. A corner whose wall spacing at that radius is
/// more than 8 lattice steps (another feature keeps the disk small) is left out: the fan's outer
/// ring would be much finer than the mesh it meets.
std::vector<SharpCorner> find_sharp_corners(const Mesh& mesh, double max_sector);

/// Rings of a fan. More reach closer to the apex but add vertices for nothing: the apex triangles
/// may be as long as they like (their small angles are forced), and three is the fewest that keeps
/// a whole lattice ring between the apex triangles' chords and the old mesh.
constexpr int kPolarFanRings = 3;

/// The narrowest apex gap (the corner between two consecutive spokes at a forced vertex, radians)
/// the fans and rings lay out under a max bound of max_angle: narrowest_feasible_corner with a
/// margin, so that rounding and the smoothing that follows do not leave an isosceles apex triangle
/// with base angles at the bound itself (a 30-degree sector cut in three at max 85: 85.03). 0 from
/// max 90 degrees on.
double apex_gap_floor(double max_angle);

/// Rebuilds the disk of `radius` around `apex` (an Input vertex of sub whose whole star sub holds,
/// with a sector narrower than the min bound, so the apex triangles' small angles are forced) as a
/// log-polar lattice of `rings` rings; each sector is divided into the nearest multiple of the
/// narrowest, or fewer parts where that would leave apex gaps narrower than apex_gap_floor(max_angle)
/// (radians). False when sub was left unchanged or the rebuild could not be completed (sub
/// is then to be discarded).
bool build_polar_fan(Mesh& sub, VertexHandle apex, double radius, int rings, double max_angle);

}  // namespace acute::detail
