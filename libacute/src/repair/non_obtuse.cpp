#include <acute/repair/non_obtuse.h>

#include "repair/exact_triangulation.h"
#include "repair/polygon_centre.h"

#include <acute/delaunay/cdt.h>
#include <acute/mesh/segments.h>

#include <algorithm>
#include <chrono>
#include <random>

namespace acute {

namespace {

using exact::Q;
using exact::Triangulation;
using exact::XPoint;
using exact::XY;
using exact::polygon_centres;

using Clock = std::chrono::steady_clock;

/// Bits of a rational (numerator + denominator): Steiner points built from Steiner points grow.
std::size_t bits(const Q& q) {
  return mpz_sizeinbase(q.get_num_mpz_t(), 2) + mpz_sizeinbase(q.get_den_mpz_t(), 2);
}

/// Above this, a point that need not be exact (off the segments) is rounded to doubles.
constexpr std::size_t kMaxBits = 400;

XPoint rounded(const XPoint& p) { return XPoint(Q(p.dx), Q(p.dy)); }

/// The foot of p on the line through a with direction (dx, dy): a + r (dx, dy), with r in `r`
/// (0 < r < 1: strictly inside the segment from a to a + (dx, dy)). Exact.
XPoint foot_on_line(const XPoint& p, const XPoint& a, const Q& dx, const Q& dy, Q& r) {
  r = ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
  return XPoint(a.x + r * dx, a.y + r * dy);
}

XPoint foot_on_line(const XPoint& p, const XPoint& a, const Q& dx, const Q& dy) {
  Q r;
  return foot_on_line(p, a, dx, dy, r);
}

/// How many of `spokes` (a vertex's neighbours with their segment ids) are segment edges; the
/// first two in `ends` (a Steiner point on a segment has 2, a free one 0).
int constrained_ends(const std::vector<std::pair<int, int>>& spokes, int ends[2]) {
  int n = 0;
  for (const auto& [w, seg] : spokes)
    if (seg >= 0 && n++ < 2) ends[n - 1] = w;
  return n;
}

struct Candidate {
  enum Kind { EdgeSplit, Free, Remove, Relocate } kind;
  /// EdgeSplit: the edge; Free: where the walk starts; Remove: tri is the vertex; Relocate: the
  /// vertex tri goes, p comes (walk from a triangle at its first neighbour edge)
  int tri = -1, edge = -1;
  XPoint p;
};

class NonObtuseSolver {
 public:
  NonObtuseSolver(Triangulation& tr, const NonObtuseParams& params, Clock::time_point deadline)
      : tr_(tr), params_(params), deadline_(deadline), rng_(params.seed) {}

  bool out_of_time() const {
    return Clock::now() > deadline_ || (params_.cancel && params_.cancel());
  }

  /// Candidate points that could remove the obtuse angle of triangle t.
  std::vector<Candidate> candidates(int t) const {
    std::vector<Candidate> out;
    const int k = tr_.obtuse_corner(t);
    if (k < 0) return out;
    const auto& tri = tr_.tri(t);
    const XPoint& c = tr_.point(tri.v[k]);
    const XPoint& a = tr_.point(tri.v[(k + 1) % 3]);
    const XPoint& b = tr_.point(tri.v[(k + 2) % 3]);
    // Foot of the altitude from the obtuse corner: two right triangles on this side.
    const XPoint exact_foot = foot_on_line(c, a, b.x - a.x, b.y - a.y);
    XPoint foot = exact_foot;
    if (tri.seg[k] >= 0) {
      out.push_back({Candidate::EdgeSplit, t, k, foot});
    } else {
      if (bits(foot.x) + bits(foot.y) > 2 * kMaxBits) {
        // Rounded, and pushed a hair away from c so both angles at the foot stay below 90.
        const double ux = foot.dx - c.dx, uy = foot.dy - c.dy;
        foot = XPoint(Q(foot.dx + 1e-9 * ux), Q(foot.dy + 1e-9 * uy));
        out.push_back({Candidate::Free, t, -1, foot});
      } else {
        out.push_back({Candidate::EdgeSplit, t, k, foot});
      }
      // Points between the foot and the far corner d across ab: one point for both sides.
      if (tri.n[k] >= 0) {
        const auto& nt = tr_.tri(tri.n[k]);
        int m = 0;
        while (nt.v[m] == tri.v[(k + 1) % 3] || nt.v[m] == tri.v[(k + 2) % 3]) ++m;
        const XPoint& d = tr_.point(nt.v[m]);
        const double fx = exact_foot.x.get_d(), fy = exact_foot.y.get_d();
        for (double lambda : {0.2, 0.45})
          out.push_back({Candidate::Free, t, -1, XPoint(Q(fx + lambda * (d.dx - fx)), Q(fy + lambda * (d.dy - fy)))});
      }
      // Circumcentre (beyond edge ab for an obtuse triangle), rounded: it need not be exact.
      const double ax = a.dx - c.dx, ay = a.dy - c.dy, bx = b.dx - c.dx, by = b.dy - c.dy;
      const double d = 2 * (ax * by - ay * bx);
      if (d != 0) {
        const double la = ax * ax + ay * ay, lb = bx * bx + by * by;
        const double ox = c.dx + (by * la - ay * lb) / d, oy = c.dy + (ax * lb - bx * la) / d;
        if (std::isfinite(ox) && std::isfinite(oy)) out.push_back({Candidate::Free, tri.n[k], -1, XPoint(Q(ox), Q(oy))});
      }
    }
    if (tri.seg[k] < 0) ray_candidates(t, k, out);
    centre_candidates(t, out);
    square_candidates(t, k, out);
    // Removing a Steiner corner (two Steiner points close on a segment make a needle that no
    // insertion mends).
    for (int m = 0; m < 3; ++m)
      if (!tr_.is_required(tri.v[m])) out.push_back({Candidate::Remove, tri.v[m], -1, XPoint()});
    // Midpoint of the longest edge (on a segment: exact), a robust last choice.
    XPoint mid((a.x + b.x) / 2, (a.y + b.y) / 2);
    if (tri.seg[k] < 0 && bits(mid.x) + bits(mid.y) > 2 * kMaxBits) mid = rounded(mid);
    out.push_back({Candidate::EdgeSplit, t, k, mid});
    if (tri.seg[k] < 0 && !(mid.x == (a.x + b.x) / 2 && mid.y == (a.y + b.y) / 2)) out.back().kind = Candidate::Free;
    return out;
  }

