// Random polygons with holes for pipeline tests: deterministic in a seed, simple by construction
// and checked exactly (predicates) before they are handed out. Near-degenerate features on purpose:
// nearly collinear vertices, a hole close to the outer boundary, short edges beside long ones,
// interior constraint segments.
#pragma once

#include <acute/core/domain.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace acute::test {

struct RandomDomain {
  Domain domain;
  std::vector<std::string> features;  ///< what the generator put in, for messages
  unsigned seed = 0;
  int attempts = 0;                   ///< candidates drawn before one passed the exact check
  double area = 0;                    ///< outer loop's area minus the holes' (shoelace)
};

namespace detail {

inline std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

/// mt19937_64 is fully specified by the standard; the std distributions are not, so uniforms are
/// made here to keep the domains identical on every standard library.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int integer(int lo, int hi) { return lo + static_cast<int>(engine_() % static_cast<std::uint64_t>(hi - lo + 1)); }  // [lo, hi]
  bool chance(double p) { return uniform() < p; }

 private:
  std::mt19937_64 engine_;
};

constexpr double kPi = 3.14159265358979323846;

/// A star-shaped polygon around c, counter-clockwise: n angles with gaps below 180 degrees
/// (so c is in the kernel and the polygon is simple), radii in [rmin, 1] * r. `first_radius`
/// (in (0, 1]) and `first_angle` fix the first vertex, e.g. to bring a hole close to an edge.
inline std::vector<Point2> star(Rng& rng, Point2 c, double r, int n, double rmin, double first_angle, double first_radius = 0) {
  std::vector<double> gaps(static_cast<std::size_t>(n));
  double sum = 0;
  for (double& g : gaps) sum += (g = rng.uniform(0.6, 1.0));  // n >= 3: every gap below 180 degrees
  std::vector<Point2> pts;
  double t = first_angle;
  for (int i = 0; i < n; ++i) {
    const double rho = (i == 0 && first_radius > 0) ? first_radius : rng.uniform(rmin, 1.0);
    pts.emplace_back(c.x() + r * rho * std::cos(t), c.y() + r * rho * std::sin(t));
    t += 2 * kPi * gaps[static_cast<std::size_t>(i)] / sum;
  }
  return pts;
}

inline double segment_distance(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

/// Exact: Positive strictly inside the closed polygon, Zero on its boundary, Negative outside.
inline Sign side_of_polygon(const Point2& q, const std::vector<Point2>& poly) {
  bool inside = false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point2& a = poly[i];
    const Point2& b = poly[(i + 1) % poly.size()];
    if (predicates::locate_on_segment(q, a, b) != predicates::SegmentLocation::Outside) return Sign::Zero;
    // Ray towards +x, half-open in y: an upward edge crosses it right of q when q is on its left.
    if ((a.y() <= q.y()) != (b.y() <= q.y())) {
      const Sign s = predicates::orient2d(a, b, q);
      if ((b.y() > a.y()) == (s == Sign::Positive)) inside = !inside;
    }
  }
  return inside ? Sign::Positive : Sign::Negative;
}

/// A domain under construction: closed loops (outer first, then holes) and free chords.
struct Draft {
  std::vector<std::vector<Point2>> loops;      // [0] the outer boundary, then holes
  std::vector<Point2> hole_seeds;              // one per hole, strictly inside it
  std::vector<std::array<Point2, 2>> chords;   // interior constraint segments
  std::vector<std::string> features;

  std::vector<std::array<Point2, 2>> all_segments() const {
    std::vector<std::array<Point2, 2>> s;
    for (const auto& l : loops)
      for (std::size_t i = 0; i < l.size(); ++i) s.push_back({l[i], l[(i + 1) % l.size()]});
    s.insert(s.end(), chords.begin(), chords.end());
    return s;
  }

  /// Distance from p to every segment so far (floating point: only for placing new features; the
  /// exact check decides).
  double clearance(const Point2& p) const {
    double d = INFINITY;
    for (const auto& s : all_segments()) d = std::min(d, segment_distance(p, s[0], s[1]));
    return d;
  }

