// Layer: mesh. Quality figures, computed with the same float formulas and the same tolerances as
// shared/tools/meshcheck (check 4) so that both report identical counts on the same file.
#include <acute/mesh/quality.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace acute {

namespace {

constexpr double kAngleTol = 1e-9;  // degrees: angles this close to a bound count as equal to it
constexpr double kDeg = 180.0 / 3.14159265358979323846;

/// Correctly rounded sum of doubles (the "partials" algorithm, as Python's math.fsum), so the
/// means agree with meshcheck's to the last bit.
class ExactSum {
 public:
  void add(double x) {
    std::size_t i = 0;
    for (double y : partials_) {
      if (std::abs(x) < std::abs(y)) std::swap(x, y);
      const double hi = x + y;
      const double lo = y - (hi - x);
      if (lo != 0.0) partials_[i++] = lo;
      x = hi;
    }
    partials_.resize(i);
    partials_.push_back(x);
  }
  double value() const {
    if (partials_.empty()) return 0.0;
    std::size_t n = partials_.size() - 1;
    double hi = partials_[n], lo = 0.0;
    while (n > 0) {
      const double x = hi, y = partials_[--n];
      hi = x + y;
      lo = y - (hi - x);
      if (lo != 0.0) break;
    }
    // Round half-way cases the way a single rounding of the exact sum would.
    if (n > 0 && ((lo < 0 && partials_[n - 1] < 0) || (lo > 0 && partials_[n - 1] > 0))) {
      const double y = lo * 2, x = hi + y;
      if (y == x - hi) hi = x;
    }
    return hi;
  }

 private:
  std::vector<double> partials_;
};

bool lex_less(const Point2& p, const Point2& q) { return p.x() != q.x() ? p.x() < q.x() : p.y() < q.y(); }

/// 0 when direction v->p has angle in [0, 180), else 1 (exact).
int half_plane(const Point2& v, const Point2& p) {
  if (p.y() != v.y()) return p.y() > v.y() ? 0 : 1;
  return p.x() > v.x() ? 0 : 1;
}

/// Counter-clockwise angle in degrees from v->p to v->q in (0, 360]; its side of 180 is exact.
double ccw_angle_deg(const Point2& v, const Point2& p, const Point2& q) {
  const Sign o = predicates::orient2d(v, p, q);
  const double x1 = p.x() - v.x(), y1 = p.y() - v.y(), x2 = q.x() - v.x(), y2 = q.y() - v.y();
  const double dot = x1 * x2 + y1 * y2;
  const double a = std::atan2(std::abs(x1 * y2 - y1 * x2), dot) * kDeg;
  if (o == Sign::Positive) return a;
  if (o == Sign::Negative) return 360.0 - a;
  return dot < 0 ? 180.0 : 360.0;
}

/// Is direction v->p within the counter-clockwise half-open range [v->r, v->s)? (exact; p, r, s != v)
bool in_ccw_range(const Point2& v, const Point2& r, const Point2& s, const Point2& p) {
  // Rank of a direction when rotating ccw from r: (half, then orientation order).
  auto half_from_r = [&](const Point2& x) {
    const Sign o = predicates::orient2d(v, r, x);
    if (o == Sign::Positive) return 0;
    if (o == Sign::Negative) return 1;
    return predicates::angle_kind(v, r, x) == AngleKind::Obtuse ? 1 : 0;  // opposite r: 180 degrees
  };
  auto before = [&](const Point2& x, const Point2& y) {  // x strictly before y from r
    const int hx = half_from_r(x), hy = half_from_r(y);
    if (hx != hy) return hx < hy;
    return predicates::orient2d(v, x, y) == Sign::Positive;
  };
  if (predicates::orient2d(v, r, s) == Sign::Zero && predicates::angle_kind(v, r, s) != AngleKind::Obtuse)
    return true;  // r == s direction: the range is the full turn
  return before(p, s);
}

/// The planar straight-line graph of a domain as meshcheck builds it: repeated points merged,
/// zero-length segments dropped, segments split at input points on them, repeated pieces merged.
struct Pslg {
  std::vector<Point2> pts;                 // merged points
  std::vector<int> first_input;            // merged point -> first Domain::points index
  std::vector<std::vector<int>> nb;        // neighbours, sorted counter-clockwise
  std::vector<std::pair<int, int>> darts;  // (vertex, neighbour slot) of every sector, in order