  /// Rays from the obtuse corner c of t until they meet a segment: the altitude (perpendicular
  /// to edge k), and along and perpendicular to each segment edge at c. Candidates: where a ray
  /// meets the segment, and the foot of the perpendicular from c on it (right angles against
  /// segments, as in a rectangular partition of an orthogonal polygon).
  void ray_candidates(int t, int k, std::vector<Candidate>& out) const {
    const auto& tri0 = tr_.tri(t);
    const int cv = tri0.v[k];
    const XPoint& c = tr_.point(cv);
    const XPoint& a = tr_.point(tri0.v[(k + 1) % 3]);
    const XPoint& b = tr_.point(tri0.v[(k + 2) % 3]);
    std::vector<std::pair<Q, Q>> dirs;
    dirs.emplace_back(b.y - a.y, -(b.x - a.x));  // right normal of ab: away from c
    for (const auto& [w, seg] : tr_.spokes(cv)) {
      if (seg < 0) continue;
      const XPoint& pw = tr_.point(w);
      const Q ux = pw.x - c.x, uy = pw.y - c.y;
      dirs.emplace_back(-ux, -uy);
      dirs.emplace_back(-uy, ux);
      dirs.emplace_back(uy, -ux);
    }
    for (const auto& [ex, ey] : dirs) shoot(cv, ex, ey, out);
  }

  void shoot(int cv, const Q& ex, const Q& ey, std::vector<Candidate>& out) const {
    const XPoint& c = tr_.point(cv);
    auto cross = [&](const XPoint& p) -> Q { return ex * (p.y - c.y) - ey * (p.x - c.x); };
    // The triangle around c whose wedge holds the direction.
    int cur = -1, exit = -1;
    for (int f : tr_.fan_of(cv)) {
      const auto& u = tr_.tri(f);
      int i = 0;
      while (u.v[i] != cv) ++i;
      const int sx = sgn(cross(tr_.point(u.v[(i + 1) % 3]))), sy = sgn(cross(tr_.point(u.v[(i + 2) % 3])));
      if (sx < 0 && sy > 0) {  // x right of the ray, y left: the ray runs between them
        cur = f;
        exit = i;
        break;
      }
    }
    if (cur < 0) return;
    for (int step = 0; step < 64; ++step) {
      const auto& u = tr_.tri(cur);
      const int x = u.v[(exit + 1) % 3], y = u.v[(exit + 2) % 3];
      if (u.seg[exit] >= 0) {
        const XPoint &px = tr_.point(x), &py = tr_.point(y);
        const Q cx = cross(px), cy = cross(py);
        const Q s = cx / (cx - cy);
        XPoint hit(px.x + s * (py.x - px.x), px.y + s * (py.y - px.y));
        if (bits(hit.x) + bits(hit.y) <= 2 * kMaxBits) out.push_back({Candidate::EdgeSplit, cur, exit, hit});
        Q r;
        const XPoint foot = foot_on_line(c, px, py.x - px.x, py.y - px.y, r);
        if (r > 0 && r < 1 && bits(foot.x) + bits(foot.y) <= 2 * kMaxBits) out.push_back({Candidate::EdgeSplit, cur, exit, foot});
        return;
      }
      const int next = u.n[exit];
      if (next < 0) return;
      const auto& w = tr_.tri(next);
      int m = 0;
      while (w.v[m] == x || w.v[m] == y) ++m;  // the far corner of next
      const int s = sgn(cross(tr_.point(w.v[m])));
      if (s == 0) return;  // through a vertex
      // Entered through (y, x) seen from next; leave through the edge the ray crosses.
      const int far = w.v[m];
      int leave = -1;
      for (int j = 0; j < 3; ++j) {
        const int p = w.v[(j + 1) % 3], q = w.v[(j + 2) % 3];
        if ((p == x && q == y) || (p == y && q == x)) continue;
        const int sp = p == far ? s : sgn(cross(tr_.point(p)));
        const int sq = q == far ? s : sgn(cross(tr_.point(q)));
        if (sp != sq) leave = j;
      }
      if (leave < 0) return;
      cur = next;
      exit = leave;
    }
  }

