// Layer: refine. Delaunay refinement (Ruppert / Chew style) on a constrained Delaunay mesh:
// encroached subsegments are split first, then skinny or large triangles get an off-centre
// (or circumcentre); points that would encroach a subsegment are not inserted, the subsegment is
// split instead. Near input corners below 60 degrees subsegments are split on concentric shells
// around the corner and the triangles there are left alone, which makes the process terminate.
#pragma once

#include <acute/mesh/mesh.h>

#include <cstddef>

namespace acute {

struct RefineParams {
  double min_angle_deg = 20.7;   ///< triangles with a smaller angle are split (practical limit ~33)
  double max_edge = 0;           ///< > 0: triangles whose circumradius exceeds max_edge/sqrt(3) are split
  std::size_t max_vertices = 50'000'000;  ///< budget: stop (status BudgetExhausted) when reached
  bool off_centers = true;       ///< Ungor's off-centres instead of circumcentres
};

enum class RefineStatus { Converged, BudgetExhausted };

struct RefineResult {
  RefineStatus status = RefineStatus::Converged;
  std::size_t inserted = 0;        ///< Steiner points added in triangles
  std::size_t segment_splits = 0;  ///< subsegment splits
};

/// Refines a constrained Delaunay mesh in place (garbage-collected at the end).
/// \pre the mesh is constrained Delaunay with its segment table set (build_cdt does both)
/// \post constrained Delaunay; every triangle not at a small input corner meets min_angle_deg
///       unless the budget ran out
RefineResult refine(Mesh& mesh, const RefineParams& params = {});

}  // namespace acute
