// Layer: ops. Moving a vertex without changing connectivity.
#pragma once

#include <acute/ops/flip.h>

namespace acute {

/// For a vertex on a segment: p lies strictly between its two neighbours along the segment in
/// every coordinate in which they differ and equals theirs where they agree (exact comparisons;
/// p is on the segment's line by the caller's projection). The chain then stays monotone.
bool keeps_segment_order(const Mesh& mesh, VertexHandle vh, const Point2& p);

/// Ok when vh may move to p: vh is not Input; a vertex on a segment stays on its segment (p is
/// projected by the caller; checked by keeps_segment_order and close_enough_to_line); a vertex
/// on the mesh border that is not on a segment never moves (Boundary); every incident triangle
/// stays strictly counter-clockwise (exact).
OpVerdict can_relocate(const Mesh& mesh, VertexHandle vh, const Point2& p);

/// Moves vh to p. \pre can_relocate(mesh, vh, p) == Ok. Does not flip: call restore_delaunay
/// with push_star_edges(vh) when the Delaunay property is wanted.
void relocate(Mesh& mesh, VertexHandle vh, const Point2& p);

}  // namespace acute