  /// Polygon centres: of t with its neighbours across unconstrained edges (a point that fans
  /// that region into non-obtuse triangles), and of the link of a Steiner corner of t (moving
  /// the corner there).
  void centre_candidates(int t, std::vector<Candidate>& out) const {
    const auto& tri = tr_.tri(t);
    auto xy = [&](int v) { return XY{tr_.point(v).dx, tr_.point(v).dy}; };
    std::vector<XY> region;
    for (int i = 0; i < 3; ++i) {
      const int a = tri.v[i], b = tri.v[(i + 1) % 3];
      region.push_back(xy(a));
      const int k = (i + 2) % 3;  // edge a -> b
      if (tri.seg[k] < 0 && tri.n[k] >= 0) {
        const auto& nt = tr_.tri(tri.n[k]);
        for (int m = 0; m < 3; ++m)
          if (nt.v[m] != a && nt.v[m] != b) region.push_back(xy(nt.v[m]));
      }
    }
    for (const auto& p : polygon_centres(region, 4)) out.push_back({Candidate::Free, t, -1, XPoint(Q(p.first), Q(p.second))});
    for (int m = 0; m < 3; ++m) {
      const int v = tri.v[m];
      if (tr_.is_required(v)) continue;
      std::vector<int> fan = tr_.fan_of(v);
      if (fan.empty()) continue;
      std::vector<XY> link;
      bool open = false;
      for (int f : fan) {
        const auto& u = tr_.tri(f);
        int i = 0;
        while (u.v[i] != v) ++i;
        link.push_back(xy(u.v[(i + 1) % 3]));
        if (u.n[(i + 1) % 3] < 0 || u.seg[(i + 1) % 3] >= 0) open = true;
      }
      if (open) {  // on a segment: it may only slide along it
        slide_candidates(v, out);
        continue;
      }
      const int anchor = tr_.tri(fan[0]).v[0] == v ? tr_.tri(fan[0]).v[1] : tr_.tri(fan[0]).v[0];
      for (const auto& p : polygon_centres(link, 3))
        out.push_back({Candidate::Relocate, v, anchor, XPoint(Q(p.first), Q(p.second))});
    }
  }

  /// How many edges at v are segment edges; the first two in `ends` (see constrained_ends).
  int constrained_spokes(int v, int ends[2]) const { return constrained_ends(tr_.spokes(v), ends); }

  /// Corners of t moved so that its obtuse corner c becomes a right one: a Steiner point at a far
  /// corner onto the line through c perpendicular to the other edge at c (exact: its foot on the
  /// line, or where the line meets its segment), and a free Steiner point at c pushed out of
  /// the circle over the long edge (rounded, a hair outside: c need not be exact).
  void square_candidates(int t, int k, std::vector<Candidate>& out) const {
    const auto& tri = tr_.tri(t);
    const int cv = tri.v[k];
    const XPoint& c = tr_.point(cv);
    int ends[2];
    for (int j = 1; j <= 2; ++j) {
      const int mv = tri.v[(k + j) % 3];
      if (tr_.is_required(mv)) continue;
      const XPoint &m = tr_.point(mv), &o = tr_.point(tri.v[(k + 3 - j) % 3]);
      const Q nx = c.y - o.y, ny = o.x - c.x;  // perpendicular to o - c
      const int n = constrained_spokes(mv, ends);
      XPoint p;
      if (n == 0) {
        p = foot_on_line(m, c, nx, ny);
      } else if (n == 2) {
        const XPoint &e0 = tr_.point(ends[0]), &e1 = tr_.point(ends[1]);
        const Q ex = e1.x - e0.x, ey = e1.y - e0.y, den = nx * ey - ny * ex;
        if (den == 0) continue;
        const Q r = -(nx * (e0.y - c.y) - ny * (e0.x - c.x)) / den;
        if (r <= 0 || r >= 1) continue;
        p = XPoint(e0.x + r * ex, e0.y + r * ey);
      } else {
        continue;
      }
      if (bits(p.x) + bits(p.y) > 2 * kMaxBits) {
        if (n != 0) continue;  // on a segment it must be exact
        p = rounded(p);
      }
      out.push_back({Candidate::Relocate, mv, cv, p});
    }
    if (tr_.is_required(cv) || constrained_spokes(cv, ends) != 0) return;
    const XPoint &a = tr_.point(tri.v[(k + 1) % 3]), &b = tr_.point(tri.v[(k + 2) % 3]);
    const double mx = 0.5 * (a.dx + b.dx), my = 0.5 * (a.dy + b.dy);
    const double r = 0.5 * std::hypot(b.dx - a.dx, b.dy - a.dy), dx = c.dx - mx, dy = c.dy - my;
    const double len = std::hypot(dx, dy);
    if (!(len > 0) || !std::isfinite(r)) return;
    const double scale = r * (1 + 1e-7) / len;
    out.push_back({Candidate::Relocate, cv, tri.v[(k + 1) % 3], XPoint(Q(mx + scale * dx), Q(my + scale * dy))});
  }

