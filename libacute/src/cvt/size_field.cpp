#include <acute/cvt/size_field.h>

#include <acute/core/errors.h>
#include <acute/delaunay/cdt.h>
#include <acute/mesh/geometry.h>
#include <acute/mesh/sectors.h>
#include <acute/mesh/segments.h>
#include <acute/predicates/predicates.h>

#include "cvt/narrow_sectors.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <queue>
#include <tuple>

namespace acute {

SizeField SizeField::uniform(double h) {
  if (!(h > 0) || !std::isfinite(h)) throw InvalidInput("size field: size must be positive and finite, got " + std::to_string(h));
  SizeField f;
  f.uniform_ = h;
  f.min_ = f.max_ = h;
  return f;
}

SizeField SizeField::piecewise_linear(std::vector<Point2> points, std::vector<std::array<int, 3>> triangles, std::vector<double> values) {
  if (points.size() != values.size()) throw InvalidInput("size field: one value per point is needed");
  if (triangles.empty()) throw InvalidInput("size field: empty background triangulation");
  SizeField f;
  f.points_ = std::move(points);
  f.triangles_ = std::move(triangles);
  f.values_ = std::move(values);
  // Adjacency: sort the directed edges (min, max, triangle, corner) and pair them up.
  std::vector<std::tuple<int, int, int, int>> edges;
  edges.reserve(3 * f.triangles_.size());
  for (std::size_t t = 0; t < f.triangles_.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = f.triangles_[t][static_cast<std::size_t>((i + 1) % 3)], b = f.triangles_[t][static_cast<std::size_t>((i + 2) % 3)];
      edges.emplace_back(std::min(a, b), std::max(a, b), static_cast<int>(t), i);
    }
  std::sort(edges.begin(), edges.end());
  f.neighbours_.assign(f.triangles_.size(), {-1, -1, -1});
  for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
    const auto& [a0, b0, t0, i0] = edges[k];
    const auto& [a1, b1, t1, i1] = edges[k + 1];
    if (a0 == a1 && b0 == b1) {
      f.neighbours_[static_cast<std::size_t>(t0)][static_cast<std::size_t>(i0)] = t1;
      f.neighbours_[static_cast<std::size_t>(t1)][static_cast<std::size_t>(i1)] = t0;
      ++k;
    }
  }
  f.update_range();
  return f;
}

void SizeField::update_range() {
  if (is_uniform()) {
    min_ = max_ = uniform_;
    return;
  }
  min_ = std::numeric_limits<double>::infinity();
  max_ = 0;
  for (const auto& t : triangles_)
    for (int v : t) {
      min_ = std::min(min_, values_[static_cast<std::size_t>(v)]);
      max_ = std::max(max_, values_[static_cast<std::size_t>(v)]);
    }
}

SizeField SizeField::with_values(std::vector<double> values) const {
  if (is_uniform() || values.size() != points_.size()) throw InvalidInput("size field: one value per background point is needed");
  SizeField f;
  f.points_ = points_;
  f.triangles_ = triangles_;
  f.neighbours_ = neighbours_;
  f.values_ = std::move(values);
  f.update_range();
  return f;
}

void SizeField::scale(double factor) {
  if (!(factor > 0)) throw InvalidInput("size field: scale factor must be positive");
  uniform_ *= factor;
  for (double& v : values_) v *= factor;
  update_range();
}

int SizeField::walk(const Point2& p, int start) const {
  const int nt = static_cast<int>(triangles_.size());
  int t = (start >= 0 && start < nt) ? start : 0;
  unsigned rot = 0;
  for (int step = 0; step < 4 * nt + 16; ++step) {
    const auto& tri = triangles_[static_cast<std::size_t>(t)];
    int next = -1;
    ++rot;
    for (int k = 0; k < 3; ++k) {
      const int i = static_cast<int>((rot + static_cast<unsigned>(k)) % 3u);
      const Point2& a = points_[static_cast<std::size_t>(tri[static_cast<std::size_t>((i + 1) % 3)])];
      const Point2& b = points_[static_cast<std::size_t>(tri[static_cast<std::size_t>((i + 2) % 3)])];
      if (predicates::orient2d(a, b, p) == Sign::Negative) {
        const int n = neighbours_[static_cast<std::size_t>(t)][static_cast<std::size_t>(i)];
        if (n >= 0) {
          next = n;
          break;
        }
      }
    }
    if (next < 0) return t;  // p is in t, or beyond the hull next to it
    t = next;
  }
  return t;
}

double SizeField::along_nearest_edge(int t, const Point2& p) const {
  const auto& tri = triangles_[static_cast<std::size_t>(t)];
  double best_d2 = std::numeric_limits<double>::infinity(), best = values_[static_cast<std::size_t>(tri[0])];
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(tri[static_cast<std::size_t>(k)]), j = static_cast<std::size_t>(tri[static_cast<std::size_t>((k + 1) % 3)]);
    const Point2 d = points_[j] - points_[i];
    const double len2 = d.squaredNorm();
    const double w = len2 > 0 ? std::clamp((p - points_[i]).dot(d) / len2, 0.0, 1.0) : 0.0;
    const double d2 = (points_[i] + w * d - p).squaredNorm();
    if (d2 < best_d2) best_d2 = d2, best = (1 - w) * values_[i] + w * values_[j];
  }
  return best;
}

