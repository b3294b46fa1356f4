// Layer: repair. Joint relaxation: a set of vertices moves at once, by gradient descent on a soft
// minimum of the angle margins of their triangles. It escapes the configurations where moving any
// single vertex makes some angle worse (e.g. a vertex between two coupled near-right angles whose
// other corners sit at the min bound), which the one-vertex relocation cannot leave.
#pragma once

#include <acute/repair/angle_bounds.h>

#include <vector>

namespace acute {

struct JointRelaxParams {
  int iterations = 80;     ///< gradient steps at most
  double tau_deg = 1.0;    ///< softness of the minimum (degrees): smaller focuses on the worst angles
};

/// Sum over the angles of the triangles incident to `vertices` of exp(-margin / tau): the energy
/// relax_jointly lowers (margins in degrees, the min bound dropped on forced-corner triangles).
double joint_energy(const Mesh& mesh, const std::vector<VertexHandle>& vertices, const AngleBounds& bounds,
                    const std::vector<bool>& forced, double tau_deg);

/// Moves the movable vertices among `vertices` jointly to lower joint_energy. Returns true if any
/// moved. Input vertices never move; OnSegment vertices slide along their segment; every triangle
/// incident to a moved vertex stays strictly counter-clockwise (exact orient2d). Connectivity is
/// unchanged: restore Delaunay afterwards when wanted.
bool relax_jointly(Mesh& mesh, const std::vector<VertexHandle>& vertices, const AngleBounds& bounds,
                   const std::vector<bool>& forced, const JointRelaxParams& params = {});

}  // namespace acute