  /// A Steiner point on a segment slid along it to the feet of its neighbours: a right angle at
  /// the new position against each (the corner of an obtuse triangle on a segment is otherwise
  /// only removed, and a thin pocket between two segments keeps it).
  void slide_candidates(int v, std::vector<Candidate>& out) const {
    const auto spokes = tr_.spokes(v);
    int ends[2];
    if (constrained_ends(spokes, ends) != 2) return;
    const XPoint &a = tr_.point(ends[0]), &b = tr_.point(ends[1]), &pv = tr_.point(v);
    const Q sx = b.x - a.x, sy = b.y - a.y;
    for (const auto& [w, seg] : spokes) {
      if (seg >= 0) continue;
      Q r;
      const XPoint foot = foot_on_line(tr_.point(w), a, sx, sy, r);
      if (r <= 0 || r >= 1) continue;
      if ((foot.x == pv.x && foot.y == pv.y) || bits(foot.x) + bits(foot.y) > 2 * kMaxBits) continue;
      out.push_back({Candidate::Relocate, v, ends[0], foot});
    }
  }

  /// Applies a candidate (inside the open transaction). Returns false when it cannot be inserted.
  bool apply(const Candidate& c) {
    if (c.kind == Candidate::Remove) return tr_.remove_vertex(c.tri);
    if (c.kind == Candidate::Relocate) {
      if (!tr_.remove_vertex(c.tri)) return false;
      return tr_.insert(c.p, tr_.triangle_of(c.edge)) >= 0;
    }
    if (c.kind == Candidate::EdgeSplit) return tr_.split_edge(c.tri, c.edge, c.p) >= 0;
    if (c.tri < 0) return false;
    return tr_.insert(c.p, c.tri) >= 0;
  }

  /// How far past 90 degrees the largest angle of an obtuse triangle is (doubles; a tie-break).
  double excess(const exact::Tri& t) const {
    double worst = 0;
    for (int k = 0; k < 3; ++k) {
      const XPoint &o = tr_.point(t.v[k]), &p = tr_.point(t.v[(k + 1) % 3]), &q = tr_.point(t.v[(k + 2) % 3]);
      const double ax = p.dx - o.dx, ay = p.dy - o.dy, bx = q.dx - o.dx, by = q.dy - o.dy;
      worst = std::max(worst, std::atan2(std::abs(ax * by - ay * bx), ax * bx + ay * by));
    }
    return std::max(0.0, worst - 1.5707963267948966);
  }

  /// Change made by the open transaction: obtuse triangles, then their total excess.
  std::pair<int, double> obtuse_delta() const {
    int count = 0;
    double ex = 0;
    for (const auto& old : tr_.touched_originals())
      if (old.alive && tr_.is_obtuse(old)) --count, ex -= excess(old);
    for (int t : tr_.touched())
      if (tr_.tri(t).alive && tr_.is_obtuse(tr_.tri(t))) ++count, ex += excess(tr_.tri(t));
    return {count, ex};
  }

  using Score = std::pair<int, double>;
  static constexpr int kNone = 1 << 30;

  /// Scores of t's candidates (inside no transaction; each tried and undone).
  std::vector<Score> scores(const std::vector<Candidate>& cands) {
    std::vector<Score> out;
    const double before = static_cast<double>(tr_.n_steiner());
    for (const auto& c : cands) {
      tr_.begin();
      const bool ok = apply(c);
      Score sc = ok ? obtuse_delta() : Score{kNone, 0.0};
      sc.second += 10.0 * (static_cast<double>(tr_.n_steiner()) - before);  // equal counts: fewer points first
      out.push_back(sc);
      tr_.rollback();
    }
    return out;
  }

  /// Fixes obtuse triangle t with the best candidate, or with the best pair (a candidate, then
  /// one for an obtuse triangle it made) when no single one leaves fewer obtuse triangles. With
  /// !allow_worse, a fix that would leave more obtuse triangles than before is not made.
  bool fix(int t, bool allow_worse) {
    const auto cands = candidates(t);
    const auto sc = scores(cands);
    int best = -1;
    Score best_score{kNone, 0.0};
    for (std::size_t i = 0; i < cands.size(); ++i) {
      // A removal only when it mends something: as a neutral move it undoes the insertion that
      // carried an obtuse triangle along a cascade, and the search goes round in circles.
      if (cands[i].kind == Candidate::Remove && sc[i].first >= 0) continue;
      if (sc[i] < best_score) best = static_cast<int>(i), best_score = sc[i];
    }
    if (best < 0) return false;
    int pair_first = -1, pair_tri = -1, pair_second = -1;
    Score pair_score = best_score;
    if (best_score.first > 0) {
      std::vector<std::size_t> order(cands.size());
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
      std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return sc[x] < sc[y]; });
      for (std::size_t r = 0; r < std::min<std::size_t>(order.size(), 4); ++r) {
        const std::size_t i = order[r];
        if (sc[i].first >= kNone) break;
        tr_.begin();
        apply(cands[i]);
        std::vector<int> bad;
        for (int u : tr_.touched())
          if (tr_.tri(u).alive && tr_.is_obtuse(tr_.tri(u))) bad.push_back(u);
        for (std::size_t bi = 0; bi < std::min<std::size_t>(bad.size(), 3); ++bi) {
          const auto second = candidates(bad[bi]);
          for (std::size_t j = 0; j < second.size(); ++j) {
            tr_.nest();
            if (apply(second[j])) {
              const Score d = obtuse_delta();
              if (d.first < pair_score.first && d < pair_score) {  // only strictly fewer obtuse
                pair_score = d;
                pair_first = static_cast<int>(i);
                pair_tri = bad[bi];
                pair_second = static_cast<int>(j);
              }
            }
            tr_.unnest();
          }
        }
        tr_.rollback();
      }
    }
    if (std::min(pair_score.first, best_score.first) >= 0) {
      // No move or pair helps: a longer chain of moves may (the obtuse triangle carried across
      // several triangles to a segment, each step changing nothing on its own). Before the
      // neutral move: taken instead, it leaves the search where the chain started.
      tr_.begin();
      std::size_t budget = kDeepBudget;
      if (deep(t, kDeepDepth, budget)) {
        tr_.commit();
        return true;
      }
      tr_.rollback();
    }
    if (allow_worse && std::min(pair_score.first, best_score.first) > 0) {
      // Stuck: a random kick (any insertable candidate) rather than the same worst-best move.
      std::vector<std::size_t> ok;
      for (std::size_t i = 0; i < cands.size(); ++i)
        if (sc[i].first < kNone && cands[i].kind != Candidate::Remove) ok.push_back(i);
      if (!ok.empty()) {
        tr_.begin();
        apply(cands[ok[std::uniform_int_distribution<std::size_t>(0, ok.size() - 1)(rng_)]]);
        tr_.commit();
        return true;
      }
    }
    if (pair_first >= 0) {
      if (!allow_worse && pair_score.first > 0) return false;
      tr_.begin();
      apply(cands[static_cast<std::size_t>(pair_first)]);
      const auto second = candidates(pair_tri);
      if (static_cast<std::size_t>(pair_second) < second.size()) apply(second[static_cast<std::size_t>(pair_second)]);
      tr_.commit();
      return true;
    }
    if (!allow_worse && best_score.first > 0) return false;
    tr_.begin();
    apply(cands[static_cast<std::size_t>(best)]);
    tr_.commit();
    return true;
  }