  /// Strictly inside the outer loop and outside every hole (exact).
  bool in_domain(const Point2& p) const {
    if (side_of_polygon(p, loops[0]) != Sign::Positive) return false;
    for (std::size_t h = 1; h < loops.size(); ++h)
      if (side_of_polygon(p, loops[h]) != Sign::Negative) return false;
    return true;
  }
};

/// Empty when the draft is a valid simple domain: no duplicate points; segments meet only at
/// shared endpoints of consecutive loop edges; no point inside a segment; every hole strictly
/// inside the outer loop and outside the other holes; every seed strictly inside its hole; chords
/// strictly inside the domain. Else the first problem.
inline std::string draft_problem(const Draft& d) {
  std::set<std::pair<double, double>> seen;
  std::vector<Point2> points;
  for (const auto& l : d.loops) points.insert(points.end(), l.begin(), l.end());
  for (const auto& c : d.chords) points.insert(points.end(), c.begin(), c.end());
  for (const auto& p : points)
    if (!seen.insert({p.x(), p.y()}).second) return "duplicate point";
  const auto segs = d.all_segments();
  for (std::size_t i = 0; i < segs.size(); ++i) {
    if (segs[i][0] == segs[i][1]) return "zero-length segment";
    for (std::size_t j = i + 1; j < segs.size(); ++j) {
      const auto r = predicates::intersect_segments(segs[i][0], segs[i][1], segs[j][0], segs[j][1]);
      if (r == predicates::SegmentIntersection::None) continue;
      const bool share = segs[i][0] == segs[j][0] || segs[i][0] == segs[j][1] || segs[i][1] == segs[j][0] || segs[i][1] == segs[j][1];
      if (r != predicates::SegmentIntersection::Touching || !share) return "segments " + std::to_string(i) + " and " + std::to_string(j) + " meet";
      // Touching at a shared endpoint: fine unless the other endpoint lies on the segment too
      // (that would be an overlap, reported as Overlapping above).
    }
  }
  for (const auto& p : points)
    for (const auto& s : segs)
      if (predicates::locate_on_segment(p, s[0], s[1]) == predicates::SegmentLocation::OnInterior) return "point inside a segment";
  for (std::size_t h = 1; h < d.loops.size(); ++h) {
    for (const auto& p : d.loops[h])
      if (side_of_polygon(p, d.loops[0]) != Sign::Positive) return "hole " + std::to_string(h) + " not strictly inside the outer loop";
    for (std::size_t g = 1; g < d.loops.size(); ++g)
      if (g != h && side_of_polygon(d.loops[h][0], d.loops[g]) != Sign::Negative) return "holes nested";
    if (side_of_polygon(d.hole_seeds[h - 1], d.loops[h]) != Sign::Positive) return "hole seed outside its hole";
  }
  for (const auto& c : d.chords)
    if (!d.in_domain(c[0]) || !d.in_domain(c[1])) return "chord endpoint outside the domain";
  return {};
}

/// Inserts 1-3 points along edge i of a loop, each offset from the edge by `offset` times its length
/// (0: rounding only), on alternating sides: nearly collinear vertices.
inline void subdivide_edge(Rng& rng, std::vector<Point2>& loop, std::size_t i, double offset) {
  const Point2 a = loop[i], b = loop[(i + 1) % loop.size()];
  const Point2 d = b - a, n(-d.y(), d.x());
  const int k = rng.integer(1, 3);
  std::vector<Point2> mid;
  for (int j = 1; j <= k; ++j) {
    const double t = static_cast<double>(j) / (k + 1) + rng.uniform(-0.1, 0.1) / (k + 1);
    mid.push_back(a + t * d + ((j % 2) ? offset : -offset) * n);
  }
  loop.insert(loop.begin() + static_cast<std::ptrdiff_t>(i + 1), mid.begin(), mid.end());
}

/// Splits the longest edge of a loop very near one end (fraction t of its length), with a bend of
/// `bend` times the short part: a short edge beside a long one.
inline void short_edge(std::vector<Point2>& loop, double t, double bend) {
  std::size_t i = 0;
  double best = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const double len = (loop[(k + 1) % loop.size()] - loop[k]).norm();
    if (len > best) best = len, i = k;
  }
  const Point2 a = loop[i], b = loop[(i + 1) % loop.size()];
  const Point2 d = b - a, n(-d.y(), d.x());
  loop.insert(loop.begin() + static_cast<std::ptrdiff_t>(i + 1), a + t * d + bend * t * n);
}