double SizeField::eval(const Point2& p, int& hint) const {
  if (is_uniform()) return uniform_;
  auto barycentric = [&](int t, double (&l)[3]) {
    const auto& tri = triangles_[static_cast<std::size_t>(t)];
    const Point2& a = points_[static_cast<std::size_t>(tri[0])];
    const Point2& b = points_[static_cast<std::size_t>(tri[1])];
    const Point2& c = points_[static_cast<std::size_t>(tri[2])];
    const double det = signed_area2(a, b, c);
    l[0] = signed_area2(p, b, c) / det, l[1] = signed_area2(a, p, c) / det, l[2] = signed_area2(a, b, p) / det;
  };
  // Most queries fall in the hint's triangle: its rounded barycentric coordinates say so without
  // the exact walk (an interpolation, not a topological decision: on an edge either side gives
  // the same value).
  double l[3];
  const bool hinted = hint >= 0 && hint < static_cast<int>(triangles_.size());
  if (hinted) barycentric(hint, l);
  if (!hinted || !(l[0] >= 0 && l[1] >= 0 && l[2] >= 0)) {
    hint = walk(p, hint);
    barycentric(hint, l);
  }
  const auto& tri = triangles_[static_cast<std::size_t>(hint)];
  // A background triangle whose rounded area is zero (collinear samples along a slanted wall; its
  // exact area is not) has no barycentric coordinates: interpolate along its edge nearest p.
  if (!(std::isfinite(l[0]) && std::isfinite(l[1]) && std::isfinite(l[2]))) return along_nearest_edge(hint, p);
  double l0 = std::max(l[0], 0.0), l1 = std::max(l[1], 0.0), l2 = std::max(l[2], 0.0);
  const double s = l0 + l1 + l2;
  if (!(s > 0)) return values_[static_cast<std::size_t>(tri[0])];
  return (l0 * values_[static_cast<std::size_t>(tri[0])] + l1 * values_[static_cast<std::size_t>(tri[1])] +
          l2 * values_[static_cast<std::size_t>(tri[2])]) /
         s;
}

DomainMeasures measure_domain(const Mesh& mesh) {
  DomainMeasures m;
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  for (auto vh : mesh.vertices()) {
    const Point2 p = point2(mesh, vh);
    xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
  }
  if (xmin <= xmax) m.diameter = std::hypot(xmax - xmin, ymax - ymin);
  for (auto fh : mesh.faces()) {
    const auto p = face_points(mesh, fh);
    m.area += 0.5 * signed_area2(p[0], p[1], p[2]);
  }
  for (auto eh : mesh.edges()) {
    if (!mesh.is_boundary(eh)) continue;
    const auto h = mesh.halfedge_handle(eh, 0);
    m.boundary_length += (point2(mesh, mesh.to_vertex_handle(h)) - point2(mesh, mesh.from_vertex_handle(h))).norm();
  }
  return m;
}

double size_for_vertex_count(const DomainMeasures& measures, std::size_t n) {
  if (n < 3) throw InvalidInput("size field: the target vertex count must be at least 3");
  if (!(measures.area > 0)) throw InvalidInput("size field: the domain has no area");
  const double qa = 2.0 * measures.area / std::sqrt(3.0), qb = 0.5 * measures.boundary_length, qc = 1.0 - static_cast<double>(n);
  const double u = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);  // u = 1/h
  return 1.0 / u;
}

double predicted_vertex_count(const Mesh& mesh, const SizeField& field) {
  double n = 1.0;
  int hint = -1;
  struct Tri {
    Point2 a, b, c;
    int depth;
  };
  std::vector<Tri> stack;
  for (auto fh : mesh.faces()) {
    const auto p = face_points(mesh, fh);
    stack.push_back({p[0], p[1], p[2], 0});
    while (!stack.empty()) {
      const Tri t = stack.back();
      stack.pop_back();
      const double h = field.eval((t.a + t.b + t.c) / 3.0, hint);
      const double area = 0.5 * signed_area2(t.a, t.b, t.c);
      if (!field.is_uniform() && area > 4.0 * h * h && t.depth < 12) {
        const Point2 ab = 0.5 * (t.a + t.b), bc = 0.5 * (t.b + t.c), ca = 0.5 * (t.c + t.a);
        stack.push_back({t.a, ab, ca, t.depth + 1});
        stack.push_back({ab, t.b, bc, t.depth + 1});
        stack.push_back({ca, bc, t.c, t.depth + 1});
        stack.push_back({ab, bc, ca, t.depth + 1});
        continue;
      }
      n += area * 2.0 / (std::sqrt(3.0) * h * h);
    }
  }
  for (auto eh : mesh.edges()) {
    if (!mesh.is_boundary(eh)) continue;
    const auto he = mesh.halfedge_handle(eh, 0);
    const Point2 a = point2(mesh, mesh.from_vertex_handle(he)), b = point2(mesh, mesh.to_vertex_handle(he));
    n += (b - a).norm() / (2.0 * field.eval(0.5 * (a + b), hint));
  }
  return n;
}