  // Before the square moves, depth 5 with 2,500 moves per search solved 11 of 17 exterior
  // instances at 10 s (two seeds; 3 without the search); depth 8 or 10,000 moves spend the time
  // on fewer triangles and solve fewer. With the square moves too: 17 of 17.
  static constexpr int kDeepDepth = 5;
  static constexpr std::size_t kDeepBudget = 2500;  // moves tried per search
  static constexpr std::size_t kDeepWidth = 3;      // best moves followed per triangle

  /// Depth-first search, inside the open transaction, for a sequence of at most `depth` moves,
  /// each one for an obtuse triangle the sequence made, after which fewer triangles are obtuse
  /// than at begin(). True with the moves applied; false with none (or `budget` moves tried).
  bool deep(int t, int depth, std::size_t& budget) {
    const auto cands = candidates(t);
    std::vector<std::pair<Score, std::size_t>> order;
    for (std::size_t i = 0; i < cands.size() && budget > 0; ++i, --budget) {
      const auto m = tr_.mark();
      if (apply(cands[i])) {
        Score d = obtuse_delta();
        if (d.first < 0) return true;
        if (cands[i].kind != Candidate::Remove) order.emplace_back(d, i);
      }
      tr_.rollback_to(m);
    }
    if (depth <= 1) return false;
    std::sort(order.begin(), order.end());
    for (std::size_t r = 0; r < std::min(order.size(), kDeepWidth) && budget > 0; ++r) {
      const auto m = tr_.mark();
      apply(cands[order[r].second]);
      std::vector<int> bad;
      for (int u : tr_.touched_since(m))
        if (tr_.tri(u).alive && tr_.is_obtuse(tr_.tri(u))) bad.push_back(u);
      for (std::size_t b = 0; b < std::min<std::size_t>(bad.size(), 2); ++b)
        if (deep(bad[b], depth - 1, budget)) return true;
      tr_.rollback_to(m);
    }
    return false;
  }

  /// Refinement: obtuse triangles fixed one by one until none is left or the caps are hit.
  /// Fixes that make things worse wait until no other fix helps.
  bool refine(std::size_t max_steiner, bool shuffled) {
    std::vector<int> queue;
    for (int t = 0; t < tr_.n_tris(); ++t)
      if (tr_.tri(t).alive && tr_.is_obtuse(tr_.tri(t))) queue.push_back(t);
    if (shuffled) std::shuffle(queue.begin(), queue.end(), rng_);
    const std::size_t initial = queue.size();
    std::size_t fixes = 0, head = 0;
    bool allow_worse = false, progress = false;
    std::size_t fewest = queue.size() + 1, stalled = 0, pass_start = queue.size();
    while (true) {
      if (head == queue.size()) {
        queue.clear();
        head = 0;
        for (int t = 0; t < tr_.n_tris(); ++t)
          if (tr_.tri(t).alive && tr_.is_obtuse(tr_.tri(t))) queue.push_back(t);
        if (queue.empty()) return true;
        std::shuffle(queue.begin(), queue.end(), rng_);
        // A pass that did not lower the obtuse count below its best: let the next fix be worse;
        // many such passes: this attempt is stuck.
        if (queue.size() < fewest) {
          fewest = queue.size();
          stalled = 0;
        } else if (++stalled > 40) {
          return queue.size() <= 4 && cascade(queue, max_steiner);
        }
        allow_worse = !progress || stalled > 2;
        pass_start = queue.size();
        progress = false;
      }
      const int t = queue[head++];
      if (!tr_.tri(t).alive || !tr_.is_obtuse(tr_.tri(t))) continue;
      if (tr_.n_steiner() >= max_steiner || out_of_time()) return false;
      if (++fixes % 32 == 0 && tr_.n_obtuse() > 4 * initial + 40) return false;  // diverging
      if (fixes > 8 * max_steiner) return false;  // cycling
      if (!fix(t, allow_worse)) continue;
      progress = true;
      if (allow_worse) {
        allow_worse = false;
      }
      // Obtuse triangles a fix made join this pass only while it is short (a pass must end,
      // or moves that trade one obtuse triangle for another would go on for ever).
      if (queue.size() < 8 * pass_start + 64)
        for (int u : tr_.last_touched())
          if (tr_.tri(u).alive && tr_.is_obtuse(tr_.tri(u))) queue.push_back(u);
    }
  }

