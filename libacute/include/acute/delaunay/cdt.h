// Layer: delaunay. Constrained Delaunay triangulation of a Domain, built by a fast index-based
// engine (spatial sort + walking point location + cavity re-triangulation for segments) and
// handed over as an acute::Mesh with constraint data filled in.
#pragma once

#include <acute/core/domain.h>
#include <acute/mesh/mesh.h>

#include <cstddef>
#include <string>
#include <vector>

namespace acute {

/// What to do when two input segments cross at a point that is not an input point.
enum class CrossingSegments {
  Error,  ///< throw InvalidInput naming both segments
  Split   ///< insert the (rounded) intersection point and split both
};

struct CdtOptions {
  CrossingSegments crossing = CrossingSegments::Error;
};

struct CdtStats {
  std::size_t merged_duplicates = 0;   ///< input points equal to an earlier one
  std::size_t points_on_segments = 0;  ///< input points lying on a segment's interior (segment split)
  std::size_t crossings_split = 0;     ///< with CrossingSegments::Split
  std::size_t dropped_points = 0;      ///< input points outside the domain
  std::vector<std::string> warnings;
};

/// The constrained Delaunay triangulation of the domain (Triangle `-p` semantics; `-c` when
/// domain.convex_hull). Every input point inside the closed domain is a vertex (kind Input,
/// input_index set); every segment is a chain of edges with data(eh).segment = its index.
/// \throws InvalidInput on crossing segments (CrossingSegments::Error) or an empty domain.
/// \post check_mesh(result, CheckLevel::Delaunay).ok()
Mesh build_cdt(const Domain& domain, const CdtOptions& options = {}, CdtStats* stats = nullptr);

/// Unconstrained Delaunay triangulation of a point set (convex hull), e.g. for benchmarks.
/// Returns triangles as counter-clockwise index triples; duplicates are skipped.
std::vector<std::array<int, 3>> delaunay_triangles(const std::vector<Point2>& points);

}  // namespace acute
