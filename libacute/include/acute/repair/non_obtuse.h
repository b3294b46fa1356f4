// Layer: repair. Non-obtuse Steiner triangulation with required points (the CG:SHOP 2025
// problem): every domain point is a vertex, every segment a chain of edges, no angle above 90
// degrees (right angles allowed), few Steiner points. Points are exact rationals throughout
// (a foot of an altitude on a slanted segment is not a double), so "non-obtuse" is decided
// exactly and the result's exact coordinates are handed out as text.
#pragma once

#include <acute/core/domain.h>
#include <acute/mesh/mesh.h>

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace acute {

struct NonObtuseParams {
  std::size_t max_steiner = 0;   ///< cap on Steiner points during refinement; 0: 60 per input point + 2000
  double time_limit_s = 0;       ///< whole run (refinement, then pruning); 0: none
  double refine_time_s = 0;      ///< non_obtuse_from_start: the fixing part of time_limit_s (0: half); pruning the rest
  /// non_obtuse_triangulation without a time limit: its search gives up after this many seconds
  /// without a non-obtuse triangulation (0: never; a stalled search may then run for hours)
  double give_up_s = 0;
  unsigned seed = 1;             ///< order of the local search
  std::function<bool()> cancel;  ///< polled; true stops (the best triangulation so far is returned)
};

struct NonObtuseResult {
  bool ok = false;               ///< no exactly obtuse triangle
  Mesh mesh;                     ///< double approximations; constraint data and kinds set; no deleted elements
  /// Exact coordinates of every mesh vertex (by index): "p" or "p/q" in lowest terms.
  std::vector<std::array<std::string, 2>> exact;
  std::size_t n_steiner = 0;     ///< vertices that are not domain points
  std::size_t n_obtuse = 0;      ///< triangles with an exactly obtuse angle
  std::size_t n_right = 0;       ///< triangles with an exactly right angle
  std::size_t n_refined = 0;     ///< Steiner points after refinement, before pruning
  std::size_t rounds = 0;        ///< refinement attempts (strategies) used
};

/// Constrained Delaunay triangulation of the domain, then obtuse triangles removed by inserting
/// the best of a few candidate points per triangle (foot of the altitude from the obtuse corner,
/// exact on a segment; circumcentre when inside the domain and not behind a segment), each
/// followed by Lawson flips; then Steiner points removed while the triangulation stays
/// non-obtuse. Attempts in different orders; when all stall, a large-neighbourhood search on the
/// best one (the Steiner points near an obtuse triangle removed, the refinement rerun). Every
/// Steiner point is exactly on its segment where it lies on one.
/// \throws InvalidInput for an invalid domain (as build_cdt).
NonObtuseResult non_obtuse_triangulation(const Domain& domain, const NonObtuseParams& params = {});

/// The same refinement and pruning from a start mesh instead of the CDT: a mesh holding every
/// vertex of build_cdt(domain) (same input_index and position) and Steiner points, with its
/// constraint data and segment table (e.g. the acute repair's result on a CVT or a refined mesh;
/// see RequiredStart). Steiner points on a segment are first moved exactly onto it, then the
/// obtuse triangles left are fixed and Steiner points removed while nothing becomes obtuse.
/// Result `ok` false with an empty mesh when the start does not fit (a point missing or moved,
/// or a triangle folded by the move onto a segment). With a time limit, a success is also
/// reduced by large neighbourhoods (a patch's Steiner points removed, kept when refilled with fewer).
NonObtuseResult non_obtuse_from_start(const Domain& domain, const Mesh& start, const NonObtuseParams& params = {});

}  // namespace acute
