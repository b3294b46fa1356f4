// Layer: ops. Edge flips and the local Delaunay test. Check-then-act: can_flip() then flip().
//
//          vl                    vl
//         /  \                  / | \ .
//       v0----v1     flip     v0  |  v1
//         \  /                  \ | /
//          vr                    vr
#pragma once

#include <acute/mesh/mesh.h>

namespace acute {

/// Why a local operator is refused.
enum class OpVerdict {
  Ok,
  Boundary,      ///< the element is on the mesh boundary
  Constrained,   ///< the edge is part of an input segment
  InputVertex,   ///< input vertices never move and are never removed
  Topology,      ///< the connectivity forbids it (link condition, degree)
  WouldInvert,   ///< a triangle would become clockwise or flat
  OffSegment     ///< a vertex on a segment would leave it
};

const char* to_string(OpVerdict verdict);

/// Ok when eh is interior, unconstrained and its quadrilateral strictly convex (exact).
OpVerdict can_flip(const Mesh& mesh, EdgeHandle eh);

/// Flips eh. \pre can_flip(mesh, eh) == OpVerdict::Ok
void flip(Mesh& mesh, EdgeHandle eh);

/// True when eh is boundary, constrained, or neither opposite vertex lies strictly inside the
/// circumcircle of the other triangle (exact incircle).
bool is_locally_delaunay(const Mesh& mesh, EdgeHandle eh);

}  // namespace acute
