// Layer: repair. Clusters: connected groups of bad triangles (sharing a vertex), with the
// triangles around their vertices — the regions the local operators work on.
#pragma once

#include <acute/repair/angle_bounds.h>

#include <vector>

namespace acute {

struct Cluster {
  std::vector<FaceHandle> bad;       ///< the bad triangles
  std::vector<VertexHandle> vertices;///< their vertices
  double worst_margin = 0;           ///< most negative margin (degrees)
};

/// Bad triangles grouped into clusters, worst cluster first.
std::vector<Cluster> find_clusters(const Mesh& mesh, const AngleBounds& bounds, const std::vector<bool>& forced);

}  // namespace acute
