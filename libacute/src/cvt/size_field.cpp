#include <acute/cvt/size_field.h>

#include <acute/core/errors.h>
#include <acute/delaunay/cdt.h>
#include <acute/mesh/geometry.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
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

double SizeField::eval(const Point2& p, int& hint) const {
  if (is_uniform()) return uniform_;
  hint = walk(p, hint);
  const auto& tri = triangles_[static_cast<std::size_t>(hint)];
  const Point2& a = points_[static_cast<std::size_t>(tri[0])];
  const Point2& b = points_[static_cast<std::size_t>(tri[1])];
  const Point2& c = points_[static_cast<std::size_t>(tri[2])];
  const double det = signed_area2(a, b, c);
  double l0 = signed_area2(p, b, c) / det, l1 = signed_area2(a, p, c) / det, l2 = signed_area2(a, b, p) / det;
  l0 = std::max(l0, 0.0), l1 = std::max(l1, 0.0), l2 = std::max(l2, 0.0);
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

/// Distance from p to segment ab and the foot point.
double segment_distance(const Point2& p, const Point2& a, const Point2& b, Point2& foot) {
  const Point2 d = b - a;
  const double l2 = d.squaredNorm();
  double t = l2 > 0 ? (p - a).dot(d) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  foot = a + t * d;
  return (p - foot).norm();
}

}  // namespace

SizeField local_feature_size_field(const Mesh& cdt, const SizeFieldParams& params) {
  const DomainMeasures dm = measure_domain(cdt);
  if (!(dm.diameter > 0)) throw InvalidInput("size field: the domain has no extent");
  const double hmax = params.hmax > 0 ? params.hmax : dm.diameter / 25.0;
  const double hmin = params.hmin > 0 ? std::min(params.hmin, hmax) : std::min(1e-6 * dm.diameter, hmax);
  const double slope = std::max(params.gradation - 1.0, 0.0);
  const double inf = std::numeric_limits<double>::infinity();

  std::vector<Point2> points;
  std::vector<double> values;
  // Input points: the nearest other point among the neighbours, the nearest constrained edge opposite
  // in the star (its foot becomes a background point too, so the segment gets the small size).
  for (auto vh : cdt.vertices()) {
    const Point2 p = point2(cdt, vh);
    double lfs = inf;
    for (auto w : cdt.vv_range(vh)) lfs = std::min(lfs, (point2(cdt, w) - p).norm());
    Point2 best_foot(0, 0);
    bool has_foot = false;
    for (auto heh : cdt.voh_range(vh)) {
      if (cdt.is_boundary(heh)) continue;
      const auto opp = cdt.next_halfedge_handle(heh);
      if (!is_constrained(cdt, cdt.edge_handle(opp))) continue;
      Point2 foot;
      const double d = segment_distance(p, point2(cdt, cdt.from_vertex_handle(opp)), point2(cdt, cdt.to_vertex_handle(opp)), foot);
      if (d < lfs) lfs = d, best_foot = foot, has_foot = true;
    }
    if (!(lfs < inf)) continue;  // isolated
    const double h = std::clamp(params.lfs_factor * lfs, hmin, hmax);
    points.push_back(p);
    values.push_back(h);
    if (has_foot) {
      points.push_back(best_foot);
      values.push_back(h);
    }
  }
  // A coarse grid at hmax lets the size grow away from the features.
  {
    double xmin = inf, ymin = inf, xmax = -inf, ymax = -inf;
    for (const Point2& p : points) xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x()), ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
    const double step = std::max(hmax, dm.diameter / 200.0);
    const int nx = static_cast<int>(std::floor((xmax - xmin) / step)), ny = static_cast<int>(std::floor((ymax - ymin) / step));
    const double ox = xmin + 0.5 * ((xmax - xmin) - nx * step), oy = ymin + 0.5 * ((ymax - ymin) - ny * step);
    for (int j = 1; j < ny; ++j)
      for (int i = 1; i < nx; ++i) {
        points.emplace_back(ox + i * step, oy + j * step);
        values.push_back(hmax);
      }
  }
  auto triangles = delaunay_triangles(points);
  // Gradation: h_w <= h_v + slope |vw| along the Delaunay edges (Dijkstra from the smallest sizes).
  std::vector<std::vector<int>> adj(points.size());
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i) adj[static_cast<std::size_t>(t[static_cast<std::size_t>(i)])].push_back(t[static_cast<std::size_t>((i + 1) % 3)]),
          adj[static_cast<std::size_t>(t[static_cast<std::size_t>((i + 1) % 3)])].push_back(t[static_cast<std::size_t>(i)]);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (std::size_t i = 0; i < points.size(); ++i) queue.emplace(values[i], static_cast<int>(i));
  std::vector<char> done(points.size(), 0);
  while (!queue.empty()) {
    const auto [h, v] = queue.top();
    queue.pop();
    if (done[static_cast<std::size_t>(v)] || h > values[static_cast<std::size_t>(v)]) continue;
    done[static_cast<std::size_t>(v)] = 1;
    for (int w : adj[static_cast<std::size_t>(v)]) {
      const double hw = h + slope * (points[static_cast<std::size_t>(w)] - points[static_cast<std::size_t>(v)]).norm();
      if (hw < values[static_cast<std::size_t>(w)]) {
        values[static_cast<std::size_t>(w)] = hw;
        queue.emplace(hw, w);
      }
    }
  }
  return SizeField::piecewise_linear(std::move(points), std::move(triangles), std::move(values));
}

SizeField make_size_field(const Mesh& input_cdt, const SizeFieldParams& params) {
  if (params.size < 0 || !std::isfinite(params.size)) throw InvalidInput("size field: --size must be positive");
  if (params.size > 0) return SizeField::uniform(params.size);
  if (params.target_vertices > 0) {
    const double h = size_for_vertex_count(measure_domain(input_cdt), params.target_vertices);
    if (!params.graded) return SizeField::uniform(h);
    SizeFieldParams p = params;
    p.hmax = h;
    SizeField f = local_feature_size_field(input_cdt, p);
    const double target = static_cast<double>(params.target_vertices);
    for (int k = 0; k < 8; ++k) {
      const double ratio = predicted_vertex_count(input_cdt, f) / target;
      if (std::abs(ratio - 1.0) < 0.01) break;
      f.scale(std::sqrt(ratio));
    }
    return f;
  }
  return local_feature_size_field(input_cdt, params);
}

}  // namespace acute
