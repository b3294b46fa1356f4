#include "delaunay/triangulation.h"

#include <acute/core/errors.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace acute::detail {

namespace {

using predicates::incircle;
using predicates::orient2d;

inline int next3(int i) { return i == 2 ? 0 : i + 1; }
inline int prev3(int i) { return i == 0 ? 2 : i - 1; }

// Sign of (u - a) along the direction (b - a), for u collinear with a and b: exact, because
// comparing coordinates of collinear points orders them along the line.
inline bool on_ray(const Point2& a, const Point2& b, const Point2& u) {
  if (b.x() != a.x()) return (b.x() > a.x()) ? (u.x() > a.x()) : (u.x() < a.x());
  return (b.y() > a.y()) ? (u.y() > a.y()) : (u.y() < a.y());
}

}  // namespace

Triangulation::Triangulation(std::vector<Point2> points) : points_(std::move(points)) {
  vtri_.assign(points_.size(), -1);
  link_.assign(points_.size(), -1);
  rep_.resize(points_.size());
  for (std::size_t i = 0; i < rep_.size(); ++i) rep_[i] = static_cast<int>(i);
}

std::uint32_t Triangulation::rand3() const {
  rng_ ^= rng_ << 13;
  rng_ ^= rng_ >> 17;
  rng_ ^= rng_ << 5;
  return rng_ % 3u;
}

int Triangulation::new_slot() {
  if (!free_.empty()) {
    const int t = free_.back();
    free_.pop_back();
    return t;
  }
  tris_.push_back(Tri{{-1, -1, -1}, {-1, -1, -1}});
  seg_.insert(seg_.end(), 3, -1);
  stamp_.push_back(0);
  return static_cast<int>(tris_.size()) - 1;
}

void Triangulation::free_slot(int t) {
  tris_[static_cast<std::size_t>(t)].v[0] = -1;
  free_.push_back(t);
}

int Triangulation::index_in(int t, int nb) const {
  const Tri& tr = tris_[static_cast<std::size_t>(t)];
  return tr.n[0] == nb ? 0 : (tr.n[1] == nb ? 1 : 2);
}

void Triangulation::set_segment_both(int t, int i, int seg) {
  int& old = seg_[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(i)];
  if (split_crossings && old >= 0 && seg >= 0 && old != seg) overlapping_segments.emplace_back(old, seg);
  old = seg;
  const int nb = tris_[static_cast<std::size_t>(t)].n[i];
  seg_[3 * static_cast<std::size_t>(nb) + static_cast<std::size_t>(index_in(nb, t))] = seg;
}

bool Triangulation::strictly_between(int x, int y, const Point2& p) const {
  const Point2& a = point(x);
  const Point2& b = point(y);
  if (a.x() != b.x()) return (a.x() < b.x()) ? (a.x() < p.x() && p.x() < b.x()) : (b.x() < p.x() && p.x() < a.x());
  return (a.y() < b.y()) ? (a.y() < p.y() && p.y() < b.y()) : (b.y() < p.y() && p.y() < a.y());
}

bool Triangulation::in_conflict(int t, const Point2& p) const {
  const Tri& tr = tris_[static_cast<std::size_t>(t)];
  for (int k = 0; k < 3; ++k) {
    if (tr.v[k] == infinite_) {
      // Ghost: in conflict when p sees its hull edge from outside, or lies inside that edge.
      const int x = tr.v[next3(k)], y = tr.v[prev3(k)];
      const Sign o = orient2d(point(x), point(y), p);
      return o == Sign::Positive || (o == Sign::Zero && strictly_between(x, y, p));
    }
  }
  return incircle(point(tr.v[0]), point(tr.v[1]), point(tr.v[2]), p) == Sign::Positive;
}

