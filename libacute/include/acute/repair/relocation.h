// Layer: repair. Our vertex relocation: move a vertex to minimise a soft minimum of the margins of
// the angles of its one-ring to the bounds (descent along its gradient over the feasible star, exact validity checks);
// vertices on a segment search along it; input vertices never move.
#pragma once

#include <acute/repair/angle_bounds.h>

namespace acute {

/// Smallest margin to the bounds over all angles of the triangles around vh (degrees).
double star_margin(const Mesh& mesh, VertexHandle vh, const AngleBounds& bounds, const std::vector<bool>& forced);

/// Soft minimum of the star's angle margins: sum of exp(-margin / 2 degrees) over its angles.
double star_energy(const Mesh& mesh, VertexHandle vh, const AngleBounds& bounds, const std::vector<bool>& forced);

/// Moves vh to a position with a lower star energy when one is found. Returns true if moved.
/// \post the star stays strictly counter-clockwise; an OnSegment vertex stays on its segment
bool relocate_for_angles(Mesh& mesh, VertexHandle vh, const AngleBounds& bounds, const std::vector<bool>& forced);

}  // namespace acute
