// Private to the pipeline: strip hubs meshed in log-polar coordinates. At an input vertex where a
// strip sector (narrower than the min bound) meets a wide one, the strip's first wall vertex is an
// edge r from the hub on the wide side and a strip's width, r sin(theta), from its next wall
// vertex: the wide side must grade from the strip's width to the hub's radius within a few
// triangles, which the isotropic start does not do. In log-polar coordinates (ln r, phi) the hub's
// walls are parallel lines, a strip is a band of constant height theta and the right grading is
// an ordinary lfs-graded mesh. The map back, exp, is conformal: the angles of small triangles are
// kept, near the walls (where the triangles are theta small) to within about theta / 2.
#pragma once

#include <acute/mesh/mesh.h>
#include <acute/mesher.h>

#include <vector>

namespace acute::detail {

/// Replaces the start mesh's disk around every strip hub (an input vertex with a sector narrower
/// than options.min_angle_deg and one that is not) by an acute mesh made in
/// log-polar coordinates and mapped back. Returns the hubs patched; a hub whose patch cannot be
/// made or inserted is left as it was. `seconds` (> 0) bounds the log-polar meshing: no patch is
/// started after it (one under way finishes its attempt, so the patches do not depend on the clock).
std::vector<Point2> patch_strip_hubs(Mesh& mesh, const MeshOptions& options, double seconds);

}  // namespace acute::detail