int Triangulation::locate(const Point2& p, int hint) const {
  int t = hint >= 0 ? hint : last_;
  if (is_ghost(t)) {
    const Tri& tr = tris_[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k)
      if (tr.v[k] == infinite_) t = tr.n[k];
  }
  int prev = -1;
  for (;;) {
    if (is_ghost(t)) return t;
    const Tri& tr = tris_[static_cast<std::size_t>(t)];
    const int r = static_cast<int>(rand3());
    int moved = -1;
    for (int k = 0; k < 3; ++k) {
      const int i = (r + k) % 3;
      const int nb = tr.n[i];
      if (nb == prev) continue;
      if (orient2d(point(tr.v[next3(i)]), point(tr.v[prev3(i)]), p) == Sign::Negative) {
        moved = nb;
        break;
      }
    }
    if (moved < 0) return t;
    prev = t;
    t = moved;
  }
}

bool Triangulation::insert_points(const std::vector<int>& order) {
  if (order.size() < 3) return false;
  // First triangle: order[0], the first point different from it, the first point off their line.
  int a = order[0];
  std::size_t kb = 1;
  while (kb < order.size() && point(order[kb]) == point(a)) ++kb;
  if (kb >= order.size()) return false;
  int b = order[kb];
  std::size_t k = kb + 1;
  while (k < order.size() && orient2d(point(a), point(b), point(order[k])) == Sign::Zero) ++k;
  if (k == order.size()) return false;
  const int c = order[k];
  if (orient2d(point(a), point(b), point(c)) == Sign::Negative) std::swap(a, b);
  const std::size_t n = order.size();
  tris_.reserve(2 * n + 8);
  seg_.reserve(6 * n + 24);
  stamp_.reserve(2 * n + 8);
  const int t0 = new_slot(), ga = new_slot(), gb = new_slot(), gc = new_slot();
  const int inf = infinite_;
  tris_[static_cast<std::size_t>(t0)] = Tri{{a, b, c}, {ga, gb, gc}};
  tris_[static_cast<std::size_t>(ga)] = Tri{{c, b, inf}, {gc, gb, t0}};
  tris_[static_cast<std::size_t>(gb)] = Tri{{a, c, inf}, {ga, gc, t0}};
  tris_[static_cast<std::size_t>(gc)] = Tri{{b, a, inf}, {gb, ga, t0}};
  vtri_[static_cast<std::size_t>(a)] = vtri_[static_cast<std::size_t>(b)] = vtri_[static_cast<std::size_t>(c)] = t0;
  last_ = t0;
  for (std::size_t j = 1; j < n; ++j) {
    if (j == k || j == kb) continue;
    const int v = order[j];
    rep_[static_cast<std::size_t>(v)] = insert_vertex(v, -1, false);
  }
  return true;
}

int Triangulation::insert_new_point(const Point2& p) {
  points_.push_back(p);
  vtri_.push_back(-1);
  link_.push_back(-1);
  const int v = static_cast<int>(points_.size()) - 1;
  rep_.push_back(v);
  const int got = insert_vertex(v, -1, true);
  if (got != v) {
    points_.pop_back();
    vtri_.pop_back();
    link_.pop_back();
    rep_.pop_back();
  }
  return got;
}