  /// Last resort for a few obtuse triangles: follow each one's chain of altitude feet (the foot
  /// on the long edge moves the obtuse triangle across it) until the chain runs into a segment
  /// and ends, whatever it costs on the way; undone when it does not end.
  bool cascade(std::vector<int> bad, std::size_t max_steiner) {
    tr_.begin();
    for (std::size_t step = 0; step < 4000 && !bad.empty(); ++step) {
      if (tr_.n_steiner() >= max_steiner || out_of_time()) break;
      const int t = bad.back();
      bad.pop_back();
      if (!tr_.tri(t).alive || !tr_.is_obtuse(tr_.tri(t))) continue;
      tr_.nest();
      const auto cands = candidates(t);
      if (cands.empty() || !apply(cands.front())) {  // the foot comes first
        tr_.unnest();
        break;
      }
      for (int u : tr_.touched())
        if (tr_.tri(u).alive && tr_.is_obtuse(tr_.tri(u)) && std::find(bad.begin(), bad.end(), u) == bad.end())
          bad.push_back(u);
    }
    for (int t = 0; t < tr_.n_tris(); ++t)
      if (tr_.tri(t).alive && tr_.is_obtuse(tr_.tri(t))) {
        tr_.rollback();
        return false;
      }
    tr_.commit();
    return true;
  }

  /// Tries to remove Steiner point v keeping every triangle non-obtuse.
  bool try_remove(int v) {
    tr_.begin();
    if (!tr_.remove_vertex(v)) {
      tr_.rollback();
      return false;
    }
    for (int t : tr_.touched())
      if (tr_.tri(t).alive && tr_.is_obtuse(tr_.tri(t))) {
        tr_.rollback();
        return false;
      }
    tr_.commit();
    return true;
  }

  /// Tries to replace Steiner points v and w by one new point (net one fewer).
  bool try_merge(int v, int w) {
    tr_.begin();
    if (!tr_.remove_vertex(v) || !tr_.remove_vertex(w)) {
      tr_.rollback();
      return false;
    }
    std::vector<int> bad;
    for (int t : tr_.touched())
      if (tr_.tri(t).alive && tr_.is_obtuse(tr_.tri(t))) bad.push_back(t);
    if (bad.empty()) {
      tr_.commit();
      return true;
    }
    if (bad.size() > 4) {
      tr_.rollback();
      return false;
    }
    // One insertion must fix everything the two removals broke.
    std::vector<Candidate> cands;
    for (int t : bad)
      for (auto& c : candidates(t)) cands.push_back(std::move(c));
    for (const auto& c : cands) {
      tr_.nest();
      bool ok = apply(c);
      if (ok)
        for (int t : tr_.touched())
          if (tr_.tri(t).alive && tr_.is_obtuse(tr_.tri(t))) {
            ok = false;
            break;
          }
      if (ok) {
        tr_.commit();
        return true;
      }
      tr_.unnest();
    }
    tr_.rollback();
    return false;
  }

  /// Local search: removals, then pairs replaced by one point, while anything improves.
  void prune() {
    for (int pass = 0; pass < 20; ++pass) {
      bool progress = false;
      std::vector<int> steiner = tr_.steiner_vertices();
      std::shuffle(steiner.begin(), steiner.end(), rng_);
      for (int v : steiner) {
        if (out_of_time()) return;
        if (tr_.alive_point(v) && try_remove(v)) progress = true;
      }
      steiner = tr_.steiner_vertices();
      std::shuffle(steiner.begin(), steiner.end(), rng_);
      for (int v : steiner) {
        if (out_of_time()) return;
        if (!tr_.alive_point(v)) continue;
        for (int w : tr_.neighbours(v)) {
          if (w == v || !tr_.alive_point(w) || tr_.is_required(w)) continue;
          if (try_merge(v, w)) {
            progress = true;
            break;
          }
        }
      }
      if (!progress) return;
    }
  }

 private:
  Triangulation& tr_;
  const NonObtuseParams& params_;
  Clock::time_point deadline_;
  std::mt19937 rng_;
};

