// Private to the repair layer: the ring of a hub's wide sectors. At an input vertex where a strip
// sector (narrower than the min bound) meets a wide one, the first vertex p of the strip's wall is
// an edge r away from the apex on the wide side, and the next one along the wall a strip's width,
// r sin(theta), away. Around p, triangles with angles in the bounds can change their size by at
// most a factor of two each, so the wide side needs a triangle that is thin too: only triangles at
// the apex may be (their small angles are forced). The ring puts movable points at the walls'
// first radii on rays into the wide sector, the first a few strip angles from the wall and each
// next gap wider: isosceles triangles at the apex (apex angle the gap, base angles below 90), their
// chords growing from a strip's width to the wide sector's spacing.
#pragma once

#include <acute/mesh/mesh.h>

#include <vector>

namespace acute::detail {

/// Gives every strip sector at apex (narrower than strip_below, wholly in sub) an isosceles apex
/// triangle: the farther of its walls' first vertices is replaced by one at the nearer's radius.
/// With a strip angle theta the base angles are 90 - theta / 2, so radii differing by a factor
/// below cos(theta) make the triangle obtuse. False when nothing changed or an edit failed.
/// outward: the nearer vertex is replaced by one at the farther's radius instead (for a sector
/// that holds one triangle, whose nearer wall vertex may be left with too few triangles beside it).
bool equalise_strip_apexes(Mesh& sub, VertexHandle apex, double strip_below, bool outward = false);

/// A sector at apex that holds one triangle (from strip_below to one_triangle_below radians,
/// wholly in sub) leaves a base vertex of its apex triangle with two triangles on its wall's
/// straight side (90 + 90) wherever the mesh beyond is one triangle wide, as between two interior
/// segments whose vertices stay. So after equalise_strip_apexes (outward when `outward`) a point is
/// put on the sector's bisector where the triangle over the apex triangle's base has the base
/// angles 45 + theta / 4 that give each base vertex three triangles of equal angles. False when
/// no such sector at apex has equal first radii after the equalisation (outward, it leaves radii
/// 1.5 times apart or more as they are) or no point could be inserted.
bool apex_with_middle_point(Mesh& sub, VertexHandle apex, double strip_below, double one_triangle_below, bool outward);

/// The radius of the disk around `apex` that rebuild_hub_ring would change (1.1 times the largest
/// first radius of a ringed sector's walls), 0 when no wide sector at apex has a strip across a wall.
double hub_ring_reach(const Mesh& mesh, VertexHandle apex, double strip_below);

/// The gaps (radians, from the first wall to the last, summing to `sector`) of the ring in a wide
/// sector with strips of strip_first / strip_last radians across its walls (0: none): from each
/// strip's wall 1.5 strip angles, from a wall with none 0.5, each next 1.6 times wider, until they
/// fill the sector; then scaled to fit, and the last ones dropped while the narrowest would be
/// below gap_floor. Fewer than two gaps: no ring.
std::vector<double> plan_ring_gaps(double sector, double strip_first, double strip_last, double gap_floor);

/// Equalises the strips' apex triangles at `apex` (an Input vertex of the region copy sub), then
/// rebuilds every wide sector there that has a strip sector narrower than `strip_below` (radians)
/// across one of its walls: the movable vertices of
/// the wide sector closer than 1.1 times its walls' first radii are removed and the ring inserted
/// (then the mesh is made Delaunay). No gap of the ring is narrower than apex_gap_floor(max_angle)
/// (fewer, wider gaps where the planned ones would be). False when there is no such sector or
/// nothing was rebuilt.
bool rebuild_hub_ring(Mesh& sub, VertexHandle apex, double strip_below, double max_angle);

}  // namespace acute::detail