inline Draft draw(Rng& rng, int index) {
  Draft d;
  // Outer boundary: a star polygon, spiky (rmin 0.5) or rounder (rmin 0.8), 5 to 24 vertices.
  const double rmin = rng.chance(0.5) ? 0.5 : 0.8;
  d.loops.push_back(star(rng, Point2(0, 0), 1.0, rng.integer(5, 24), rmin, rng.uniform(0, 2 * kPi)));
  d.features.push_back(std::string(rmin < 0.6 ? "spiky" : "round") + " star of " + std::to_string(d.loops[0].size()));

  // Near-degenerate boundary features on the outer loop (before holes, so holes keep clear of them).
  auto& outer = d.loops[0];
  if (rng.chance(0.15)) {
    // A spike between two consecutive vertices, its tip angle about 10-28 degrees: an input corner
    // below the min bound (exempt from it, but its triangles must still be acute).
    const std::size_t i = static_cast<std::size_t>(rng.integer(0, static_cast<int>(outer.size()) - 1));
    const Point2 a = outer[i], b = outer[(i + 1) % outer.size()];
    const double ta = std::atan2(a.y(), a.x()), tb = std::atan2(b.y(), b.x());
    const double half_gap = 0.5 * std::remainder(tb - ta, 2 * kPi), t = ta + half_gap;
    const double r = std::min(a.norm(), b.norm()), tip = rng.uniform(10, 28) * kPi / 180;
    const double reach = r * std::cos(half_gap) + r * std::sin(half_gap) / std::tan(0.5 * tip);
    outer.insert(outer.begin() + static_cast<std::ptrdiff_t>(i + 1), Point2(reach * std::cos(t), reach * std::sin(t)));
    d.features.push_back("spike of about " + fmt(std::round(tip * 180 / kPi)) + " degrees");
  }
  if (rng.chance(0.35)) {
    const double offsets[] = {0.0, 1e-14, 1e-10, 1e-6};
    const double off = offsets[rng.integer(0, 3)];
    for (int e = rng.integer(1, 3); e > 0; --e) subdivide_edge(rng, outer, static_cast<std::size_t>(rng.integer(0, static_cast<int>(outer.size()) - 1)), off);
    d.features.push_back("nearly collinear (offset " + fmt(off) + ")");
  }
  if (rng.chance(0.3)) {
    const double t = rng.chance(0.5) ? 1e-3 : 1e-2;
    const double bend = rng.chance(0.5) ? 0.0 : 0.4;
    short_edge(outer, t, bend);
    d.features.push_back("short edge " + fmt(t) + " of the longest");
  }

  // Holes: 1 to 3; a quarter of the domains put the first one close to the outer boundary.
  const bool near_boundary = index % 4 == 1;
  const int holes = rng.integer(1, 3);
  for (int h = 0; h < holes; ++h) {
    Point2 c;
    double r = 0, first_angle = rng.uniform(0, 2 * kPi), first_radius = 0;
    if (h == 0 && near_boundary) {
      // Centre inward from the midpoint of an outer edge; the first hole vertex faces that edge at a
      // gap of 0.2% - 2% of the domain's size.
      const double gap = rng.chance(0.5) ? 2e-3 : 2e-2;
      const std::size_t e = static_cast<std::size_t>(rng.integer(0, static_cast<int>(outer.size()) - 1));
      const Point2 a = outer[e], b = outer[(e + 1) % outer.size()];
      const Point2 m = 0.5 * (a + b), inward = Point2(-(b - a).y(), (b - a).x()).normalized();
      const double want = 0.15;
      c = m + (want + gap) * inward;
      const double room = d.clearance(c);
      if (!d.in_domain(c) || room < gap + 0.03) continue;
      r = room - gap;
      first_angle = std::atan2(-inward.y(), -inward.x());
      first_radius = 1.0;
      d.features.push_back("hole at gap " + fmt(gap) + " from the boundary");
    } else {
      for (int tries = 0; tries < 50 && r == 0; ++tries) {
        const Point2 p(rng.uniform(-1, 1), rng.uniform(-1, 1));
        const double room = d.clearance(p);
        if (room > 0.08 && d.in_domain(p)) c = p, r = room * rng.uniform(0.35, 0.7);
      }
      if (r == 0) continue;
      d.features.push_back("hole");
    }
    auto loop = star(rng, c, r, rng.integer(3, 10), 0.7, first_angle, first_radius);
    if (rng.chance(0.2)) subdivide_edge(rng, loop, 0, 1e-12);
    // Holes are loops like any other; Triangle semantics need no orientation.
    d.loops.push_back(std::move(loop));
    d.hole_seeds.push_back(c);
  }

  // Interior constraint segments in about one domain in six: a chord inside a free disk.
  if (rng.chance(0.17)) {
    for (int tries = 0; tries < 50; ++tries) {
      const Point2 p(rng.uniform(-1, 1), rng.uniform(-1, 1));
      const double room = d.clearance(p);
      if (room < 0.1 || !d.in_domain(p)) continue;
      const double t = rng.uniform(0, 2 * kPi), half = 0.8 * room;
      const Point2 u(std::cos(t), std::sin(t));
      d.chords.push_back({p - half * u, p + half * u});
      d.features.push_back("interior segment");
      break;
    }
  }
  return d;
}

}  // namespace detail