namespace {

/// The vertices and constrained/boundary edges of a mesh in a bucket grid, for exact
/// nearest-feature distances with features incident to given vertices excluded.
class FeatureGrid {
 public:
  explicit FeatureGrid(const Mesh& mesh) {
    std::vector<int> vmap(mesh.n_vertices(), -1);
    for (auto vh : mesh.vertices()) {
      if (mesh.status(vh).deleted() || mesh.is_isolated(vh)) continue;
      vmap[static_cast<std::size_t>(vh.idx())] = static_cast<int>(points_.size());
      points_.push_back(point2(mesh, vh));
      vertex_of_.push_back(vh.idx());
    }
    for (auto eh : mesh.edges()) {
      if (mesh.status(eh).deleted() || !(is_constrained(mesh, eh) || mesh.is_boundary(eh))) continue;
      const auto h = mesh.halfedge_handle(eh, 0);
      edges_.push_back({vmap[static_cast<std::size_t>(mesh.from_vertex_handle(h).idx())],
                        vmap[static_cast<std::size_t>(mesh.to_vertex_handle(h).idx())]});
    }
    index_of_.assign(mesh.n_vertices(), -1);
    for (std::size_t i = 0; i < vertex_of_.size(); ++i) index_of_[static_cast<std::size_t>(vertex_of_[i])] = static_cast<int>(i);
    lo_ = hi_ = points_.empty() ? Point2(0, 0) : points_[0];
    for (const Point2& p : points_) lo_ = lo_.cwiseMin(p), hi_ = hi_.cwiseMax(p);
    const double w = hi_.x() - lo_.x(), ht = hi_.y() - lo_.y();
    const double n = static_cast<double>(std::max<std::size_t>(points_.size(), 1));
    cell_ = std::max({std::sqrt(w * ht / n), std::max(w, ht) / 2048.0, std::numeric_limits<double>::min()});
    nx_ = static_cast<int>(w / cell_) + 1;
    ny_ = static_cast<int>(ht / cell_) + 1;
    // Counting pass, then fill (CSR); items: vertex i -> i, edge k -> n_points + k.
    std::vector<std::pair<int, int>> pairs;  // (cell, item)
    for (std::size_t i = 0; i < points_.size(); ++i) pairs.emplace_back(cell_of(points_[i]), static_cast<int>(i));
    for (std::size_t k = 0; k < edges_.size(); ++k) {
      const Point2 a = points_[static_cast<std::size_t>(edges_[k][0])], b = points_[static_cast<std::size_t>(edges_[k][1])];
      const int item = static_cast<int>(points_.size() + k);
      // Row bands: the x-range of the edge within each row, widened by one cell for rounding.
      const int j0 = row(std::min(a.y(), b.y())), j1 = row(std::max(a.y(), b.y()));
      for (int j = j0; j <= j1; ++j) {
        const double y0 = lo_.y() + j * cell_, y1 = y0 + cell_;
        double xa = a.x(), xb = b.x();
        if (a.y() != b.y()) {
          const auto x_at = [&](double y) { return a.x() + (b.x() - a.x()) * std::clamp((y - a.y()) / (b.y() - a.y()), 0.0, 1.0); };
          xa = x_at(y0), xb = x_at(y1);
        }
        const int i0 = std::max(0, col(std::min(xa, xb)) - 1), i1 = std::min(nx_ - 1, col(std::max(xa, xb)) + 1);
        for (int i = i0; i <= i1; ++i) pairs.emplace_back(j * nx_ + i, item);
      }
    }
    start_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 1, 0);
    for (const auto& pr : pairs) ++start_[static_cast<std::size_t>(pr.first) + 1];
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(pairs.size());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (const auto& pr : pairs) items_[static_cast<std::size_t>(fill[static_cast<std::size_t>(pr.first)]++)] = pr.second;
  }

  std::size_t num_points() const { return points_.size(); }
  const Point2& point(std::size_t i) const { return points_[i]; }
  const std::vector<std::array<int, 2>>& edges() const { return edges_; }
  /// Grid index of mesh vertex idx (-1: not a feature).
  int index_of(int vertex_idx) const { return index_of_[static_cast<std::size_t>(vertex_idx)]; }

  /// Distance from p to the nearest feature that is not grid vertex x0/x1 and has no endpoint
  /// among them (infinity when there is none).
  double nearest(const Point2& p, int x0, int x1, Point2* foot = nullptr) const {
    const int ci = col(p.x()), cj = row(p.y());
    double best = std::numeric_limits<double>::infinity();
    Point2 best_foot = p;
    const int kmax = std::max(nx_, ny_);
    for (int k = 0; k <= kmax; ++k) {
      // Cells at Chebyshev ring k are at least (k - 1) * cell_ away (one cell of rasterisation slack).
      if (best <= (k - 1) * cell_) break;
      for (int j = cj - k; j <= cj + k; ++j) {
        if (j < 0 || j >= ny_) continue;
        const int step = (j == cj - k || j == cj + k) ? 1 : 2 * k;
        for (int i = ci - k; i <= ci + k; i += std::max(step, 1)) {
          if (i < 0 || i >= nx_) continue;
          const auto c = static_cast<std::size_t>(j * nx_ + i);
          for (int s = start_[c]; s < start_[c + 1]; ++s) {
            const int item = items_[static_cast<std::size_t>(s)];
            if (item < static_cast<int>(points_.size())) {
              if (item == x0 || item == x1) continue;
              const double d = (points_[static_cast<std::size_t>(item)] - p).norm();
              if (d < best) best = d, best_foot = points_[static_cast<std::size_t>(item)];
            } else {
              const auto& e = edges_[static_cast<std::size_t>(item) - points_.size()];
              if (e[0] == x0 || e[0] == x1 || e[1] == x0 || e[1] == x1) continue;
              const Point2 q = nearest_on_segment(p, points_[static_cast<std::size_t>(e[0])], points_[static_cast<std::size_t>(e[1])]);
              const double d = (p - q).norm();
              if (d < best) best = d, best_foot = q;
            }
          }
        }
      }
    }
    if (foot) *foot = best_foot;
    return best;
  }

 private:
  int col(double x) const { return std::clamp(static_cast<int>(std::floor((x - lo_.x()) / cell_)), 0, nx_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>(std::floor((y - lo_.y()) / cell_)), 0, ny_ - 1); }
  int cell_of(const Point2& p) const { return row(p.y()) * nx_ + col(p.x()); }

  std::vector<Point2> points_;
  std::vector<int> vertex_of_, index_of_;
  std::vector<std::array<int, 2>> edges_;
  Point2 lo_{0, 0}, hi_{0, 0};
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<int> start_, items_;
};

/// The edges of a triangulation as compressed rows, each edge once per direction, with lengths:
/// built once per triangulation, graded many times.
struct EdgeGraph {
  std::vector<int> start, adj;
  std::vector<double> length;