int Triangulation::insert_vertex(int v, int hint, bool checked) {
  const Point2& p = point(v);
  const int t = locate(p, hint);
  if (!is_ghost(t)) {
    const Tri& tr = tris_[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k)
      if (point(tr.v[k]) == p) return tr.v[k];
  }
  const unsigned stamp = ++stamp_counter_;
  cavity_.clear();
  stack_.clear();
  boundary_.clear();
  split_edges_.clear();
  stamp_[static_cast<std::size_t>(t)] = stamp;
  stack_.push_back(t);
  while (!stack_.empty()) {
    const int c = stack_.back();
    stack_.pop_back();
    cavity_.push_back(c);
    for (int i = 0; i < 3; ++i) {
      const Tri& tc = tris_[static_cast<std::size_t>(c)];
      const int nb = tc.n[i];
      if (stamp_[static_cast<std::size_t>(nb)] == stamp) continue;
      const int s = seg_[3 * static_cast<std::size_t>(c) + static_cast<std::size_t>(i)];
      const int x = tc.v[next3(i)], y = tc.v[prev3(i)];
      bool enter;
      if (s >= 0) {
        // A constrained edge bounds the cavity, unless p lies on it: then it is split.
        enter = x != infinite_ && y != infinite_ && orient2d(point(x), point(y), p) == Sign::Zero &&
                strictly_between(x, y, p);
        if (enter) split_edges_.push_back({x, y, s});
      } else {
        enter = in_conflict(nb, p);
      }
      if (enter) {
        stamp_[static_cast<std::size_t>(nb)] = stamp;
        stack_.push_back(nb);
      } else {
        boundary_.push_back(BoundaryEdge{x, y, nb, index_in(nb, c), s});
      }
    }
  }
  ACUTE_ASSERT(boundary_.size() == cavity_.size() + 2);
  new_tris_.clear();
  for (std::size_t k = 0; k < boundary_.size(); ++k)
    new_tris_.push_back(k < cavity_.size() ? cavity_[k] : new_slot());
  for (std::size_t k = 0; k < boundary_.size(); ++k) {
    const BoundaryEdge& be = boundary_[k];
    const int nt = new_tris_[k];
    Tri& tr = tris_[static_cast<std::size_t>(nt)];
    tr.v[0] = be.x;
    tr.v[1] = be.y;
    tr.v[2] = v;
    tr.n[2] = be.nb;
    tris_[static_cast<std::size_t>(be.nb)].n[be.nbi] = nt;
    int* sg = &seg_[3 * static_cast<std::size_t>(nt)];
    sg[0] = sg[1] = -1;
    sg[2] = be.seg;
    link(be.x) = nt;
    if (be.x != infinite_) vtri_[static_cast<std::size_t>(be.x)] = nt;
  }
  for (std::size_t k = 0; k < boundary_.size(); ++k) {
    const int nt = new_tris_[k];
    Tri& tr = tris_[static_cast<std::size_t>(nt)];
    const int u = link(tr.v[1]);
    tr.n[0] = u;
    tris_[static_cast<std::size_t>(u)].n[1] = nt;
  }
  for (const auto& se : split_edges_) {
    set_segment_both(link(se[0]), 1, se[2]);
    set_segment_both(link(se[1]), 1, se[2]);
  }
  vtri_[static_cast<std::size_t>(v)] = new_tris_[0];
  last_ = new_tris_[0];
  if (checked) {
    for (int nt : new_tris_) {
      if (is_ghost(nt)) continue;
      const Tri& tr = tris_[static_cast<std::size_t>(nt)];
      ACUTE_ASSERT(orient2d(point(tr.v[0]), point(tr.v[1]), point(tr.v[2])) == Sign::Positive);
    }
  }
  return v;
}