/// Domain number `index` of the family drawn with `seed`: an outer star polygon with 1-3 holes and
/// the near-degenerate features listed in `features` (some with a spike: an input angle below 30). Candidates failing the exact check are
/// redrawn (deterministically).
inline RandomDomain random_polygon_with_holes(unsigned seed, int index) {
  RandomDomain out;
  out.seed = seed;
  for (int attempt = 0;; ++attempt) {
    detail::Rng rng((static_cast<std::uint64_t>(seed) << 32) ^ (static_cast<std::uint64_t>(index) * 1000003u + static_cast<std::uint64_t>(attempt)));
    detail::Draft d = detail::draw(rng, index);
    if (d.loops.size() < 2 || !detail::draft_problem(d).empty()) continue;
    out.attempts = attempt + 1;
    Domain& dom = out.domain;
    for (std::size_t k = 0; k < d.loops.size(); ++k) {
      const auto& l = d.loops[k];
      double twice = 0;
      for (std::size_t i = 0; i < l.size(); ++i) {
        const Point2& a = l[i];
        const Point2& b = l[(i + 1) % l.size()];
        twice += a.x() * b.y() - a.y() * b.x();
      }
      out.area += (k == 0 ? 0.5 : -0.5) * std::abs(twice);
      const int base = static_cast<int>(dom.points.size());
      for (std::size_t i = 0; i < l.size(); ++i) {
        dom.points.push_back(l[i]);
        dom.segments.push_back({base + static_cast<int>(i), base + static_cast<int>((i + 1) % l.size())});
      }
    }
    for (const auto& c : d.chords) {
      const int base = static_cast<int>(dom.points.size());
      dom.points.push_back(c[0]);
      dom.points.push_back(c[1]);
      dom.segments.push_back({base, base + 1});
    }
    dom.holes = d.hole_seeds;
    dom.point_markers.assign(dom.points.size(), 0);
    dom.segment_markers.assign(dom.segments.size(), 0);
    dom.name = "random_" + std::to_string(seed) + "_" + std::to_string(index);
    out.features = std::move(d.features);
    return out;
  }
}

/// Writes a domain as a Triangle .poly (1-based, 17 significant digits) for `acute mesh` and meshcheck.
inline void write_poly(const Domain& d, const std::string& path, const std::string& comment = {}) {
  std::ofstream f(path);
  f << std::setprecision(17);
  if (!comment.empty()) f << "# " << comment << "\n";
  f << d.points.size() << " 2 0 0\n";
  for (std::size_t i = 0; i < d.points.size(); ++i) f << i + 1 << " " << d.points[i].x() << " " << d.points[i].y() << "\n";
  f << d.segments.size() << " 0\n";
  for (std::size_t i = 0; i < d.segments.size(); ++i) f << i + 1 << " " << d.segments[i][0] + 1 << " " << d.segments[i][1] + 1 << "\n";
  f << d.holes.size() << "\n";
  for (std::size_t i = 0; i < d.holes.size(); ++i) f << i + 1 << " " << d.holes[i].x() << " " << d.holes[i].y() << "\n";
}

}  // namespace acute::test
