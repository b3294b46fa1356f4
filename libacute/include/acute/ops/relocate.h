// Layer: ops. Moving a vertex without changing connectivity.
#pragma once

#include <acute/ops/flip.h>

namespace acute {

/// Ok when vh may move to p: vh is not Input; a vertex on a segment stays on its segment (p is
/// projected by the caller; checked to lie strictly between its neighbours along the segment);
/// every incident triangle stays strictly counter-clockwise (exact).
OpVerdict can_relocate(const Mesh& mesh, VertexHandle vh, const Point2& p);

/// Moves vh to p. \pre can_relocate(mesh, vh, p) == Ok. Does not flip: call restore_delaunay
/// with push_star_edges(vh) when the Delaunay property is wanted.
void relocate(Mesh& mesh, VertexHandle vh, const Point2& p);

}  // namespace acute