void Triangulation::insert_segment(int a, int b, int seg) {
  if (a == b) return;
  struct Depth {
    int& d;
    explicit Depth(int& dd) : d(dd) { ++d; }
    ~Depth() { --d; }
  } depth_guard(depth_);
  if (depth_ > 200) throw InvalidInput("resolving crossings at segment " + std::to_string(seg) + " did not converge");
  const Point2 pb = point(b);
  while (a != b) {
    const Point2 pa = point(a);
    int t = vtri_[static_cast<std::size_t>(a)];
    ACUTE_ASSERT(t >= 0);
    const int start = t;
    int next_a = -1, walk_t = -1, u = -1, w = -1;
    for (;;) {
      const Tri& tr = tris_[static_cast<std::size_t>(t)];
      const int i = tr.v[0] == a ? 0 : (tr.v[1] == a ? 1 : 2);
      u = tr.v[next3(i)];
      w = tr.v[prev3(i)];
      if (u != infinite_ && w != infinite_) {
        if (u == b || w == b) {
          set_segment_both(t, u == b ? prev3(i) : next3(i), seg);
          next_a = b;
          break;
        }
        const Sign ou = orient2d(pa, pb, point(u));
        const Sign ow = orient2d(pa, pb, point(w));
        if (ou == Sign::Zero && on_ray(pa, pb, point(u))) {
          set_segment_both(t, prev3(i), seg);
          ++points_on_segments;
          next_a = u;
          break;
        }
        if (ow == Sign::Zero && on_ray(pa, pb, point(w))) {
          set_segment_both(t, next3(i), seg);
          ++points_on_segments;
          next_a = w;
          break;
        }
        if (ou == Sign::Negative && ow == Sign::Positive) {
          walk_t = t;
          break;
        }
      }
      t = tr.n[next3(i)];
      ACUTE_ASSERT(t != start);
    }
    if (next_a >= 0) {
      a = next_a;
      continue;
    }
    // Walk through the triangles crossed by a->b; u stays right of the line, w left.
    crossed_.clear();
    left_.clear();
    right_.clear();
    crossed_.push_back(walk_t);
    right_.push_back(u);
    left_.push_back(w);
    int cur = walk_t;
    int ei = tris_[static_cast<std::size_t>(cur)].v[0] == a ? 0 : (tris_[static_cast<std::size_t>(cur)].v[1] == a ? 1 : 2);
    int end = -1;
    for (;;) {
      const int s2 = seg_[3 * static_cast<std::size_t>(cur) + static_cast<std::size_t>(ei)];
      if (s2 >= 0) {
        if (!split_crossings)
          throw InvalidInput("segments " + std::to_string(s2) + " and " + std::to_string(seg) + " cross");
        // Split both at the (rounded) intersection point x and start again on the pieces. x is
        // off both lines by rounding, so the pieces a-x and x-c of this segment end at c, the
        // next vertex exactly on a-b: vertices on a-b beyond x stay on the chain, and the rest
        // c-b is inserted along the exact line again. The crossed edge u-w is one edge of its
        // chain (nothing lies inside it). Removing its constraint can leave the triangulation
        // non-Delaunay there: Lawson flips restore the CDT before x is inserted (Bowyer-Watson
        // needs a CDT for a star-shaped cavity).
        const Point2 pu = point(u), pw = point(w);
        const Point2 d = pb - pa, e = pw - pu;
        const double den = d.x() * e.y() - d.y() * e.x();
        const Point2 f = pu - pa;
        // Nearly parallel pieces (crossings at one point, rounded apart) can make den 0 or the
        // parameter absurd: keep x on the segment (NaN: its middle).
        double s = (f.x() * e.y() - f.y() * e.x()) / den;
        s = std::isnan(s) ? 0.5 : std::clamp(s, 0.0, 1.0);
        const Point2 x = pa + s * d;
        const int c = next_on_line(cur, ei, u, w, pa, pb, b);
        set_segment_both(cur, ei, -1);
        restore_delaunay(cur, ei);
        ++crossings_split;
        split_segment_ids.push_back(s2);
        split_segment_ids.push_back(seg);
        const int xv = insert_new_point(x);
        insert_segment(u, xv, s2);
        insert_segment(xv, w, s2);
        insert_segment(a, xv, seg);
        insert_segment(xv, c, seg);
        insert_segment(c, b, seg);
        return;
      }
      const int nb = tris_[static_cast<std::size_t>(cur)].n[ei];
      const int j = index_in(nb, cur);
      const int vv = tris_[static_cast<std::size_t>(nb)].v[j];
      ACUTE_ASSERT(vv != infinite_);
      crossed_.push_back(nb);
      if (vv == b) {
        end = b;
        break;
      }
      const Sign o = orient2d(pa, pb, point(vv));
      if (o == Sign::Zero) {
        end = vv;
        ++points_on_segments;
        break;
      }
      if (o == Sign::Negative) {
        right_.push_back(vv);
        u = vv;
      } else {
        left_.push_back(vv);
        w = vv;
      }
      cur = nb;
      const Tri& tn = tris_[static_cast<std::size_t>(nb)];
      ei = (tn.v[0] != u && tn.v[0] != w) ? 0 : ((tn.v[1] != u && tn.v[1] != w) ? 1 : 2);
    }
    retriangulate(a, end, seg);
    a = end;
  }
}

void Triangulation::emit(int p, int q, int c) {
  const int t = crossed_[slot_pos_++];
  tris_[static_cast<std::size_t>(t)] = Tri{{p, q, c}, {-1, -1, -1}};
  new_tris_.push_back(t);
}

