// Layer: repair (internal). A constrained triangulation on exact rational points (GMP), with
// the local operators the non-obtuse solver needs (edge split, point insertion, vertex removal,
// Lawson flips) and a journal so any sequence of them can be tried and undone. Predicates are
// filtered: doubles with an error bound, exact rationals when the filter cannot decide.
#pragma once

#include <acute/mesh/mesh.h>
#include <acute/mesh/segments.h>

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace acute::exact {

using Q = mpq_class;

/// An exact point and its nearest doubles (err bounds |x - dx| and |y - dy|).
struct XPoint {
  Q x, y;
  double dx = 0, dy = 0, err = 0;
  XPoint() = default;
  XPoint(Q px, Q py);
};

int orient(const XPoint& p, const XPoint& q, const XPoint& r);              ///< sign of (q-p) x (r-p)
int dot_sign(const XPoint& apex, const XPoint& p, const XPoint& q);         ///< sign of (p-apex).(q-apex)
int incircle(const XPoint& a, const XPoint& b, const XPoint& c, const XPoint& d);  ///< > 0: d inside circle abc (ccw)

/// Triangle: corners counter-clockwise; edge k is opposite corner k (v[k+1], v[k+2]).
struct Tri {
  std::array<int, 3> v{{-1, -1, -1}};
  std::array<int, 3> n{{-1, -1, -1}};    ///< neighbour across edge k; -1 outside the domain
  std::array<int, 3> seg{{-1, -1, -1}};  ///< input segment of edge k; -1 unconstrained
  bool alive = true;
  /// Cached class of the corners (-1 not yet known, 0 acute, 1 a right corner, 2 an obtuse
  /// corner): the corners never move, and the exact test of a right angle is costly.
  mutable signed char cls = -1;
};

class Triangulation {
 public:
  /// From a constrained triangulation (build_cdt): its vertices are the required points.
  static Triangulation from_mesh(const Mesh& mesh);
  /// From a mesh holding every vertex of `cdt` (same input_index, same position) plus Steiner
  /// points, constraint data and segment table set (e.g. a repaired mesh): the CDT's vertices
  /// are the required points, in its order (to_mesh(cdt, ...) then works); Steiner points on a
  /// segment (endpoints by segment id in `segments`) are moved exactly onto it. False when the
  /// start does not fit (a CDT point missing, or a triangle folded by that move).
  static bool from_start(const Mesh& cdt, const Mesh& start, const SegmentTable& segments, Triangulation& out);
  /// Live part as a Mesh (kinds, input indices, segment ids and table as in `like`); exact
  /// coordinates per output vertex into *exact.
  Mesh to_mesh(const Mesh& like, std::vector<std::array<std::string, 2>>* exact) const;

  int n_tris() const { return static_cast<int>(tris_.size()); }
  const Tri& tri(int t) const { return tris_[static_cast<std::size_t>(t)]; }
  const XPoint& point(int v) const { return pts_[static_cast<std::size_t>(v)]; }
  bool alive_point(int v) const { return alive_[static_cast<std::size_t>(v)] != 0; }
  bool is_required(int v) const { return v < n_required_; }
  int triangle_of(int v) const { return vtri_[static_cast<std::size_t>(v)]; }

  /// Corner with an obtuse angle, or -1.
  int obtuse_corner(int t) const;
  bool is_obtuse(const Tri& t) const;
  bool is_right(const Tri& t) const;
  std::size_t n_obtuse() const;
  std::size_t n_right() const;
  std::size_t n_steiner() const { return n_steiner_; }
  std::vector<int> steiner_vertices() const;
  std::vector<int> neighbours(int v) const;
  std::vector<int> fan_of(int v) const;
  /// Edges at v: (other end, segment or -1).
  std::vector<std::pair<int, int>> spokes(int v) const;

  // Operators (call inside a transaction). They return the new vertex or -1 / false, and leave
  // the triangulation constrained Delaunay (Lawson flips).
  int split_edge(int t, int k, const XPoint& p);  ///< p exactly inside edge k of t
  int insert(const XPoint& p, int start);          ///< located by a walk from start; not behind a segment
  bool remove_vertex(int v);                       ///< Steiner points only

  // Journal.
  /// A point inside the open transaction to come back to (any number of them, innermost first).
  struct Mark {
    std::size_t tlog, vlog, alog, ntris, npts, nsteiner;
  };
  void begin();
  void nest();      ///< a mark inside the transaction
  void unnest();    ///< back to the mark
  Mark mark() const;
  void rollback_to(const Mark& m);
  void commit();
  void rollback();  ///< back to begin()
  /// Triangle slots changed or created since begin() (live or dead).
  std::vector<int> touched() const;
  /// Values at begin() of the slots that existed then and were changed.
  std::vector<Tri> touched_originals() const;
  /// Triangle slots changed or created since mark m (live or dead).
  std::vector<int> touched_since(const Mark& m) const;
  const std::vector<int>& last_touched() const { return last_touched_; }

 private:
  void build(const Mesh& mesh, const std::vector<int>& vertex_slot, std::vector<XPoint> pts, int n_required);
  void set_tri(int t, const Tri& value);
  void set_vtri(int v, int t);
  void set_alive(int v, char a);
  int add_point(const XPoint& p);
  /// Replaces triangles `old` by `fresh` (same region); fresh edges not shared within fresh and
  /// not in old take their segment from `segs` (undirected) and have no neighbour.
  std::vector<int> replace(const std::vector<int>& old, const std::vector<std::array<int, 3>>& fresh,
                           const std::vector<std::array<int, 3>>& segs);
  void legalize(const std::vector<int>& tris);
  /// Triangles around v counter-clockwise; open is true when v is on the domain boundary (then
  /// the first and last triangle have the boundary edges).
  bool fan(int v, std::vector<int>& out, bool& open) const;

  std::vector<XPoint> pts_;
  std::vector<char> alive_;
  std::vector<int> vtri_;
  std::vector<Tri> tris_;
  std::vector<int> seg_marker_;
  int n_required_ = 0;
  std::size_t n_steiner_ = 0;

  bool open_ = false;
  Mark begin_{}, nest_{};
  std::vector<std::pair<int, Tri>> tlog_;
  std::vector<std::pair<int, int>> vlog_;
  std::vector<std::pair<int, char>> alog_;
  std::vector<int> last_touched_;
  mutable std::vector<unsigned> stamp_;
  mutable unsigned epoch_ = 0;
};

}  // namespace acute::exact
