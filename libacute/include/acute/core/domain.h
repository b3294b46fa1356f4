// Layer: core. The input of the mesher: a planar straight-line graph (PSLG).
#pragma once

#include <acute/core/types.h>

#include <array>
#include <string>
#include <vector>

namespace acute {

/// A planar straight-line graph with Triangle `-p` semantics: the domain is the union of the
/// bounded regions enclosed by segments, minus the regions containing a hole seed.
/// Segments inside the domain are interior constraints. Every point is kept in the mesh
/// (points outside the domain are dropped by the mesher).
struct Domain {
  std::vector<Point2> points;
  std::vector<int> point_markers;                 ///< boundary marker per point (0 when none)
  std::vector<std::array<int, 2>> segments;       ///< indices into points
  std::vector<int> segment_markers;               ///< boundary marker per segment (0 when none)
  std::vector<Point2> holes;                      ///< hole seed points
  /// Mesh the convex hull of the points (Triangle `-c`), not only what the segments enclose.
  bool convex_hull = false;
  std::string name;                               ///< e.g. the file stem, for messages and reports
  std::string source_path;                        ///< the file it was read from, if any
  std::string instance_uid;                       ///< CG:SHOP instance uid, if any

  std::size_t num_points() const { return points.size(); }
  std::size_t num_segments() const { return segments.size(); }
};

}  // namespace acute