  explicit Pslg(const Domain& d) {
    const int n = int(d.points.size());
    std::vector<int> order(n);
    for (int i = 0; i < n; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return lex_less(d.points[a], d.points[b]); });
    std::vector<int> rep(n, -1);
    for (int k = 0; k < n; ++k) {
      const int i = order[k];
      if (k > 0 && d.points[i] == d.points[order[k - 1]]) {
        rep[i] = rep[order[k - 1]];
        first_input[rep[i]] = std::min(first_input[rep[i]], i);
      } else {
        rep[i] = int(pts.size());
        pts.push_back(d.points[i]);
        first_input.push_back(i);
      }
    }
    // pts is sorted lexicographically: candidates on a segment are found by bisection on x.
    nb.assign(pts.size(), {});
    std::vector<std::pair<int, int>> pieces;
    for (const auto& s : d.segments) {
      if (s[0] < 0 || s[1] < 0 || s[0] >= n || s[1] >= n) continue;
      const int a = rep[s[0]], b = rep[s[1]];
      if (a == b) continue;
      const Point2 &pa = pts[a], &pb = pts[b];
      const double xlo = std::min(pa.x(), pb.x()), xhi = std::max(pa.x(), pb.x());
      const double ylo = std::min(pa.y(), pb.y()), yhi = std::max(pa.y(), pb.y());
      auto lo = std::lower_bound(pts.begin(), pts.end(), Point2(xlo, -std::numeric_limits<double>::infinity()), lex_less);
      std::vector<int> on;
      for (auto it = lo; it != pts.end() && it->x() <= xhi; ++it) {
        const int k = int(it - pts.begin());
        if (k == a || k == b || it->y() < ylo || it->y() > yhi) continue;
        if (predicates::locate_on_segment(*it, pa, pb) == predicates::SegmentLocation::OnInterior) on.push_back(k);
      }
      // Points on a segment are ordered from a to b lexicographically (or the reverse).
      const bool forward = lex_less(pa, pb);
      std::sort(on.begin(), on.end(), [&](int u, int v) { return forward ? u < v : u > v; });
      int prev = a;
      on.push_back(b);
      for (int k : on) {
        pieces.emplace_back(std::min(prev, k), std::max(prev, k));
        prev = k;
      }
    }
    std::sort(pieces.begin(), pieces.end());
    pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
    for (auto [u, v] : pieces) {
      nb[u].push_back(v);
      nb[v].push_back(u);
    }
    for (std::size_t v = 0; v < nb.size(); ++v) {
      const Point2& pv = pts[v];
      std::sort(nb[v].begin(), nb[v].end(), [&](int i, int j) {
        const int hi = half_plane(pv, pts[i]), hj = half_plane(pv, pts[j]);
        if (hi != hj) return hi < hj;
        return predicates::orient2d(pv, pts[i], pts[j]) == Sign::Positive;
      });
      for (std::size_t s = 0; s < nb[v].size(); ++s) darts.emplace_back(int(v), int(s));
    }
  }

  /// Angle of the sector from neighbour slot s counter-clockwise to the next one.
  double sector_angle(int v, int s) const {
    const auto& l = nb[v];
    if (l.size() == 1) return 360.0;
    return ccw_angle_deg(pts[v], pts[l[s]], pts[l[(s + 1) % l.size()]]);
  }
};

std::vector<ForcedCorner> collect_forced(const Pslg& g, double min_angle_deg,
                                         const std::function<bool(int, int)>& sector_in_domain) {
  std::vector<ForcedCorner> out;
  for (auto [v, s] : g.darts) {
    const double a = g.sector_angle(v, s);
    if (a < min_angle_deg - kAngleTol && sector_in_domain(v, s)) out.push_back(ForcedCorner{g.first_input[v], a});
  }
  std::stable_sort(out.begin(), out.end(), [](const ForcedCorner& x, const ForcedCorner& y) { return x.angle_deg < y.angle_deg; });
  return out;
}

