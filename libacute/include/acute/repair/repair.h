// Layer: repair. The acute repair: find clusters of bad triangles and fix them with local operators
// (split, vertex removal / collapse, flips, relocation) plus smoothing; global sweeps first, then
// only around what is still bad; until nothing is bad or the budget runs out.
#pragma once

#include <acute/repair/angle_bounds.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace acute {

struct RepairProgress {
  int iteration = 0;
  std::size_t bad = 0;
  bool global = true;
};

struct RepairParams {
  AngleBounds bounds;
  int max_iterations = 300;
  int global_iterations = 5;      ///< sweeps over the whole mesh before going local
  /// The global sweeps also end once fewer than one triangle in this many is bad: a sweep costs the
  /// whole mesh, the local phase only the neighbourhoods of what is left.
  std::size_t global_ratio = 10'000;
  std::size_t max_vertices = 50'000'000;
  /// Before the first iteration, rebuild the disk around every forced corner (a sector narrower
  /// than the min bound) as a graded log-polar fan, kept where it leaves fewer infeasible vertices.
  bool grade_sharp_corners = true;
  /// Input vertices (by position) whose disks the caller has graded already (the pipeline's
  /// log-polar hub patches): left out of that rebuild.
  std::vector<Point2> graded_corners;
  double time_limit_s = 0;         ///< 0: none
  /// Iterations without a new best (fewest bad triangles) before stopping: stuck clusters get
  /// fresh random re-samplings every iteration, so some persistence pays.
  int stagnation_limit = 150;
  /// When > 0: a run whose best has at most restart_at_most bad triangles stops after this many
  /// iterations without a new best instead. For a caller that restarts such a run from another
  /// start (generate_mesh): past ~50 a run seldom recovers, and runs that met the bounds went at
  /// most 21 iterations without a new best (300 stress domains, CG:SHOP's 150 instances at the
  /// default size and ~1k, its 40 examples, 25 classic domains).
  int stagnation_limit_before_restart = 0;
  std::size_t restart_at_most = 0;
  std::function<void(const RepairProgress&)> observer;
  std::function<bool()> cancel;    ///< returns true to stop early
};

enum class RepairStatus { Converged, IterationLimit, TimeLimit, Cancelled, VertexBudget };

struct RepairResult {
  RepairStatus status = RepairStatus::IterationLimit;
  int iterations = 0;
  std::size_t bad_before = 0, bad_after = 0;
  std::size_t inserted = 0, removed = 0, relocated = 0;
  std::size_t committed = 0;  ///< cluster edits written back
};

/// Repairs the mesh in place; on return the mesh is the best one seen (fewest bad triangles),
/// garbage-collected. \pre constrained Delaunay mesh with input vertices and constraints marked
/// (build_cdt / the CVT) and its segment table set.
RepairResult repair_acute(Mesh& mesh, const RepairParams& params = {});

/// Bad triangles of a mesh under the bounds (forced corners exempt from the min bound).
std::vector<FaceHandle> bad_triangles(const Mesh& mesh, const AngleBounds& bounds);

}  // namespace acute
