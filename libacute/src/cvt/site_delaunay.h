// Layer: cvt (private). The unconstrained Delaunay triangulation of the CVT sites over their
// convex hull, kept from one evaluation to the next. Its edges give every site the bisectors
// that bound its Voronoi cell, whatever the mesh (a constrained Delaunay mesh is not Delaunay
// next to a constraint, and it has no triangles in holes or concavities, so its edges alone
// miss Voronoi neighbours across them).
#pragma once

#include <acute/core/types.h>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace acute::detail {

class SiteDelaunay {
 public:
  /// A triangulation the caller has already of part of the sites' hull (a mesh region): its
  /// triangles (counter-clockwise, in site ids) and its border (directed edges with the part on
  /// their left). The rest, up to the frame, is small (the border's constrained triangulation), and
  /// Lawson flips make the whole Delaunay: linear where the part is nearly Delaunay already, as a
  /// constrained Delaunay mesh is away from its constraints.
  struct Seed {
    std::vector<std::array<int, 3>> triangles;
    std::vector<std::array<int, 2>> border;
  };

  /// Makes this the Delaunay triangulation of `points` and a frame of four far points around them
  /// (ids points.size() .. + 3): with the frame, nearly collinear sites on a straight boundary
  /// segment (collinear but for rounding) make no sliver on the hull, which their sliding along
  /// the segment would turn over. When the previous triangulation was of the same number of
  /// points (same identities: `same_sites`) and every triangle is still counter-clockwise at the
  /// new positions, it is repaired by Lawson flips (exact incircle), which is linear for small
  /// moves; otherwise it is rebuilt from scratch.
  /// Without a repairable previous triangulation, a `seed` (when given and consistent with the
  /// points) replaces the build from scratch.
  void update(const std::vector<Point2>& points, bool same_sites, const Seed* seed = nullptr);

  /// The Delaunay neighbours of site i (every site sharing an edge with it; never the frame).
  std::pair<const int*, const int*> neighbours(int i) const {
    const auto b = static_cast<std::size_t>(start_[static_cast<std::size_t>(i)]);
    const auto e = static_cast<std::size_t>(start_[static_cast<std::size_t>(i) + 1]);
    return {adjacent_.data() + b, adjacent_.data() + e};
  }

  /// Every triangle, the frame's too: a corner >= num_sites() is a frame point.
  const std::vector<std::array<int, 3>>& triangles() const { return tri_; }
  std::size_t num_sites() const { return n_sites_; }
  /// The triangle across the edge opposite corner i of t; -1 on the hull.
  int across(int t, int i) const { return nbr_[static_cast<std::size_t>(t)][static_cast<std::size_t>(i)]; }
  /// A triangle incident to site i.
  int vertex_triangle(int i) const { return vertex_tri_[static_cast<std::size_t>(i)]; }

  std::size_t rebuilds() const { return rebuilds_; }
  std::size_t flips() const { return flips_; }
  std::size_t seeded_builds() const { return seeded_; }  ///< of the rebuilds, those from a seed

 private:
  void rebuild();
  bool build_from_seed(const Seed& seed);
  void link_neighbours();
  bool all_counter_clockwise() const;
  void lawson();
  void flip(int t, int i);
  void build_adjacency();

  std::vector<Point2> points_;  ///< the sites, then the frame
  std::size_t n_sites_ = 0;
  std::vector<std::array<int, 3>> tri_;  ///< counter-clockwise vertex ids
  std::vector<std::array<int, 3>> nbr_;  ///< nbr_[t][i]: across the edge opposite corner i; -1 on the hull
  std::vector<int> start_, adjacent_;    ///< CSR of the neighbours
  std::vector<int> vertex_tri_;
  std::vector<int> incident_start_, incident_;  ///< rebuild scratch: triangles around each vertex
  std::vector<std::pair<int, int>> stack_;      ///< (triangle, edge) to check
  std::vector<int> border_local_;               ///< seed scratch: site -> border point, or -1
  std::size_t rebuilds_ = 0, flips_ = 0, seeded_ = 0;
};

}  // namespace acute::detail
