// Layer: refine. Delaunay refinement (Ruppert / Chew style) on a constrained Delaunay mesh:
// encroached subsegments are split first, then skinny or large triangles get an off-centre
// (or circumcentre); points that would encroach a subsegment are not inserted, the subsegment is
// split instead. Input corners narrower than 60 degrees are lopped first: their segments are cut
// at one radius r and the cut points joined by temporary chord constraints, so the fan triangles
// at the corner are never split and the rest sees only angles >= 90 at the chord ends (corners
// shrink to r/2 when needed). At a corner narrower than min_angle_deg (a forced corner) every
// triangle incident on the corner is excused from the angle test, as meshcheck's free min angle.
#pragma once

#include <acute/mesh/mesh.h>

#include <cstddef>

namespace acute {

struct RefineParams {
  double min_angle_deg = 20.7;   ///< triangles with a smaller angle are split (practical limit ~33)
  double max_edge = 0;           ///< > 0: triangles whose circumradius exceeds max_edge/sqrt(3) are split
  std::size_t max_vertices = 50'000'000;  ///< budget: stop (status BudgetExhausted) when reached
  double time_limit_s = 0;       ///< > 0: stop (status OutOfTime) after about this many seconds
  bool off_centers = true;       ///< Ungor's off-centres instead of circumcentres
};

enum class RefineStatus { Converged, BudgetExhausted, OutOfTime };

struct RefineResult {
  RefineStatus status = RefineStatus::Converged;
  std::size_t inserted = 0;        ///< Steiner points added in triangles
  std::size_t segment_splits = 0;  ///< subsegment splits
  std::size_t corners = 0;         ///< input corners lopped (sectors below 60 degrees)
  std::size_t shrinks = 0;         ///< times a lopped corner was cut again at half its radius
};

/// Refines a constrained Delaunay mesh in place (garbage-collected at the end).
/// \pre the mesh is constrained Delaunay with its segment table set (build_cdt does both)
/// \post constrained Delaunay (the chords are released); unless the budget or time ran out, every
///       triangle not incident on a forced corner has all angles >= min_angle_deg (up to ~33 in
///       practice) and, with max_edge > 0, circumradius <= max_edge / sqrt(3) (fan triangles too)
RefineResult refine(Mesh& mesh, const RefineParams& params = {});

}  // namespace acute