  EdgeGraph(const std::vector<Point2>& points, const std::vector<std::array<int, 3>>& triangles) {
    // Every corner lists its two neighbours; interior edges come twice and are deduplicated per row.
    std::vector<int> count(points.size() + 1, 0), raw(6 * triangles.size());
    for (const auto& t : triangles)
      for (int v : t) count[static_cast<std::size_t>(v) + 1] += 2;
    for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
    std::vector<int> fill(count.begin(), count.end() - 1);
    for (const auto& t : triangles)
      for (int i = 0; i < 3; ++i) {
        const auto v = static_cast<std::size_t>(t[static_cast<std::size_t>(i)]);
        raw[static_cast<std::size_t>(fill[v]++)] = t[static_cast<std::size_t>((i + 1) % 3)];
        raw[static_cast<std::size_t>(fill[v]++)] = t[static_cast<std::size_t>((i + 2) % 3)];
      }
    start.assign(points.size() + 1, 0);
    adj.reserve(raw.size() / 2 + points.size());
    length.reserve(adj.capacity());
    for (std::size_t v = 0; v < points.size(); ++v) {
      const auto b = raw.begin() + count[v], e = raw.begin() + count[v + 1];
      std::sort(b, e);
      for (auto it = b; it != e; ++it) {
        if (it != b && *it == *(it - 1)) continue;
        adj.push_back(*it);
        length.push_back((points[static_cast<std::size_t>(*it)] - points[v]).norm());
      }
      start[v + 1] = static_cast<int>(adj.size());
    }
  }
};

/// Dijkstra from the smallest sizes: values[w] <= values[v] + slope |vw| along every edge.
void grade(const EdgeGraph& graph, std::vector<double>& values, double slope) {
  using Item = std::pair<double, int>;
  // The result is the min-plus closure of the values, so only vertices that lower a neighbour
  // need to start in the queue (the others enter when lowered): most samples and grid points don't.
  std::vector<Item> heap;
  for (std::size_t v = 0; v < values.size(); ++v)
    for (int k = graph.start[v]; k < graph.start[v + 1]; ++k)
      if (values[v] + slope * graph.length[static_cast<std::size_t>(k)] < values[static_cast<std::size_t>(graph.adj[static_cast<std::size_t>(k)])]) {
        heap.emplace_back(values[v], static_cast<int>(v));
        break;
      }
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue(std::greater<Item>(), std::move(heap));
  std::vector<char> done(values.size(), 0);
  while (!queue.empty()) {
    const auto [h, v] = queue.top();
    queue.pop();
    if (done[static_cast<std::size_t>(v)] || h > values[static_cast<std::size_t>(v)]) continue;
    done[static_cast<std::size_t>(v)] = 1;
    for (int k = graph.start[static_cast<std::size_t>(v)]; k < graph.start[static_cast<std::size_t>(v) + 1]; ++k) {
      const int w = graph.adj[static_cast<std::size_t>(k)];
      if (done[static_cast<std::size_t>(w)]) continue;
      const double hw = h + slope * graph.length[static_cast<std::size_t>(k)];
      if (hw < values[static_cast<std::size_t>(w)]) {
        values[static_cast<std::size_t>(w)] = hw;
        queue.emplace(hw, w);
      }
    }
  }
}

/// The field is linear between its background points, so a long Delaunay edge whose two ends are
/// both small (two tiny features closer than the background grid's step) keeps it small all along
/// (stress seed 35: 933,000 predicted vertices instead of 1,800). Such an edge gets points from
/// each end at the distances where the graded size doubles, plus its midpoint, and the sizes are
/// graded again; a round or two leave every edge's interpolant within a factor 2 of the graded
/// bound. The points are added to the samples once, as large sizes that the gradation brings down.
/// False (samples unchanged) when give_up(s) says a second round of s seconds is out of time.
bool add_grading_points(LfsSamples& samples, double gradation, double hmax, const std::function<bool(double)>& give_up) {
  const double slope = gradation - 1.0;
  if (!(slope > 0)) return true;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Point2> points;
  std::vector<double> values;
  for (std::size_t i = 0; i < samples.points.size(); ++i)
    if (samples.lfs[i] < inf) points.push_back(samples.points[i]), values.push_back(std::min(samples.lfs[i], hmax));
  const std::size_t n_samples = points.size();
  if (n_samples < 3) return true;
  constexpr int kRounds = 2;
  double last_round_s = 0;
  for (int round = 0; round < kRounds; ++round) {
    // give_up(s): whether a step of s seconds would outlast the time the caller has.
    if (round > 0 && give_up(last_round_s)) return false;
    const auto round_start = std::chrono::steady_clock::now();
    const auto triangles = delaunay_triangles(points);
    // A round is not cut short, but given up between its steps once the time is gone (the first
    // round on a 10,000-vertex polygon takes seconds: debug2 under a 2 s limit spent 2 s here).
    if (give_up(0)) return false;
    for (std::size_t i = n_samples; i < points.size(); ++i) values[i] = hmax;
    grade(EdgeGraph(points, triangles), values, slope);
    if (give_up(0)) return false;
    const std::size_t before = points.size();
    // Each edge once, hull edges included (they have one triangle, in either orientation).
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    edges.reserve(3 * triangles.size());
    for (const auto& t : triangles)
      for (int i = 0; i < 3; ++i) {
        const auto a = static_cast<std::size_t>(t[static_cast<std::size_t>(i)]), b = static_cast<std::size_t>(t[static_cast<std::size_t>((i + 1) % 3)]);
        edges.emplace_back(std::min(a, b), std::max(a, b));
      }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const auto& [v, w] : edges) {
      const double hv = values[v], hw = values[w];
      const Point2 pv = points[v], pw = points[w];
      const double half = 0.5 * (pw - pv).norm();
      if (0.5 * (hv + hw) >= 0.5 * std::min(hmax, std::min(hv, hw) + slope * half)) continue;
      const Point2 u = (pw - pv) / (2.0 * half);
      for (const auto& [from, dir, h0] : {std::tuple{pv, u, hv}, std::tuple{pw, Point2(-u), hw}})
        for (double r = h0 / slope; r < half && h0 + slope * r < hmax; r = 2.0 * r + h0 / slope) {
          points.push_back(from + r * dir);
          values.push_back(hmax);
        }
      points.push_back(pv + half * u);
      values.push_back(hmax);
    }
    if (points.size() == before) break;
    last_round_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - round_start).count();
  }
  for (std::size_t i = n_samples; i < points.size(); ++i) {
    samples.points.push_back(points[i]);
    samples.lfs.push_back(std::numeric_limits<double>::max());
  }
  return true;
}