/// Mesh vertices used by faces, sorted by position (for exact coordinate look-ups).
std::vector<VertexHandle> used_vertices_by_position(const Mesh& mesh) {
  // Sorted as (x, y, index) copies, not handles that look their points up: the same order as a
  // stable sort of the handles by position, at a third of the time on a million vertices.
  struct Keyed {
    double x, y;
    int idx;
  };
  std::vector<Keyed> keyed;
  keyed.reserve(mesh.n_vertices());
  for (auto vh : mesh.vertices())
    if (!mesh.is_isolated(vh)) keyed.push_back({mesh.point(vh)[0], mesh.point(vh)[1], vh.idx()});
  std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.idx < b.idx;
  });
  std::vector<VertexHandle> vs;
  vs.reserve(keyed.size());
  for (const Keyed& k : keyed) vs.emplace_back(k.idx);
  return vs;
}

VertexHandle find_vertex_at(const Mesh& mesh, const std::vector<VertexHandle>& sorted, const Point2& p) {
  auto it = std::lower_bound(sorted.begin(), sorted.end(), p,
                             [&](VertexHandle vh, const Point2& q) { return lex_less(point2(mesh, vh), q); });
  if (it != sorted.end() && point2(mesh, *it) == p) return *it;
  return VertexHandle();
}

std::vector<ForcedCorner> forced_corners_mesh_based(const Pslg& g, double min_angle_deg, const Mesh& mesh,
                                                    const std::vector<VertexHandle>& sorted) {
  return collect_forced(g, min_angle_deg, [&](int v, int s) {
    const VertexHandle mv = find_vertex_at(mesh, sorted, g.pts[v]);
    if (!mv.is_valid()) return false;
    const auto& l = g.nb[v];
    if (l.size() == 1) return true;  // the mesh has triangles at the end of a dangling segment
    const Point2 &pv = g.pts[v], &r = g.pts[l[s]], &e = g.pts[l[(s + 1) % l.size()]];
    // A conforming mesh has each triangle corner at mv inside one sector: test its first edge.
    for (auto heh : mesh.voh_range(mv)) {
      if (mesh.is_boundary(heh)) continue;
      if (in_ccw_range(pv, r, e, point2(mesh, mesh.to_vertex_handle(heh)))) return true;
    }
    return false;
  });
}

/// Which sectors of a PSLG lie in its domain, from the PSLG alone: faces are traced on the
/// half-edges (face on the left), a counter-clockwise cycle bounds a bounded face, the outer
/// cycle of a connected component lies in the innermost counter-clockwise cycle of another
/// component that contains it, and faces containing a hole seed are removed.
class DomainFaces {
 public:
  DomainFaces(const Pslg& g, const Domain& d) : g_(g) {
    const int nv = int(g.nb.size());
    offset_.assign(nv + 1, 0);
    for (int v = 0; v < nv; ++v) offset_[v + 1] = offset_[v] + int(g.nb[v].size());
    const int nd = offset_[nv];
    cycle_.assign(nd, -1);
    std::vector<int> comp = components();
    std::vector<int> cycle_comp;
    for (int v = 0; v < nv; ++v) {
      for (int s = 0; s < int(g.nb[v].size()); ++s) {
        if (cycle_[offset_[v] + s] >= 0) continue;
        const int id = int(cycles_.size());
        cycles_.emplace_back();
        ExactSum area2;
        int u = v, k = s;
        while (cycle_[offset_[u] + k] < 0) {
          cycle_[offset_[u] + k] = id;
          cycles_.back().push_back({u, g.nb[u][k]});
          const int w = g.nb[u][k];
          const Point2 &pu = g.pts[u], &pw = g.pts[w];
          area2.add(pu.x() * pw.y());
          area2.add(-(pw.x() * pu.y()));
          // Next dart: at w, the neighbour just clockwise of u.
          const auto& l = g.nb[w];
          const int j = int(std::find(l.begin(), l.end(), u) - l.begin());
          k = (j + int(l.size()) - 1) % int(l.size());
          u = w;
        }
        area2_.push_back(area2.value());
        cycle_comp.push_back(comp[v]);
      }
    }
    // The face each cycle bounds: itself when counter-clockwise, else the face around its component.
    face_.assign(cycles_.size(), -1);
    for (std::size_t c = 0; c < cycles_.size(); ++c) {
      if (area2_[c] > 0) {
        face_[c] = int(c);
      } else {
        face_[c] = innermost_containing(g.pts[cycles_[c].front().first], cycle_comp, cycle_comp[c]);
      }
    }
    hole_.assign(cycles_.size(), 0);
    for (const Point2& h : d.holes) {
      bool on_segment = false;
      for (const auto& cyc : cycles_)
        for (auto [u, w] : cyc)
          if (predicates::locate_on_segment(h, g.pts[u], g.pts[w]) != predicates::SegmentLocation::Outside) on_segment = true;
      if (on_segment) continue;  // meshcheck ignores such a seed
      const int f = innermost_containing(h, cycle_comp, -1);
      if (f >= 0) hole_[f] = 1;
    }
  }

