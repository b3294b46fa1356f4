// Layer: delaunay (private). The index-based constrained Delaunay engine behind build_cdt:
// flat arrays of triangles (3 vertex ids, 3 neighbour ids, 3 segment ids), an infinite vertex
// with ghost triangles over the hull edges, Bowyer-Watson insertion with a remembering
// stochastic walk, and segment insertion by cavity re-triangulation. All decisions are exact
// (acute::predicates).
#pragma once

#include <acute/core/types.h>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace acute::detail {

class Triangulation {
 public:
  /// Edge i of a triangle joins vertices (i+1)%3 and (i+2)%3 (it is opposite vertex i);
  /// neighbour i shares that edge. Finite triangles are counter-clockwise; a ghost triangle
  /// holds the infinite vertex and the hull edge seen from outside.
  struct Tri {
    int v[3];
    int n[3];
  };

  /// The points may repeat: a point equal to an inserted one is not inserted (see rep).
  explicit Triangulation(std::vector<Point2> points);

  /// Inserts the given vertices (indices into the points) in this order. Afterwards rep(v) is
  /// v, or the vertex holding the same position. Returns false, and builds nothing, when all the
  /// points are collinear (or fewer than 3 distinct).
  bool insert_points(const std::vector<int>& order);
  int rep(int v) const { return rep_[static_cast<std::size_t>(v)]; }

  /// Adds a new point and inserts it (constraints respected; a point exactly on a constrained
  /// edge splits it). Returns its vertex id, or the id of an existing vertex at that position.
  /// \pre insert_points returned true.
  int insert_new_point(const Point2& p);

  /// Makes the segment between vertices a and b a chain of constrained edges labelled seg.
  /// Vertices exactly on it split it; crossing a constrained edge throws InvalidInput naming
  /// both segment ids, or (split_crossings) inserts the rounded intersection point.
  void insert_segment(int a, int b, int seg);

  /// -1 when the segment between vertices a and b is a chain of constrained edges (any labels);
  /// otherwise the vertex where the chain from a breaks. Linear in the degrees along the chain.
  /// Exact: only for segments not split at rounded crossing points.
  int find_missing_segment(int a, int b) const;

  bool split_crossings = false;
  std::vector<int> split_segment_ids;  ///< segments split at a rounded crossing point (may repeat)
  /// Pairs of segments sharing a constrained edge (collinear overlap; recorded with split_crossings):
  /// the edge carries one label, so a split of it bends both.
  std::vector<std::pair<int, int>> overlapping_segments;
  std::size_t points_on_segments = 0;  ///< vertices found in a segment's interior
  std::size_t crossings_split = 0;

  // Read access.
  int num_vertices() const { return static_cast<int>(points_.size()); }  ///< finite vertices
  int infinite() const { return infinite_; }
  const Point2& point(int v) const { return points_[static_cast<std::size_t>(v)]; }
  int num_slots() const { return static_cast<int>(tris_.size()); }
  bool alive(int t) const { return tris_[static_cast<std::size_t>(t)].v[0] >= 0; }
  bool is_ghost(int t) const {
    const Tri& tr = tris_[static_cast<std::size_t>(t)];
    return tr.v[0] == infinite_ || tr.v[1] == infinite_ || tr.v[2] == infinite_;
  }
  const Tri& tri(int t) const { return tris_[static_cast<std::size_t>(t)]; }
  int segment(int t, int i) const { return seg_[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(i)]; }
  /// A live triangle incident to v (-1 if v was never inserted).
  int vertex_triangle(int v) const { return vtri_[static_cast<std::size_t>(v)]; }

  /// A triangle containing p (closed), or a ghost triangle whose hull edge p lies strictly outside.
  int locate(const Point2& p, int hint = -1) const;

  /// Consistency of the structure (neighbours mutual, finite triangles CCW); empty when fine.
  std::string validate() const;

 private:
  struct BoundaryEdge {
    int x, y;     // directed as in the removed triangle
    int nb, nbi;  // outside neighbour and the index of the shared edge in it
    int seg;
  };
  struct EdgeRec {
    std::uint64_t key;
    int t, i;      // new triangle and edge, or outside neighbour
    int boundary;  // index into boundary_ or -1
  };

  int insert_vertex(int v, int hint, bool checked);
  bool in_conflict(int t, const Point2& p) const;
  bool strictly_between(int x, int y, const Point2& p) const;
  int new_slot();
  void free_slot(int t);
  void set_segment_both(int t, int i, int seg);
  void retriangulate(int a, int end, int seg);
  // Crossing splits: the edge of t opposite index i becomes p-q (both triangles finite).
  void flip(int t, int i);
  // Lawson flips from the unconstrained edge i of t until every unconstrained edge they touch is
  // locally Delaunay: restores the CDT after a constraint is removed.
  void restore_delaunay(int t, int i);
  // From the constrained edge ei of cur crossed by the line pa->pb (u right, w left of it), the
  // first vertex beyond it lying exactly on that line (b at the latest), walking through edges
  // whether constrained or not.
  int next_on_line(int cur, int ei, int u, int w, const Point2& pa, const Point2& pb, int b) const;
  void triangulate_chain(int p, int q, int lo, int hi);
  int index_in(int t, int nb) const;
  int& link(int v) { return v == infinite_ ? link_inf_ : link_[static_cast<std::size_t>(v)]; }
  void emit(int p, int q, int c);
  std::size_t slot_pos_ = 0;
  std::uint32_t rand3() const;

  std::vector<Point2> points_;
  int infinite_ = std::numeric_limits<int>::max();
  int link_inf_ = -1;
  std::vector<Tri> tris_;
  std::vector<int> seg_;
  std::vector<int> vtri_;
  std::vector<int> rep_;
  std::vector<int> free_;
  std::vector<unsigned> stamp_;
  unsigned stamp_counter_ = 0;
  int last_ = -1;
  mutable std::uint32_t rng_ = 2463534242u;

  // Scratch, reused across operations (no allocation in hot loops).
  std::vector<int> cavity_, stack_, link_, crossed_, left_, right_, chain_, new_tris_;
  std::vector<std::pair<std::uint64_t, int>> inner_segments_;  // constrained edges inside a cavity
  std::vector<BoundaryEdge> boundary_;
  std::vector<EdgeRec> recs_;
  std::vector<std::array<int, 3>> split_edges_;
  std::vector<std::array<int, 4>> chain_stack_;
  std::vector<std::pair<int, int>> flip_stack_;
  int depth_ = 0;
};

/// Insertion order: a biased randomized insertion order whose rounds are Hilbert-sorted
/// (deterministic seed).
std::vector<int> brio_hilbert_order(const std::vector<Point2>& points, std::uint64_t seed = 0x9E3779B97F4A7C15ull);

}  // namespace acute::detail