/// How fast the size a tight wall forces falls off with the distance from it: the wall's triangles
/// need their size about as far as they reach, and beyond that the features' own sizes should win
/// (at the gradation slope, 0.3, a wall's size overrode a tiny segment a third of its edge away).
constexpr double kTightWallDecay = 1.0;
/// Graded fields from lfs samples: values clamp(lfs_factor * lfs, hmin, hmax) at the samples, hmax
/// on a grid at about hmax (the size can grow away from the features), then gradation-limited
/// along the Delaunay edges of those points. The triangulation depends only on the grid step, so
/// the fits of make_size_field (several factors or caps in a row) triangulate once per step.
class GradedFields {
 public:
  /// wide_factor: the largest lfs factor at the samples on wide corners (LfsSamples::wide_corners).
  GradedFields(const LfsSamples& samples, const DomainMeasures& dm, double gradation, double wide_factor, double scale)
      : dm_(dm), slope_(std::max(gradation - 1.0, 0.0)), wide_factor_(wide_factor), scale_(scale), tight_walls_(samples.tight_walls) {
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<std::array<double, 2>> wide;
    for (const Point2& p : samples.wide_corners) wide.push_back({p.x(), p.y()});
    std::sort(wide.begin(), wide.end());
    for (std::size_t i = 0; i < samples.points.size(); ++i) {
      const Point2& p = samples.points[i];
      lo_ = lo_.cwiseMin(p), hi_ = hi_.cwiseMax(p);
      if (!(samples.lfs[i] < inf)) continue;
      points_.push_back(p);
      lfs_.push_back(samples.lfs[i]);
      wide_.push_back(std::binary_search(wide.begin(), wide.end(), std::array<double, 2>{p.x(), p.y()}));
    }
  }

  void set_wide_factor(double wide_factor) { wide_factor_ = wide_factor; }

  /// The field times SizeFieldParams::scale, then raised beside every tight wall whose field asks
  /// for more edges along it than its capacity allows: along the wall to F(t) = gamma min(t, L - t) (t from its nearer end, gamma
  /// such that max(h, F) gives it capacity + 1 edges: the few Steiner points grade from where the
  /// field is fine, at its ends, instead of being spent there), and off it by F less
  /// kTightWallDecay times the distance.
  /// (The last step of a field: a scaling after it would shrink what the walls need.)
  SizeField finished(SizeField field, bool* changed = nullptr) const {
    if (changed) *changed = false;
    if (scale_ != 1.0) field.scale(scale_);
    if (tight_walls_.empty() || field.is_uniform()) return field;
    std::vector<double> values = field.background_values();
    const auto& points = field.background_points();
    std::vector<std::size_t> by_x;  // the background points in x order, once a wall needs them
    bool any = false;
    constexpr int kSamples = 64;  // per half of a wall, denser toward its end (t ~ k^4)
    std::vector<double> t, h;
    for (const auto& w : tight_walls_) {
      const double len = (w.b - w.a).norm();
      if (!(len > 0)) continue;
      const Point2 u = (w.b - w.a) / len;
      t.clear();
      for (int k = 0; k <= kSamples; ++k) t.push_back(0.5 * len * std::pow(static_cast<double>(k) / kSamples, 4));
      for (int k = kSamples - 1; k >= 0; --k) t.push_back(len - 0.5 * len * std::pow(static_cast<double>(k) / kSamples, 4));
      h.clear();
      for (std::size_t k = 0; k + 1 < t.size(); ++k) h.push_back(field(w.a + 0.5 * (t[k] + t[k + 1]) * u));
      auto edges = [&](double gamma) {
        double n = 0;
        for (std::size_t k = 0; k + 1 < t.size(); ++k) {
          const double mid = 0.5 * (t[k] + t[k + 1]);
          n += (t[k + 1] - t[k]) / std::max(h[k], gamma * std::min(mid, len - mid));
        }
        return n;
      };
      const double allowed = len / w.edge;  // capacity + 1
      if (edges(0) <= allowed) continue;
      double lo = 0, hi = 1;
      for (int k = 0; k < 200 && edges(hi) > allowed; ++k) hi *= 2;
      for (int k = 0; k < 60; ++k) {
        const double mid = lo > 0 ? std::sqrt(lo * hi) : 0.5 * hi;
        (edges(mid) > allowed ? lo : hi) = mid;
      }
      const double gamma = hi, reach = gamma * 0.5 * len / kTightWallDecay;
      const Point2 box_lo = w.a.cwiseMin(w.b) - Point2(reach, reach), box_hi = w.a.cwiseMax(w.b) + Point2(reach, reach);
      if (by_x.empty()) {
        by_x.resize(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) by_x[i] = i;
        std::sort(by_x.begin(), by_x.end(), [&](std::size_t i, std::size_t j) { return points[i].x() < points[j].x(); });
      }
      // Only the slab of the wall's reach in x: no pass over every point per wall.
      auto first = std::lower_bound(by_x.begin(), by_x.end(), box_lo.x(), [&](std::size_t i, double x) { return points[i].x() < x; });
      for (auto it = first; it != by_x.end() && points[*it].x() <= box_hi.x(); ++it) {
        const Point2& p = points[*it];
        if (p.y() < box_lo.y() || p.y() > box_hi.y()) continue;
        const double along = std::clamp((p - w.a).dot(u), 0.0, len);
        const double floor = gamma * std::min(along, len - along) - kTightWallDecay * (p - (w.a + along * u)).norm();
        if (floor > values[*it]) values[*it] = floor, any = true;
      }
    }
    if (!any) return field;
    if (changed) *changed = true;
    return field.with_values(std::move(values));
  }