  bool sector_in_domain(int v, int s) const {
    const int f = face_[cycle_[offset_[v] + s]];
    return f >= 0 && !hole_[f];
  }

 private:
  std::vector<int> components() const {
    std::vector<int> comp(g_.nb.size(), -1);
    int n = 0;
    for (std::size_t v = 0; v < g_.nb.size(); ++v) {
      if (comp[v] >= 0) continue;
      std::vector<int> stack{int(v)};
      comp[v] = n;
      while (!stack.empty()) {
        const int u = stack.back();
        stack.pop_back();
        for (int w : g_.nb[u])
          if (comp[w] < 0) {
            comp[w] = n;
            stack.push_back(w);
          }
      }
      ++n;
    }
    return comp;
  }

  /// Winding number of a closed cycle around p (p not on it), with exact orientations.
  int winding(const std::vector<std::pair<int, int>>& cyc, const Point2& p) const {
    int w = 0;
    for (auto [a, b] : cyc) {
      const Point2 &pa = g_.pts[a], &pb = g_.pts[b];
      if (pa.y() <= p.y()) {
        if (pb.y() > p.y() && predicates::orient2d(pa, pb, p) == Sign::Positive) ++w;
      } else if (pb.y() <= p.y() && predicates::orient2d(pa, pb, p) == Sign::Negative) {
        --w;
      }
    }
    return w;
  }

  /// The smallest counter-clockwise cycle, of a component other than skip_comp, around p; -1 if none.
  int innermost_containing(const Point2& p, const std::vector<int>& cycle_comp, int skip_comp) const {
    int best = -1;
    for (std::size_t c = 0; c < cycles_.size(); ++c) {
      if (!(area2_[c] > 0) || cycle_comp[c] == skip_comp) continue;
      if (best >= 0 && !(area2_[c] < area2_[best])) continue;
      if (winding(cycles_[c], p) != 0) best = int(c);
    }
    return best;
  }

  const Pslg& g_;
  std::vector<int> offset_, cycle_, face_;
  std::vector<std::vector<std::pair<int, int>>> cycles_;
  std::vector<double> area2_;
  std::vector<char> hole_;
};

}  // namespace

std::vector<ForcedCorner> forced_corners(const Domain& domain, double min_angle_deg) {
  const Pslg g(domain);
  const DomainFaces faces(g, domain);
  return collect_forced(g, min_angle_deg, [&](int v, int s) { return faces.sector_in_domain(v, s); });
}