void Triangulation::triangulate_chain(int p0, int q0, int lo0, int hi0) {
  // The chain_[lo..hi) lies left of p->q, ordered from p to q: pick the vertex whose circle
  // through p and q is empty of the others (circles through p, q are nested on that side).
  // Explicit stack: long segments may cross very many triangles.
  chain_stack_.clear();
  chain_stack_.push_back({p0, q0, lo0, hi0});
  while (!chain_stack_.empty()) {
    const auto [p, q, lo, hi] = chain_stack_.back();
    chain_stack_.pop_back();
    if (lo >= hi) continue;
    int ci = lo;
    for (int j = lo + 1; j < hi; ++j)
      if (incircle(point(p), point(q), point(chain_[static_cast<std::size_t>(ci)]), point(chain_[static_cast<std::size_t>(j)])) ==
          Sign::Positive)
        ci = j;
    const int c = chain_[static_cast<std::size_t>(ci)];
    emit(p, q, c);
    chain_stack_.push_back({p, c, lo, ci});
    chain_stack_.push_back({c, q, ci + 1, hi});
  }
}

void Triangulation::retriangulate(int a, int end, int seg) {
  const unsigned stamp = ++stamp_counter_;
  for (int t : crossed_) stamp_[static_cast<std::size_t>(t)] = stamp;
  auto key_of = [](int x, int y) {
    const auto lo = static_cast<std::uint32_t>(std::min(x, y)), hi = static_cast<std::uint32_t>(std::max(x, y));
    return (static_cast<std::uint64_t>(lo) << 32) | hi;
  };
  boundary_.clear();
  inner_segments_.clear();
  for (int t : crossed_) {
    const Tri& tr = tris_[static_cast<std::size_t>(t)];
    for (int i = 0; i < 3; ++i) {
      const int nb = tr.n[i];
      if (stamp_[static_cast<std::size_t>(nb)] == stamp) {
        // A constrained edge with crossed triangles on both sides is not crossed (that throws or
        // splits): both its ends lie on one side of the segment, the chain on that side goes out
        // along it and back (a spike), and the re-triangulation of the chain keeps it as an edge.
        // It is seen from both sides; the label is restored below.
        const int s = seg_[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(i)];
        if (s >= 0 && t < nb) inner_segments_.emplace_back(key_of(tr.v[next3(i)], tr.v[prev3(i)]), s);
        continue;
      }
      boundary_.push_back(BoundaryEdge{tr.v[next3(i)], tr.v[prev3(i)], nb, index_in(nb, t),
                                       seg_[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(i)]});
    }
  }
  new_tris_.clear();
  slot_pos_ = 0;
  chain_.assign(left_.begin(), left_.end());
  triangulate_chain(a, end, 0, static_cast<int>(chain_.size()));
  chain_.assign(right_.rbegin(), right_.rend());
  triangulate_chain(end, a, 0, static_cast<int>(chain_.size()));
  ACUTE_ASSERT(slot_pos_ == crossed_.size());

  recs_.clear();
  for (int t : new_tris_) {
    const Tri& tr = tris_[static_cast<std::size_t>(t)];
    for (int i = 0; i < 3; ++i) recs_.push_back(EdgeRec{key_of(tr.v[next3(i)], tr.v[prev3(i)]), t, i, -1});
  }
  for (std::size_t k = 0; k < boundary_.size(); ++k)
    recs_.push_back(EdgeRec{key_of(boundary_[k].x, boundary_[k].y), boundary_[k].nb, boundary_[k].nbi, static_cast<int>(k)});
  std::sort(recs_.begin(), recs_.end(), [](const EdgeRec& l, const EdgeRec& r) { return l.key < r.key; });
  ACUTE_ASSERT(recs_.size() % 2 == 0);
  for (std::size_t k = 0; k < recs_.size(); k += 2) {
    EdgeRec r1 = recs_[k], r2 = recs_[k + 1];
    ACUTE_ASSERT(r1.key == r2.key && (r1.boundary < 0 || r2.boundary < 0));
    if (r1.boundary >= 0) std::swap(r1, r2);
    tris_[static_cast<std::size_t>(r1.t)].n[r1.i] = r2.t;
    tris_[static_cast<std::size_t>(r2.t)].n[r2.i] = r1.t;
    int s = -1;
    if (r2.boundary >= 0) {
      s = boundary_[static_cast<std::size_t>(r2.boundary)].seg;
    } else if (r1.key == key_of(a, end)) {
      s = seg;
    } else {
      for (auto& inner : inner_segments_)
        if (inner.first == r1.key) {
          s = inner.second;
          inner.second = -1;  // found
        }
    }
    seg_[3 * static_cast<std::size_t>(r1.t) + static_cast<std::size_t>(r1.i)] = s;
    if (r2.boundary < 0) seg_[3 * static_cast<std::size_t>(r2.t) + static_cast<std::size_t>(r2.i)] = s;
  }
  for (const auto& inner : inner_segments_)
    if (inner.second >= 0)
      throw InternalError("inserting segment " + std::to_string(seg) + ": the constrained edge " + std::to_string(inner.first >> 32) + "-" +
                          std::to_string(inner.first & 0xFFFFFFFFu) + " of segment " + std::to_string(inner.second) +
                          " inside its cavity was not rebuilt");
  for (int t : new_tris_) {
    const Tri& tr = tris_[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k) vtri_[static_cast<std::size_t>(tr.v[k])] = t;
  }
  last_ = new_tris_.front();
}

