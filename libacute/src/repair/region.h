// Private to the repair layer: a cluster's neighbourhood copied into a small mesh of its own, where
// candidate operations are tried and compared cheaply; the best one is written back.
//
// The region is every face incident to a movable vertex. Vertices of those faces that are not movable
// form the frozen ring: they become VertexKind::Input in the copy, so nothing outside the region
// changes shape and comparing the region's faces compares the whole mesh.
#pragma once

#include <acute/mesh/mesh.h>

#include <string>
#include <vector>

namespace acute::detail {

struct Region {
  Mesh sub;                             ///< the copy; frozen ring vertices are Input
  std::vector<VertexHandle> to_big;     ///< sub vertex index -> big vertex (frozen and input ones only)
  std::vector<bool> forced;             ///< forced-corner flags by sub vertex index
  std::vector<FaceHandle> big_faces;    ///< faces of the big mesh the region replaces
  std::vector<VertexHandle> big_inner;  ///< movable vertices of the big mesh
};

/// Copies the faces around `movable` into a Region (extending `movable` where a ring vertex would be
/// touched by the region in two separate fans). Returns false if the region is empty.
bool extract_region(const Mesh& big, std::vector<VertexHandle> movable, const std::vector<bool>& big_forced, Region& region);

/// Replaces the region's faces in the big mesh by those of `sub` (a modified copy of region.sub
/// whose frozen vertices are unchanged). Input vertices keep their big-mesh handles. Returns the
/// big-mesh handles of sub's other (new or re-added) vertices.
std::vector<VertexHandle> commit_region(Mesh& big, const Region& region, const Mesh& sub);

}  // namespace acute::detail

namespace acute::detail {
/// Paranoid check used by tests and ACUTE_PARANOID runs: every face counter-clockwise, every
/// constrained edge and OnSegment vertex on its input segment's line (1e-9 relative). Empty when fine.
std::string constraint_violation(const Mesh& mesh);
}  // namespace acute::detail