  SizeField make(double lfs_factor, double hmin, double hmax) {
    // Fine enough that the size can grow between the features (values in between are linear).
    const double step = std::clamp(hmax, dm_.diameter / 200.0, dm_.diameter / 50.0);
    if (step != step_) triangulate(step);
    std::vector<double> values(background_.background_points().size(), hmax);
    for (std::size_t i = 0; i < lfs_.size(); ++i)
      values[i] = std::clamp((wide_[i] ? std::min(lfs_factor, wide_factor_) : lfs_factor) * lfs_[i], hmin, hmax);
    grade(*graph_, values, slope_);
    return background_.with_values(std::move(values));
  }

 private:
  void triangulate(double step) {
    std::vector<Point2> points = points_;
    const int nx = static_cast<int>(std::floor((hi_.x() - lo_.x()) / step)), ny = static_cast<int>(std::floor((hi_.y() - lo_.y()) / step));
    const double ox = lo_.x() + 0.5 * ((hi_.x() - lo_.x()) - nx * step), oy = lo_.y() + 0.5 * ((hi_.y() - lo_.y()) - ny * step);
    for (int j = 1; j < ny; ++j)
      for (int i = 1; i < nx; ++i) points.emplace_back(ox + i * step, oy + j * step);
    auto triangles = delaunay_triangles(points);
    std::vector<double> values(points.size(), 1.0);
    graph_ = std::make_unique<EdgeGraph>(points, triangles);
    background_ = SizeField::piecewise_linear(std::move(points), std::move(triangles), std::move(values));
    step_ = step;
  }