int Triangulation::next_on_line(int cur, int ei, int u, int w, const Point2& pa, const Point2& pb, int b) const {
  for (;;) {
    const int nb = tris_[static_cast<std::size_t>(cur)].n[ei];
    const int j = index_in(nb, cur);
    const int vv = tris_[static_cast<std::size_t>(nb)].v[j];
    ACUTE_ASSERT(vv != infinite_);
    if (vv == b) return b;
    const Sign o = orient2d(pa, pb, point(vv));
    if (o == Sign::Zero) return vv;
    (o == Sign::Negative ? u : w) = vv;
    cur = nb;
    const Tri& tn = tris_[static_cast<std::size_t>(nb)];
    ei = (tn.v[0] != u && tn.v[0] != w) ? 0 : ((tn.v[1] != u && tn.v[1] != w) ? 1 : 2);
  }
}

void Triangulation::flip(int t, int i) {
  const int nb = tris_[static_cast<std::size_t>(t)].n[i];
  const int j = index_in(nb, t);
  const Tri a = tris_[static_cast<std::size_t>(t)], b = tris_[static_cast<std::size_t>(nb)];
  const int p = a.v[i], x = a.v[next3(i)], y = a.v[prev3(i)], q = b.v[j];
  const int* sa = &seg_[3 * static_cast<std::size_t>(t)];
  const int* sb = &seg_[3 * static_cast<std::size_t>(nb)];
  // Outer edges: y-p (A), p-x (B) of t; x-q (C), q-y (D) of nb.
  const int A = a.n[next3(i)], B = a.n[prev3(i)], C = b.n[next3(j)], D = b.n[prev3(j)];
  const int sA = sa[next3(i)], sB = sa[prev3(i)], sC = sb[next3(j)], sD = sb[prev3(j)];
  const int iA = index_in(A, t), iC = index_in(C, nb);
  // t = (p, x, q), nb = (q, y, p): counter-clockwise because p, x, q, y is a convex quadrilateral.
  tris_[static_cast<std::size_t>(t)] = Tri{{p, x, q}, {C, nb, B}};
  tris_[static_cast<std::size_t>(nb)] = Tri{{q, y, p}, {A, t, D}};
  const int st[3] = {sC, -1, sB}, sn[3] = {sA, -1, sD};
  for (int k = 0; k < 3; ++k) {
    seg_[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(k)] = st[k];
    seg_[3 * static_cast<std::size_t>(nb) + static_cast<std::size_t>(k)] = sn[k];
  }
  tris_[static_cast<std::size_t>(A)].n[iA] = nb;
  tris_[static_cast<std::size_t>(C)].n[iC] = t;
  vtri_[static_cast<std::size_t>(p)] = vtri_[static_cast<std::size_t>(x)] = t;
  vtri_[static_cast<std::size_t>(q)] = vtri_[static_cast<std::size_t>(y)] = nb;
  last_ = t;
}

