// Layer: repair. The angle bounds, what makes a triangle bad, and the corners the input forces.
#pragma once

#include <acute/mesh/mesh.h>

#include <array>
#include <vector>

namespace acute {

/// Angles must lie in [min_deg, max_deg). `margin_deg` is kept inside both bounds during repair so
/// that a referee computing angles in floating point agrees with the verdict.
struct AngleBounds {
  double min_deg = 30.0;
  double max_deg = 90.0;
  double margin_deg = 1e-6;
  /// >= 0: the one triangle filling an input sector narrower than 180 - 2 (max - margin) (whose
  /// other two angles sum to at least 2 max less the margin: unsatisfiable) counts as
  /// within the max bound while its largest angle is at most (180 - sector) / 2 + this. For a
  /// repair's working bounds, so that it spends itself on what can be mended; a verdict on the
  /// bounds asked for keeps the default, < 0 (off).
  double unsatisfiable_apex_slack_deg = -1;
};

/// Angles (degrees) of triangle abc at a, b, c.
std::array<double, 3> angles_deg(const Point2& a, const Point2& b, const Point2& c);

/// Per-vertex flag: the vertex is an input corner with a sector narrower than the min bound
/// (between consecutive segments, inside the domain). Triangles incident on it are exempt from the
/// min bound (not from the max bound), as in meshcheck.
std::vector<bool> forced_corner_vertices(const Mesh& mesh, double min_deg);

/// The angle (degrees) of the domain sector at vh that contains face fh: the fan of faces around vh
/// between consecutive constrained or boundary edges. Negative when unknown: the fan meets the
/// frozen border of a region copy before closing. A full star without walls gives 360.
double sector_angle(const Mesh& mesh, VertexHandle vh, FaceHandle fh);

/// True when the min bound does not apply to the angle of face fh at its corner vh: vh is a forced
/// corner and the sector holding fh is narrower than min_deg (or unknown). Sharper than the
/// per-triangle exemption of is_bad_triangle (which follows the referee): used by the energies so
/// that a small angle at a forced vertex in one of its wide sectors still gets pushed up.
bool min_exempt_corner(const Mesh& mesh, VertexHandle vh, FaceHandle fh, double min_deg, const std::vector<bool>& forced);

/// True when vh (a Steiner vertex on a wall) is the first vertex of a strip's wall: joined by a
/// segment edge to a forced corner where a sector beside that edge is narrower than
/// strip_below_deg (a strip). The strip's apex triangle is isosceles; with a strip angle theta its
/// base angles are 90 - theta / 2, so a slide of either wall vertex by a fraction of theta / 2 of
/// its radius makes it obtuse, and no single-vertex move can bring the pair back; such vertices
/// stay where the start (or the hub ring) put them, even where an edit has split the apex
/// triangle's base.
bool closes_strip_apex(const Mesh& mesh, VertexHandle vh, const std::vector<bool>& forced, double strip_below_deg);

/// How far triangle fh is from the bounds: the smallest margin min(angle - min, max - angle) over
/// its angles, in degrees (negative when bad). `exempt_min` drops the min-bound part.
double triangle_margin(const Mesh& mesh, FaceHandle fh, const AngleBounds& bounds, bool exempt_min);

/// True when fh violates the bounds (margin below bounds.margin_deg).
bool is_bad_triangle(const Mesh& mesh, FaceHandle fh, const AngleBounds& bounds, const std::vector<bool>& forced);

}  // namespace acute