  DomainMeasures dm_;
  double slope_;
  Point2 lo_{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Point2 hi_{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  std::vector<Point2> points_;  ///< the samples with a finite lfs
  std::vector<double> lfs_;
  double wide_factor_;
  double scale_;
  std::vector<char> wide_;  ///< the sample is on a wide corner
  std::vector<LfsSamples::TightWall> tight_walls_;
  double step_ = -1;
  SizeField background_;  ///< samples + grid at step_, triangulated
  std::unique_ptr<EdgeGraph> graph_;  ///< background_'s edges
};

}  // namespace

/// Pieces that can carry fewer Steiner points than this are tight walls (LfsSamples::tight_walls).
constexpr std::uint64_t kTightWallCapacity = 1u << 20;

LfsSamples local_feature_size_samples(const Mesh& cdt, double spacing_cap) {
  if (!(spacing_cap > 0)) throw InvalidInput("size field: the lfs spacing cap must be positive");
  const FeatureGrid grid(cdt);
  LfsSamples out;
  const std::size_t nv = grid.num_points();
  std::vector<double> vertex_lfs(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    Point2 foot;
    vertex_lfs[i] = grid.nearest(grid.point(i), static_cast<int>(i), static_cast<int>(i), &foot);
    out.points.push_back(grid.point(i));
    out.lfs.push_back(vertex_lfs[i]);
    // The nearest point of that feature gets the same size (a vertex close to the middle of a
    // long segment makes the segment small there).
    if (foot != grid.point(i)) {
      out.points.push_back(foot);
      out.lfs.push_back(vertex_lfs[i]);
    }
  }
  for (const auto& e : grid.edges()) {
    const Point2 a = grid.point(static_cast<std::size_t>(e[0])), b = grid.point(static_cast<std::size_t>(e[1]));
    const double len = (b - a).norm();
    if (!(len > 0)) continue;
    if (const std::uint64_t capacity = chain_capacity(a, b); capacity < kTightWallCapacity)
      out.tight_walls.push_back({a, b, len / static_cast<double>(capacity + 1)});
    const Point2 u = (b - a) / len;
    // lfs is 1-Lipschitz: samples one lfs apart keep it within a factor 2 in between.
    // min_step bounds the samples of a long segment beside a long thin feature (16 per spacing);
    // a whole-segment floor (len / 16) missed a tiny hole 1/400 of a long wall away (seed 476).
    const double min_step = std::min(len, spacing_cap) / 16.0;
    auto step = [&](double d) { return std::max(std::min(d, spacing_cap), min_step); };
    const double end_step = step(vertex_lfs[static_cast<std::size_t>(e[1])]);
    for (double t = step(vertex_lfs[static_cast<std::size_t>(e[0])]); t < len - 0.5 * end_step;) {
      const Point2 x = a + t * u;
      const double d = grid.nearest(x, e[0], e[1]);
      out.points.push_back(x);
      out.lfs.push_back(d);
      t += step(d);
    }
  }
  // Narrow sectors: their two walls share the apex, so neither sees the other above.
  detail::append_strip_samples(cdt, out.points, out.lfs);
  constexpr double kWide = kWideCornerDeg * 3.14159265358979323846 / 180.0;
  for (auto vh : cdt.vertices()) {
    if (cdt.status(vh).deleted() || !is_input(cdt, vh)) continue;
    for (const SegmentSector& sector : segment_sectors(cdt, vh))
      if (sector.radians >= kWide) {
        out.wide_corners.push_back(point2(cdt, vh));
        break;
      }
  }
  // Samples at one point (a vertex's foot on another input vertex, beside that vertex's own
  // sample) keep the smallest value: the field's triangulation keeps one of them, and were it the
  // large one, a feature shorter than the spacing would vanish from the field.
  std::vector<std::pair<std::array<double, 2>, double>> merged;
  merged.reserve(out.points.size());
  for (std::size_t i = 0; i < out.points.size(); ++i) merged.push_back({{out.points[i].x(), out.points[i].y()}, out.lfs[i]});
  std::sort(merged.begin(), merged.end());  // by point, then by lfs: the first of a point is its smallest
  merged.erase(std::unique(merged.begin(), merged.end(), [](const auto& x, const auto& y) { return x.first == y.first; }), merged.end());
  out.points.clear();
  out.lfs.clear();
  for (const auto& [xy, lfs] : merged) out.points.emplace_back(xy[0], xy[1]), out.lfs.push_back(lfs);
  return out;
}

namespace {

/// Whether params.abandon_after_s has passed since start.
bool past_abandon_time(const SizeFieldParams& params, std::chrono::steady_clock::time_point start, double next_step_s = 0) {
  return params.abandon_after_s > 0 &&
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() + next_step_s > params.abandon_after_s;
}

/// The uniform field of a size field given up at its abandon time, flagged for the caller.
SizeField given_up(double h, bool* abandoned) {
  if (abandoned) *abandoned = true;
  return SizeField::uniform(h);
}

/// The graded fields of the input's local feature size up to hmax (local_feature_size_field's
/// samples and grading points, once for several factors); none when params.abandon_after_s passed.
std::optional<GradedFields> lfs_fields(const Mesh& cdt, const SizeFieldParams& params, const DomainMeasures& dm, double hmax) {
  const auto start = std::chrono::steady_clock::now();
  LfsSamples samples = local_feature_size_samples(cdt, hmax);
  if (past_abandon_time(params, start)) return std::nullopt;
  if (!add_grading_points(samples, params.gradation, hmax, [&](double next_s) { return past_abandon_time(params, start, next_s); }) ||
      past_abandon_time(params, start))
    return std::nullopt;
  return std::optional<GradedFields>(std::in_place, samples, dm, params.gradation, params.lfs_factor, params.scale);
}

double graded_hmax(const SizeFieldParams& params, const DomainMeasures& dm) {
  return params.hmax > 0 ? params.hmax : kDefaultMaxSizeRatio * dm.diameter;
}

double graded_hmin(const SizeFieldParams& params, const DomainMeasures& dm, double hmax) {
  return params.hmin > 0 ? std::min(params.hmin, hmax) : std::min(kMinSizeRatio * dm.diameter, hmax);
}

/// The graded field of the local feature size below hmax, its feature-bound sizes coarsened to
/// kCoarsestLfsFactor (wide corners keep the factor asked for) when at params.lfs_factor they would
/// need more than kMaxFeatureExcess times the vertices of a uniform hmax: the excess rule of a
/// count, against the largest size's count. Flags features_decide when it coarsened.
SizeField graded_below(const Mesh& cdt, const SizeFieldParams& params, const DomainMeasures& dm, double hmax, GradedFields& fields,
                       bool* features_decide) {
  const double hmin = graded_hmin(params, dm, hmax);
  SizeField f = fields.make(params.lfs_factor, hmin, hmax);
  if (!(params.lfs_factor < kCoarsestLfsFactor) || !(f.min_value() < hmax)) return f;
  const double uniform_count = predicted_vertex_count(cdt, SizeField::uniform(hmax));
  if (predicted_vertex_count(cdt, f) > kMaxFeatureExcess * uniform_count) {
    f = fields.make(kCoarsestLfsFactor, hmin, hmax);
    if (features_decide) *features_decide = true;
  }
  return f;
}

}  // namespace

SizeField local_feature_size_field(const Mesh& cdt, const SizeFieldParams& params, bool* abandoned) {
  const DomainMeasures dm = measure_domain(cdt);
  if (!(dm.diameter > 0)) throw InvalidInput("size field: the domain has no extent");
  const double hmax = graded_hmax(params, dm);
  auto fields = lfs_fields(cdt, params, dm, hmax);
  if (!fields) return given_up(hmax, abandoned);
  return fields->finished(fields->make(params.lfs_factor, graded_hmin(params, dm, hmax), hmax));
}

SizeField make_size_field(const Mesh& input_cdt, const SizeFieldParams& params, bool* abandoned, bool* features_decide, bool* held_back) {
  if (abandoned) *abandoned = false;
  if (features_decide) *features_decide = false;
  if (held_back) *held_back = false;
  if (params.size < 0 || !std::isfinite(params.size)) throw InvalidInput("size field: --size must be positive");
  if (!(params.scale > 0) || !std::isfinite(params.scale)) throw InvalidInput("size field: the scale must be positive");
  if (params.size > 0) {
    if (!params.graded) return SizeField::uniform(params.scale * params.size);
    // The size is the largest; where the features need finer, the graded field of the local
    // feature size (with the count path's excess rule against the uniform size's count).
    const DomainMeasures dm = measure_domain(input_cdt);
    if (!(dm.diameter > 0)) throw InvalidInput("size field: the domain has no extent");
    const double hmax = params.hmax > 0 ? std::min(params.hmax, params.size) : params.size;
    auto fields = lfs_fields(input_cdt, params, dm, hmax);
    if (!fields) return given_up(hmax, abandoned);
    bool raised = false;
    SizeField f = fields->finished(graded_below(input_cdt, params, dm, hmax, *fields, features_decide), &raised);
    if (!(f.min_value() < params.scale * params.size) && !raised) return SizeField::uniform(params.scale * params.size);  // nothing finer: the exact lattice
    return f;
  }
  if (params.target_vertices > 0) {
    const DomainMeasures dm = measure_domain(input_cdt);
    const double hn = size_for_vertex_count(dm, params.target_vertices);
    if (!params.graded) return SizeField::uniform(params.scale * hn);
    // The graded field with hmax = hn is <= hn everywhere, so it predicts >= N vertices; raise hmax
    // (never the lfs-bound values) until the count comes down to N, or to hmax = diameter.
    const auto start = std::chrono::steady_clock::now();
    auto out_of_time = [&] {
      return params.time_limit_s > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > params.time_limit_s;
    };
    const double target = static_cast<double>(params.max_vertices > 0 ? std::min(params.target_vertices, params.max_vertices) : params.target_vertices);
    const double hmin = graded_hmin(params, dm, hn);
    LfsSamples samples = local_feature_size_samples(input_cdt, hn);
    if (past_abandon_time(params, start)) return given_up(hn, abandoned);
    if (!add_grading_points(samples, params.gradation, hn, [&](double next_s) { return past_abandon_time(params, start, next_s); }) ||
        past_abandon_time(params, start))
      return given_up(hn, abandoned);
    GradedFields fields(samples, dm, params.gradation, params.lfs_factor, params.scale);
    auto field_at = [&](double hmax) { return fields.make(params.lfs_factor, hmin, hmax); };
    const double top = std::max(hn, dm.diameter);
    if (past_abandon_time(params, start)) return given_up(hn, abandoned);
    SizeField ft = field_at(top);
    if (past_abandon_time(params, start)) return given_up(hn, abandoned);
    const double at_top = predicted_vertex_count(input_cdt, ft);
    if (std::getenv("ACUTE_TRACE")) std::fprintf(stderr, "size field: lfs-bound count %.0f, target %.0f\n", at_top, target);
    if (at_top >= target) {
      // The features alone need more than N: keep h <= lfs (the count exceeds the target) unless
      // that is over kMaxFeatureExcess * N; then coarsen the lfs-bound sizes by a common factor
      // lambda (count ~ 1 / lambda^2 there: a few secant steps), up to kCoarsestLfsFactor unless
      // the count is held.
      double budget = params.max_vertices > 0 ? static_cast<double>(params.max_vertices) : INFINITY;
      double cap = std::min(kMaxFeatureExcess * target, budget);
      if (at_top <= cap) return fields.finished(ft);
      const double coarsest = std::max(params.lfs_factor, kCoarsestLfsFactor);
      bool stop_at_coarsest = true;  // once: past it the budget is the only cap
      const double held = params.hold_count ? std::max(kMaxFeatureExcess * target, params.held_count_at_least) : INFINITY;
      // Secant steps on log(count) against log(lambda): the exponent starts at the area's 2 and is
      // then measured (the boundary's 1 / lambda share and the hmin clamp make it smaller; debug2
      // at 2k vertices has 0.9, where assuming 2 left it 25% over after five steps).
      double lambda = params.lfs_factor, count = at_top, exponent = 2.0;
      // Not cut by the time share (the first fields are the finest), only given up with the start
      // once the abandon time has passed (debug2 at 2k vertices spent 26 s here under a 15 s share).
      for (int k = 0; k < 5 && std::abs(count / cap - 1.0) >= 0.1; ++k) {
        if (past_abandon_time(params, start)) return given_up(hn, abandoned);
        const double last_lambda = lambda, last_count = count;
        lambda *= std::pow(count / cap, 1.0 / exponent);
        if (stop_at_coarsest && lambda >= coarsest) {
          // The features decide the count from here, within the vertex budget.
          stop_at_coarsest = false;
          lambda = coarsest;
          ft = fields.make(lambda, hmin, top);
          count = predicted_vertex_count(input_cdt, ft);
          if (count <= std::min(budget, held)) {
            if (features_decide) *features_decide = true;
            return fields.finished(ft);
          }
          if (held < budget) {
            // A held count coarsens wide corners too (they would keep it far over the cap: debug2's
            // 10,000).
            budget = held;
            if (held_back) *held_back = true;
            fields.set_wide_factor(INFINITY);
            ft = fields.make(lambda, hmin, top);
            count = predicted_vertex_count(input_cdt, ft);
          }
          cap = budget;
          continue;
        }
        ft = fields.make(lambda, hmin, top);
        count = predicted_vertex_count(input_cdt, ft);
        if (count < last_count) exponent = std::clamp(std::log(last_count / count) / std::log(lambda / last_lambda), 0.5, 2.0);
      }
      return fields.finished(ft);
    }
    SizeField f = field_at(hn);
    double ratio = predicted_vertex_count(input_cdt, f) / target;
    if (ratio <= 1.02) {
      // At or below the target (the count model is not exact): refine uniformly, never coarsen
      // (the values at the features are the lfs).
      for (int k = 0; k < 8 && ratio < 0.99 && !out_of_time(); ++k) {
        f.scale(std::sqrt(ratio));
        ratio = predicted_vertex_count(input_cdt, f) / target;
      }
      return fields.finished(f);
    }
    double lo = hn, hi = top;  // count(lo) > target > count(hi)
    for (int k = 0; k < 30; ++k) {
      const double mid = std::sqrt(lo * hi);
      f = field_at(mid);
      ratio = predicted_vertex_count(input_cdt, f) / target;
      if (std::abs(ratio - 1.0) < 0.02 || hi / lo < 1.001) break;
      if (out_of_time()) {  // keep a field at or below the count
        if (ratio > 1.0) f = field_at(hi);
        break;
      }
      (ratio > 1.0 ? lo : hi) = mid;
    }
    return fields.finished(f);
  }
  // Neither: the graded field below the default largest size, with the same excess rule (debug2's
  // needles at the acute start's 0.7 asked for 3.1M vertices, 14 minutes; at 1.0, 1.9M).
  const DomainMeasures dm = measure_domain(input_cdt);
  if (!(dm.diameter > 0)) throw InvalidInput("size field: the domain has no extent");
  const double hmax = graded_hmax(params, dm);
  auto fields = lfs_fields(input_cdt, params, dm, hmax);
  if (!fields) return given_up(hmax, abandoned);
  return fields->finished(graded_below(input_cdt, params, dm, hmax, *fields, features_decide));
}

}  // namespace acute