/// Removes the Steiner points of the triangles within `depth` steps (across edges) of triangle
/// `centre`: the large neighbourhood that unstick and reduce rebuild. Returns how many went.
std::size_t without_steiner_near(Triangulation& tr, int centre, int depth) {
  std::vector<int> region{centre};
  std::vector<char> seen(static_cast<std::size_t>(tr.n_tris()), 0);
  seen[static_cast<std::size_t>(centre)] = 1;
  for (std::size_t head = 0, level_end = 1, level = 0; head < region.size() && level < static_cast<std::size_t>(depth); ++head) {
    for (int k = 0; k < 3; ++k) {
      const int u = tr.tri(region[head]).n[k];
      if (u >= 0 && !seen[static_cast<std::size_t>(u)]) {
        seen[static_cast<std::size_t>(u)] = 1;
        region.push_back(u);
      }
    }
    if (head + 1 == level_end) ++level, level_end = region.size();
  }
  std::vector<int> victims;
  for (int t : region)
    for (int v : tr.tri(t).v)
      if (!tr.is_required(v)) victims.push_back(v);
  std::sort(victims.begin(), victims.end());
  victims.erase(std::unique(victims.begin(), victims.end()), victims.end());
  tr.begin();
  for (int v : victims)
    if (tr.alive_point(v)) tr.remove_vertex(v);
  tr.commit();
  return victims.size();
}

/// Large-neighbourhood search on a stalled triangulation: the Steiner points within a few
/// triangles of one of its obtuse triangles removed and the refinement run again from there (the
/// greedy search gets stuck in a local arrangement it will not undo); a round is kept when it
/// leaves fewer obtuse triangles, or as many with hardly more points (drift across a plateau).
/// True when no obtuse triangle is left.
bool unstick(Triangulation& best, const NonObtuseParams& params, std::size_t cap, Clock::time_point deadline,
             std::size_t max_rounds) {
  std::mt19937 rng(params.seed * 7919u + 13u);
  const bool timed = deadline != Clock::time_point::max();
  for (std::size_t round = 0; round < max_rounds && best.n_obtuse() > 0; ++round) {
    const auto now = Clock::now();
    if (now > deadline || (params.cancel && params.cancel())) break;
    std::vector<int> bad;
    for (int t = 0; t < best.n_tris(); ++t)
      if (best.tri(t).alive && best.is_obtuse(best.tri(t))) bad.push_back(t);
    const int depth = 1 + static_cast<int>(rng() % 5);
    const int centre = bad[rng() % bad.size()];
    Triangulation tr = best;
    without_steiner_near(tr, centre, depth);
    NonObtuseParams p = params;
    p.seed = params.seed + 1000u + static_cast<unsigned>(round);
    NonObtuseSolver solver(tr, p, timed ? now + (deadline - now) / 3 : deadline);
    const bool ok = solver.refine(cap, true);
    if (ok || tr.n_obtuse() < best.n_obtuse() || (tr.n_obtuse() == best.n_obtuse() && tr.n_steiner() <= best.n_steiner() + 2))
      best = std::move(tr);
    if (ok) return true;
  }
  return best.n_obtuse() == 0;
}

/// Steiner points fewer by large neighbourhoods: all Steiner points within a few triangles of a
/// random one removed and the refinement rerun from there; kept when the result is non-obtuse
/// with fewer points (a dense start, as a repaired CVT mesh, loses few points one at a time).
void reduce(Triangulation& best, const NonObtuseParams& params, std::size_t cap, Clock::time_point deadline) {
  if (deadline == Clock::time_point::max()) return;  // only with a time limit: it runs until it
  std::mt19937 rng(params.seed * 104729u + 7u);
  for (std::size_t round = 0; best.n_steiner() > 0; ++round) {
    const auto now = Clock::now();
    if (now > deadline || (params.cancel && params.cancel())) break;
    std::vector<int> live;
    for (int t = 0; t < best.n_tris(); ++t)
      if (best.tri(t).alive) live.push_back(t);
    const int depth = 1 + static_cast<int>(rng() % 4);
    const int centre = live[rng() % live.size()];
    Triangulation tr = best;
    if (without_steiner_near(tr, centre, depth) < 2) continue;  // one point: the pruning's job
    NonObtuseParams p = params;
    p.seed = params.seed + 5000u + static_cast<unsigned>(round);
    NonObtuseSolver solver(tr, p, std::min(deadline, now + std::chrono::milliseconds(300)));
    if (solver.refine(cap, true) && tr.n_steiner() < best.n_steiner()) best = std::move(tr);
  }
}

}  // namespace


namespace {

/// The result's mesh and counts from the final triangulation.
void finish(const Triangulation& tr, const Mesh& cdt, NonObtuseResult& result) {
  result.mesh = tr.to_mesh(cdt, &result.exact);
  result.n_steiner = tr.n_steiner();
  result.n_obtuse = tr.n_obtuse();
  result.n_right = tr.n_right();
  result.ok = result.n_obtuse == 0;
}

}  // namespace

