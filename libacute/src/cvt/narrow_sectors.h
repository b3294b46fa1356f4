// Private to the cvt layer: the strips of narrow sectors. A domain sector narrower than 30 degrees
// at an input vertex (its apex triangles' small angles are forced) is a strip whose width grows as
// r sin(theta) with the distance r from the apex. Its two walls share the apex, so the local feature
// size (the distance to features sharing no endpoint) never sees one wall from the other, and the
// start filled such strips one sliver wide (la.poly's 4-degree hub). The size field gets the strip
// width along both walls from the apex triangle outwards, and the sampler cuts both walls at the
// apex triangle's radius: an isosceles apex triangle, then triangles about as wide as the strip.
#pragma once

#include <acute/core/types.h>
#include <acute/mesh/mesh.h>

#include <vector>

namespace acute::detail {

/// Sectors narrower than this (radians) are strips. Walls: constrained and boundary edges
/// (is_segment_or_boundary).
constexpr double kStripSector = 3.14159265358979323846 / 6.0;

/// The apex of strip sectors: the narrowest of them (radians; 0 when vh has none) and how far the
/// size field's strip samples start from it, a third of its shortest wall.
struct StripApex {
  double narrowest = 0;
  double reach = 0;
  /// The radius of the apex triangle, where the sampler cuts both walls: where the strip is as
  /// wide as `size_at_apex` (a fine request resolves the strip from close in), at most the reach.
  double triangle_radius(double size_at_apex) const;
};
StripApex strip_apex(const Mesh& mesh, VertexHandle vh);

/// Whether the wall spoke `out` (a halfedge leaving its vertex) bounds a strip sector on either side.
bool bounds_strip_sector(const Mesh& mesh, HalfedgeHandle out);

/// Size samples along both walls of every strip sector of `mesh` (an input CDT, faces only inside
/// the domain): at radii r0 (StripApex::reach), r0 (1 + sin theta), ... up to the shorter wall's
/// length, the distance to the other wall. At most max_per_wall samples per wall (a needle sector
/// of 0.1 degree would need thousands): the step grows to fit.
void append_strip_samples(const Mesh& mesh, std::vector<Point2>& points, std::vector<double>& values, int max_per_wall = 2048);

}  // namespace acute::detail