void Triangulation::restore_delaunay(int t0, int i0) {
  flip_stack_.clear();
  flip_stack_.emplace_back(t0, i0);
  while (!flip_stack_.empty()) {
    const auto [t, i] = flip_stack_.back();
    flip_stack_.pop_back();
    if (!alive(t) || is_ghost(t) || segment(t, i) >= 0) continue;
    const int nb = tris_[static_cast<std::size_t>(t)].n[i];
    if (is_ghost(nb)) continue;
    const Tri& a = tris_[static_cast<std::size_t>(t)];
    const int q = tris_[static_cast<std::size_t>(nb)].v[index_in(nb, t)];
    if (incircle(point(a.v[0]), point(a.v[1]), point(a.v[2]), point(q)) != Sign::Positive) continue;
    flip(t, i);
    // The four outer edges: 0 and 2 of both new triangles.
    flip_stack_.emplace_back(t, 0);
    flip_stack_.emplace_back(t, 2);
    flip_stack_.emplace_back(nb, 0);
    flip_stack_.emplace_back(nb, 2);
  }
}

int Triangulation::find_missing_segment(int a, int b) const {
  const Point2 pb = point(b);
  int cur = a;
  for (int steps = 0; cur != b; ++steps) {
    const int start = vtri_[static_cast<std::size_t>(cur)];
    if (start < 0 || steps > num_vertices()) return cur;
    const Point2 pc = point(cur);
    int t = start, next = -1;
    do {
      const Tri& tr = tris_[static_cast<std::size_t>(t)];
      const int i = tr.v[0] == cur ? 0 : (tr.v[1] == cur ? 1 : 2);
      const int u = tr.v[next3(i)];  // edge prev3(i) joins cur and u
      if (u != infinite_ && seg_[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(prev3(i))] >= 0 &&
          (u == b || (orient2d(pc, pb, point(u)) == Sign::Zero && on_ray(pc, pb, point(u))))) {
        next = u;
        break;
      }
      t = tr.n[next3(i)];
    } while (t != start);
    if (next < 0) return cur;
    cur = next;
  }
  return -1;
}

std::string Triangulation::validate() const {
  std::ostringstream out;
  int bad = 0;
  for (int t = 0; t < num_slots() && bad < 10; ++t) {
    if (!alive(t)) continue;
    const Tri& tr = tri(t);
    for (int i = 0; i < 3; ++i) {
      const int nb = tr.n[i];
      if (nb < 0 || nb >= num_slots() || !alive(nb)) {
        out << "triangle " << t << ": neighbour " << i << " dead; ";
        ++bad;
        continue;
      }
      const int j = index_in(nb, t);
      const Tri& tn = tri(nb);
      if (tn.n[j] != t || tn.v[next3(j)] != tr.v[prev3(i)] || tn.v[prev3(j)] != tr.v[next3(i)]) {
        out << "triangle " << t << ": edge " << i << " not mutual; ";
        ++bad;
      }
      if (segment(nb, j) != segment(t, i)) {
        out << "triangle " << t << ": edge " << i << " segment ids differ; ";
        ++bad;
      }
    }
    if (!is_ghost(t) && orient2d(point(tr.v[0]), point(tr.v[1]), point(tr.v[2])) != Sign::Positive) {
      out << "triangle " << t << ": not counter-clockwise; ";
      ++bad;
    }
  }
  return out.str();
}

// ---- spatial sort -------------------------------------------------------------------------