NonObtuseResult non_obtuse_triangulation(const Domain& domain, const NonObtuseParams& params) {
  const auto t0 = Clock::now();
  const auto deadline = params.time_limit_s > 0
                            ? t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(params.time_limit_s))
                            : Clock::time_point::max();
  const Mesh cdt = build_cdt(domain);
  const std::size_t cap = params.max_steiner > 0 ? params.max_steiner : 60 * domain.points.size() + 2000;

  NonObtuseResult result;
  Triangulation best = Triangulation::from_mesh(cdt);
  bool best_ok = false;
  // Refinement strategies in turn (later ones only when an earlier one got stuck): each one
  // starts from the CDT; the first that ends non-obtuse is pruned.
  // Greedy refinements from the CDT, each in a different order (the order matters a lot: a
  // cascade of altitude feet either closes quickly or runs away, which ends the attempt), each
  // success pruned; the best kept. Time: attempts until half the budget, pruning the rest.
  const bool timed = deadline != Clock::time_point::max();
  // Untimed, a stalled search gives up here (a success is then pruned without a limit).
  const auto give_up = !timed && params.give_up_s > 0
                           ? t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(params.give_up_s))
                           : Clock::time_point::max();
  // When a search without a result ends: the time limit, else the give-up time (or never).
  const auto search_end = timed ? deadline : give_up;
  int successes = 0;
  for (unsigned attempt = 0; attempt < 400; ++attempt) {
    const auto now = Clock::now();
    if (attempt > 0 && (now > deadline || (params.cancel && params.cancel()))) break;
    if (successes >= 4 || (successes >= 1 && (!timed || now - t0 > (deadline - t0) / 2))) break;
    if (!best_ok && search_end != Clock::time_point::max() && now - t0 > (search_end - t0) * 6 / 10) break;  // the rest for unstick()
    Triangulation tr = Triangulation::from_mesh(cdt);
    NonObtuseParams p = params;
    p.seed = params.seed + attempt;
    // The first attempt gets most of the time (its plateau search does finish, slowly).
    const auto share = timed ? now + (attempt == 0 ? (deadline - now) / 2 : (deadline - now) / 3)
                             : best_ok ? deadline : std::min(give_up, now + (give_up - now) / 2);
    NonObtuseSolver solver(tr, p, share);
    ++result.rounds;
    if (solver.refine(cap, attempt > 0)) {
      const std::size_t refined = tr.n_steiner();
      NonObtuseSolver pruner(tr, p, timed ? Clock::now() + (deadline - Clock::now()) / 2 : deadline);
      pruner.prune();
      if (!best_ok || tr.n_steiner() < best.n_steiner()) {
        result.n_refined = refined;
        best = std::move(tr);
      }
      best_ok = true;
      ++successes;
    } else if (!best_ok && (attempt == 0 || tr.n_obtuse() < best.n_obtuse())) {
      best = std::move(tr);
    }
  }
  if (!best_ok && !(params.cancel && params.cancel())) {
    // Every attempt stalled: work on the one with fewest obtuse triangles left, then prune it.
    const auto lns_end = timed ? t0 + (search_end - t0) * 9 / 10 : search_end;
    best_ok = unstick(best, params, cap, lns_end, timed ? 100000 : 200);
    if (best_ok) {
      result.n_refined = best.n_steiner();
      NonObtuseSolver pruner(best, params, deadline);
      pruner.prune();
    }
  }
  finish(best, cdt, result);
  return result;
}

NonObtuseResult non_obtuse_from_start(const Domain& domain, const Mesh& start, const NonObtuseParams& params) {
  const auto t0 = Clock::now();
  const bool timed = params.time_limit_s > 0;
  const auto deadline = timed ? t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(params.time_limit_s))
                              : Clock::time_point::max();
  const Mesh cdt = build_cdt(domain);
  NonObtuseResult result;
  Triangulation tr;
  SegmentTable segments;  // by segment id: the domain's segments
  for (const auto& sg : domain.segments)
    segments.push_back({domain.points[static_cast<std::size_t>(sg[0])], domain.points[static_cast<std::size_t>(sg[1])]});
  if (!Triangulation::from_start(cdt, start, segments, tr)) {
    result.n_obtuse = static_cast<std::size_t>(-1);
    return result;
  }
  // The start has far more Steiner points than a CDT attempt needs: the cap grows with it.
  const std::size_t cap = std::max(params.max_steiner > 0 ? params.max_steiner : 60 * domain.points.size() + 2000,
                                   2 * tr.n_steiner() + 100);
  ++result.rounds;
  bool ok = tr.n_obtuse() == 0;
  if (!ok) {
    // A few attempts in different orders, each from the start (a failed one may leave more).
    const Triangulation initial = tr;
    const auto fix_deadline =
        !timed ? deadline
               : params.refine_time_s > 0
                     ? std::min(deadline, t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(params.refine_time_s)))
                     : t0 + (deadline - t0) / 2;
    for (unsigned attempt = 0; attempt < 3 && !ok; ++attempt) {
      if (attempt > 0) {
        if (Clock::now() > fix_deadline || (params.cancel && params.cancel())) break;
        tr = initial;
        ++result.rounds;
      }
      NonObtuseParams p = params;
      p.seed = params.seed + attempt;
      NonObtuseSolver solver(tr, p, timed ? Clock::now() + (fix_deadline - Clock::now()) / 2 : deadline);
      ok = solver.refine(cap, attempt > 0);
    }
    if (!ok) {  // the attempt with fewest obtuse triangles, worked on locally
      if (tr.n_obtuse() > initial.n_obtuse()) tr = initial;
      ok = unstick(tr, params, cap, fix_deadline, timed ? 100000 : 50);
    }
  }
  result.n_refined = tr.n_steiner();
  if (ok) {
    NonObtuseSolver pruner(tr, params, deadline);
    pruner.prune();
    reduce(tr, params, cap, timed ? deadline - (deadline - Clock::now()) / 5 : deadline);
    NonObtuseSolver again(tr, params, deadline);
    again.prune();
  }
  finish(tr, cdt, result);
  return result;
}

}  // namespace acute