std::array<double, 3> triangle_angles_deg(const Point2& a, const Point2& b, const Point2& c) {
  // Same operation order as meshcheck: u = b - a, v = c - a, w = v - u.
  const double ux = b.x() - a.x(), uy = b.y() - a.y();
  const double vx = c.x() - a.x(), vy = c.y() - a.y();
  const double wx = vx - ux, wy = vy - uy;
  const double cr = std::abs(ux * vy - uy * vx);
  return {std::atan2(cr, ux * vx + uy * vy) * kDeg, std::atan2(cr, -(ux * wx + uy * wy)) * kDeg,
          std::atan2(cr, vx * wx + vy * wy) * kDeg};
}

double narrowest_feasible_corner(double max_angle) { return 3.14159265358979323846 - 2.0 * max_angle; }

std::vector<ForcedCorner> unsatisfiable_sectors(const Domain& domain, double min_angle_deg, double max_angle_deg) {
  // Corners a triangle can have with its other two angles in [min, max): (180 - 2 max, 180 - 2 min].
  const double corner_lo = narrowest_feasible_corner(max_angle_deg / kDeg) * kDeg, corner_hi = 180.0 - 2.0 * min_angle_deg;
  // Corners of a split sector are in [min, max) too.
  const double lo = std::max(min_angle_deg, corner_lo), hi = std::min(max_angle_deg, corner_hi);
  auto satisfiable = [&](double theta) {
    if (theta < min_angle_deg - kAngleTol) return theta > corner_lo + kAngleTol;
    if (!(hi > lo)) return false;
    if (lo <= kAngleTol) return true;  // corners as small as needed
    // k corners cover [k lo, k hi] (hi and a lo of 180 - 2 max are open: a hair inside them)
    for (double k = std::max(1.0, std::floor(theta / hi)); k <= std::ceil(theta / lo) + 1; ++k)
      if (theta >= k * lo - kAngleTol && theta <= k * hi + kAngleTol) return true;
    return false;
  };
  std::vector<ForcedCorner> out;
  for (const ForcedCorner& sector : forced_corners(domain, 361.0))
    if (!satisfiable(sector.angle_deg)) out.push_back(sector);
  return out;
}

std::vector<ForcedCorner> forced_corners(const Domain& domain, double min_angle_deg, const Mesh& mesh) {
  const Pslg g(domain);
  return forced_corners_mesh_based(g, min_angle_deg, mesh, used_vertices_by_position(mesh));
}