namespace {

std::uint64_t splitmix64(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Hilbert index of (x, y) in a 2^order grid, by a 4-state table (state = transposed?, flipped?;
// both commute, so composing is xor): one lookup per level, no data-dependent branches.
struct HilbertTable {
  std::uint8_t entry[16];  // [state * 4 + (xbit << 1 | ybit)] = digit | next_state << 2
  HilbertTable() {
    for (int st = 0; st < 4; ++st)
      for (int q = 0; q < 4; ++q) {
        const int sw = st & 1, fl = st >> 1;
        int tx = ((q >> 1) & 1) ^ fl, ty = (q & 1) ^ fl;
        if (sw) std::swap(tx, ty);
        const int digit = (3 * tx) ^ ty;
        int nsw = sw, nfl = fl;
        if (ty == 0) {
          nsw ^= 1;
          if (tx == 1) nfl ^= 1;
        }
        entry[st * 4 + q] = static_cast<std::uint8_t>(digit | ((nsw | (nfl << 1)) << 2));
      }
  }
};

std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, int order) {
  static const HilbertTable table;
  std::uint64_t d = 0;
  unsigned st = 0;
  for (int l = order - 1; l >= 0; --l) {
    const unsigned q = (((x >> l) & 1u) << 1) | ((y >> l) & 1u);
    const unsigned e = table.entry[st * 4 + q];
    d = (d << 2) | (e & 3u);
    st = e >> 2;
  }
  return d;
}

}  // namespace

std::vector<int> brio_hilbert_order(const std::vector<Point2>& points, std::uint64_t seed) {
  const std::size_t n = points.size();
  std::vector<int> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<int>(i);
  if (n < 2) return order;
  for (std::size_t i = n - 1; i > 0; --i)
    std::swap(order[i], order[static_cast<std::size_t>(((splitmix64(seed) >> 32) * (i + 1)) >> 32)]);
  double minx = points[0].x(), maxx = minx, miny = points[0].y(), maxy = miny;
  for (const auto& p : points) {
    minx = std::min(minx, p.x());
    maxx = std::max(maxx, p.x());
    miny = std::min(miny, p.y());
    maxy = std::max(maxy, p.y());
  }
  constexpr int kOrder = 16;
  const double scale = static_cast<double>((1u << kOrder) - 1) / std::max({maxx - minx, maxy - miny, 1e-300});
  // Keys computed once in input order (sequential reads of the points).
  std::vector<std::uint32_t> key(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto qx = static_cast<std::uint32_t>((points[i].x() - minx) * scale);
    const auto qy = static_cast<std::uint32_t>((points[i].y() - miny) * scale);
    key[i] = static_cast<std::uint32_t>(hilbert_index(qx, qy, kOrder));
  }
  // (32-bit Hilbert key << 32 | index), radix-sorted on the key bytes.
  std::vector<std::uint64_t> keyed, tmp;
  keyed.reserve(n);
  tmp.resize(n);
  // Rounds [0, n/2^k), ..., [n/4, n/2), [n/2, n), each in Hilbert order.
  std::size_t lo = 0;
  std::size_t hi = n;
  std::vector<std::size_t> bounds;
  while (hi > 64) {
    bounds.push_back(hi);
    hi /= 2;
  }
  bounds.push_back(hi);
  std::reverse(bounds.begin(), bounds.end());
  for (std::size_t r = 0; r < bounds.size(); ++r) {
    const std::size_t end = bounds[r];
    keyed.clear();
    for (std::size_t i = lo; i < end; ++i)
      keyed.push_back((static_cast<std::uint64_t>(key[static_cast<std::size_t>(order[i])]) << 32) | static_cast<std::uint32_t>(order[i]));
    if (keyed.size() < 1024) {
      std::sort(keyed.begin(), keyed.end());
    } else {
      for (int shift = 32; shift < 64; shift += 8) {
        std::size_t count[257] = {};
        for (std::uint64_t x : keyed) ++count[((x >> shift) & 0xFF) + 1];
        for (int b = 0; b < 256; ++b) count[b + 1] += count[b];
        for (std::uint64_t x : keyed) tmp[count[(x >> shift) & 0xFF]++] = x;
        std::copy(tmp.begin(), tmp.begin() + static_cast<std::ptrdiff_t>(keyed.size()), keyed.begin());
      }
    }
    for (std::size_t i = lo; i < end; ++i) order[i] = static_cast<int>(keyed[i - lo] & 0xFFFFFFFFu);
    lo = end;
  }
  return order;
}

}  // namespace acute::detail