QualityReport measure_quality(const Mesh& mesh, const QualityOptions& options, const Domain* domain) {
  QualityReport r;
  r.min_angle_bound = options.min_angle_deg;
  r.max_angle_bound = options.max_angle_deg;
  r.has_histogram = options.histogram;
  const double s3 = std::sqrt(3.0);

  std::vector<std::array<VertexHandle, 3>> tris;
  tris.reserve(mesh.n_faces());
  for (auto fh : mesh.faces()) {
    std::array<VertexHandle, 3> t;
    int k = 0;
    for (auto fv : mesh.fv_range(fh)) {  // starts at the first vertex given to add_face
      if (k < 3) t[k] = fv;
      ++k;
    }
    if (k == 3) tris.push_back(t);
  }
  const std::size_t nt = tris.size();
  r.n_triangles = nt;
  const auto sorted = used_vertices_by_position(mesh);
  r.n_vertices = sorted.size();

  std::vector<double> tmin(nt), tmax(nt), qual(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const Point2 a = point2(mesh, tris[t][0]), b = point2(mesh, tris[t][1]), c = point2(mesh, tris[t][2]);
    const auto ang = triangle_angles_deg(a, b, c);
    tmin[t] = std::min({ang[0], ang[1], ang[2]});
    tmax[t] = std::max({ang[0], ang[1], ang[2]});
    const double ux = b.x() - a.x(), uy = b.y() - a.y(), vx = c.x() - a.x(), vy = c.y() - a.y();
    const double wx = vx - ux, wy = vy - uy;
    const double cr = std::abs(ux * vy - uy * vx);
    const double la = std::sqrt(wx * wx + wy * wy), lb = std::sqrt(vx * vx + vy * vy), lc = std::sqrt(ux * ux + uy * uy);
    const double h = std::max(std::max(la, lb), lc);
    const double ph = (la + lb + lc) * 0.5 * h;
    qual[t] = ph > 0 ? s3 * cr / ph : 0.0;
    if (options.histogram) {
      for (double v : ang) {
        const double rr = std::nearbyint(v / 10.0);  // ties to even, as Python's round()
        if (std::abs(v - 10.0 * rr) <= kAngleTol) {
          if (rr == 9.0) {
            ++r.histogram_right;
            continue;
          }
          v = 10.0 * rr;
        }
        const double i = std::floor(v / 10.0);
        r.histogram[i < 0 ? 0 : (i > 17 ? 17 : std::size_t(i))] += 1;
      }
    }
  }

  // Steiner points and forced corners need the domain.
  std::vector<char> forced_vertex(mesh.n_vertices(), 0);
  bool any_forced = false;
  if (domain) {
    std::vector<Point2> inputs = domain->points;
    std::sort(inputs.begin(), inputs.end(), lex_less);
    std::size_t steiner = 0;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
      const Point2 p = point2(mesh, sorted[i]);
      if (i > 0 && point2(mesh, sorted[i - 1]) == p) continue;  // count positions once
      if (!std::binary_search(inputs.begin(), inputs.end(), p, lex_less)) ++steiner;
    }
    r.n_steiner = steiner;
    // The domain-based test: it agrees with meshcheck even when the mesh is off the segments by
    // rounding (the mesh-based one then misses corners).
    r.forced_corners = forced_corners(*domain, options.min_angle_deg);
    for (const auto& fc : r.forced_corners) {
      const VertexHandle vh = find_vertex_at(mesh, sorted, domain->points[fc.point]);
      if (vh.is_valid()) {
        forced_vertex[vh.idx()] = 1;
        any_forced = true;
      }
    }
  }
  if (nt == 0) return r;

  const double lo_b = options.min_angle_deg - kAngleTol, max_b = options.max_angle_deg;
  r.min_angle = *std::min_element(tmin.begin(), tmin.end());
  r.max_angle = *std::max_element(tmax.begin(), tmax.end());
  for (std::size_t t = 0; t < nt; ++t) {
    const double lo = tmin[t], hi = tmax[t];
    r.n_below_min += lo < lo_b;
    r.n_above_max += hi > max_b + kAngleTol;
    r.n_at_max += std::abs(hi - max_b) <= kAngleTol;
    r.n_right += std::abs(hi - 90.0) <= kAngleTol;
    r.n_obtuse += hi > 90.0 + kAngleTol;
    r.n_max_violations += hi > max_b - kAngleTol;
  }
  auto mean_std = [nt](const std::vector<double>& xs) {
    ExactSum s;
    for (double x : xs) s.add(x);
    const double m = s.value() / double(nt);
    ExactSum v;
    for (double x : xs) v.add((x - m) * (x - m));
    return std::make_pair(m, std::sqrt(v.value() / double(nt)));
  };
  std::tie(r.mean_min_angle, r.std_min_angle) = mean_std(tmin);
  std::tie(r.mean_max_angle, r.std_max_angle) = mean_std(tmax);
  r.q_min = *std::min_element(qual.begin(), qual.end());
  ExactSum qs;
  for (double q : qual) qs.add(q);
  r.q_mean = qs.value() / double(nt);

  if (any_forced) {
    for (std::size_t t = 0; t < nt; ++t) {
      const auto& tv = tris[t];
      if (forced_vertex[tv[0].idx()] || forced_vertex[tv[1].idx()] || forced_vertex[tv[2].idx()]) continue;
      ++r.n_free_triangles;
      if (!r.free_min_angle || tmin[t] < *r.free_min_angle) r.free_min_angle = tmin[t];
      r.n_below_min_free += tmin[t] < lo_b;
    }
  } else {
    r.free_min_angle = r.min_angle;
    r.n_free_triangles = nt;
    r.n_below_min_free = r.n_below_min;
  }
  return r;
}

}  // namespace acute
