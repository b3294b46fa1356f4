#include "cvt/site_delaunay.h"

#include <acute/core/errors.h>
#include <acute/delaunay/cdt.h>
#include <acute/predicates/predicates.h>

#include "delaunay/triangulation.h"

#include <algorithm>
#include <cstdint>

namespace acute::detail {

void SiteDelaunay::update(const std::vector<Point2>& points, bool same_sites, const Seed* seed) {
  const bool repairable = same_sites && points.size() == n_sites_ && !tri_.empty();
  n_sites_ = points.size();
  if (repairable) {
    std::copy(points.begin(), points.end(), points_.begin());  // the frame stays where it was
  } else {
    points_ = points;
    // The frame: four points far outside the sites' bounding box.
    Point2 lo = points.empty() ? Point2(0, 0) : points.front(), hi = lo;
    for (const Point2& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const Point2 c = 0.5 * (lo + hi);
    const double r = 8.0 * std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1e-300});
    for (const Point2& corner : {Point2(-r, -r), Point2(r, -r), Point2(r, r), Point2(-r, r)}) points_.push_back(c + corner);
  }
  if (repairable && all_counter_clockwise()) {
    lawson();
  } else if (!repairable && seed && build_from_seed(*seed)) {
    ++rebuilds_;
    ++seeded_;
    lawson();
  } else {
    rebuild();
  }
  build_adjacency();
}

bool SiteDelaunay::all_counter_clockwise() const {
  for (const auto& t : tri_)
    if (predicates::orient2d(points_[static_cast<std::size_t>(t[0])], points_[static_cast<std::size_t>(t[1])],
                             points_[static_cast<std::size_t>(t[2])]) != Sign::Positive)
      return false;
  return true;
}

void SiteDelaunay::rebuild() {
  ++rebuilds_;
  tri_ = delaunay_triangles(points_);
  link_neighbours();
}

bool SiteDelaunay::build_from_seed(const Seed& seed) {
  const auto n = static_cast<int>(n_sites_);
  // The border's points and the frame, triangulated with the border as constraints.
  border_local_.assign(n_sites_, -1);
  std::vector<Point2> pts;
  std::vector<int> site_of;
  for (const auto& e : seed.border)
    for (int v : e) {
      if (v < 0 || v >= n) return false;
      int& l = border_local_[static_cast<std::size_t>(v)];
      if (l >= 0) continue;
      l = static_cast<int>(pts.size());
      pts.push_back(points_[static_cast<std::size_t>(v)]);
      site_of.push_back(v);
    }
  for (int k = 0; k < 4; ++k) {
    pts.push_back(points_[n_sites_ + static_cast<std::size_t>(k)]);
    site_of.push_back(n + k);
  }
  Triangulation tr(pts);
  if (!tr.insert_points(brio_hilbert_order(pts))) return false;
  for (int i = 0; i < tr.num_vertices(); ++i)
    if (tr.rep(i) != i) return false;
  std::vector<std::uint64_t> inside_edges;
  inside_edges.reserve(seed.border.size());
  auto key = [](int a, int b) { return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b); };
  try {
    for (const auto& e : seed.border) {
      const int a = border_local_[static_cast<std::size_t>(e[0])], b = border_local_[static_cast<std::size_t>(e[1])];
      if (a == b) return false;
      tr.insert_segment(a, b, 0);
      inside_edges.push_back(key(a, b));
    }
  } catch (const InvalidInput&) {
    return false;  // border edges that cross: not a region's border
  }
  if (tr.points_on_segments > 0) return false;
  std::sort(inside_edges.begin(), inside_edges.end());
  // Each triangle is inside the part (on the left of a border edge) or outside it (the frame's ring
  // and the part's holes): floods from both kinds of border triangles across unconstrained edges
  // must label every triangle, and never one twice.
  std::vector<signed char> label(static_cast<std::size_t>(tr.num_slots()), 0);
  std::vector<int> stack;
  for (int t = 0; t < tr.num_slots(); ++t) {
    if (!tr.alive(t)) continue;
    signed char want = tr.is_ghost(t) ? 2 : 0;
    for (int i = 0; i < 3 && !tr.is_ghost(t); ++i) {
      if (tr.segment(t, i) < 0) continue;
      const auto& v = tr.tri(t).v;
      const signed char side = std::binary_search(inside_edges.begin(), inside_edges.end(), key(v[(i + 1) % 3], v[(i + 2) % 3])) ? 1 : 2;
      if (want != 0 && want != side) return false;
      want = side;
    }
    if (want == 0) continue;
    if (label[static_cast<std::size_t>(t)] != 0 && label[static_cast<std::size_t>(t)] != want) return false;
    if (label[static_cast<std::size_t>(t)] == want) continue;
    label[static_cast<std::size_t>(t)] = want;
    stack.push_back(t);
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        if (tr.segment(u, i) >= 0) continue;
        const int w = tr.tri(u).n[i];
        if (w < 0) continue;
        signed char& lw = label[static_cast<std::size_t>(w)];
        if (lw == want) continue;
        if (lw != 0) return false;
        lw = want;
        stack.push_back(w);
      }
    }
  }
  tri_ = seed.triangles;
  for (int t = 0; t < tr.num_slots(); ++t) {
    if (!tr.alive(t) || tr.is_ghost(t)) continue;
    if (label[static_cast<std::size_t>(t)] == 0) return false;
    if (label[static_cast<std::size_t>(t)] == 2) {
      const auto& v = tr.tri(t).v;
      tri_.push_back({site_of[static_cast<std::size_t>(v[0])], site_of[static_cast<std::size_t>(v[1])], site_of[static_cast<std::size_t>(v[2])]});
    }
  }
  // A triangulation of the frame's square by counter-clockwise triangles, each edge shared by two
  // of them but the square's four, over every site: 2 V - 6 triangles (Euler, four hull vertices).
  if (tri_.size() != 2 * points_.size() - 6) return false;
  for (const auto& t : tri_)
    for (int v : t)
      if (v < 0 || static_cast<std::size_t>(v) >= points_.size()) return false;
  if (!all_counter_clockwise()) return false;
  link_neighbours();
  std::size_t open = 0;
  for (std::size_t t = 0; t < tri_.size(); ++t)
    for (int u : nbr_[t]) {
      if (u < 0) {
        ++open;
        continue;
      }
      const auto& back = nbr_[static_cast<std::size_t>(u)];
      if (back[0] != static_cast<int>(t) && back[1] != static_cast<int>(t) && back[2] != static_cast<int>(t)) return false;  // an edge of three triangles
    }
  return open == 4;
}

void SiteDelaunay::link_neighbours() {
  const std::size_t n = points_.size();
  // Triangles around each vertex (CSR), then each edge's twin among the triangles of its head.
  incident_start_.assign(n + 1, 0);
  for (const auto& t : tri_)
    for (int v : t) ++incident_start_[static_cast<std::size_t>(v) + 1];
  for (std::size_t i = 0; i < n; ++i) incident_start_[i + 1] += incident_start_[i];
  incident_.resize(3 * tri_.size());
  {
    std::vector<int>& fill = start_;  // reused as a cursor; rebuilt by build_adjacency
    fill.assign(incident_start_.begin(), incident_start_.end() - 1);
    for (std::size_t t = 0; t < tri_.size(); ++t)
      for (int v : tri_[t]) incident_[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = static_cast<int>(t);
  }
  nbr_.assign(tri_.size(), {-1, -1, -1});
  for (std::size_t t = 0; t < tri_.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = tri_[t][static_cast<std::size_t>((i + 1) % 3)], b = tri_[t][static_cast<std::size_t>((i + 2) % 3)];
      // The twin holds b -> a: it is among the triangles of both ends, so the shorter list is
      // searched (a frame vertex has every hull site as a neighbour: a long straight wall's
      // hundred thousand sites made the longer list's scans quadratic).
      const auto deg = [&](int v) { return incident_start_[static_cast<std::size_t>(v) + 1] - incident_start_[static_cast<std::size_t>(v)]; };
      const int via = deg(a) < deg(b) ? a : b;
      for (int k = incident_start_[static_cast<std::size_t>(via)]; k < incident_start_[static_cast<std::size_t>(via) + 1]; ++k) {
        const int u = incident_[static_cast<std::size_t>(k)];
        const auto& tu = tri_[static_cast<std::size_t>(u)];
        int j = 0;
        while (tu[static_cast<std::size_t>(j)] != b) {
          if (++j == 3) break;  // (searching a's list: u need not hold b)
        }
        if (j < 3 && tu[static_cast<std::size_t>((j + 1) % 3)] == a) {
          nbr_[t][static_cast<std::size_t>(i)] = u;
          break;
        }
      }
    }
}

void SiteDelaunay::lawson() {
  stack_.clear();
  for (std::size_t t = 0; t < tri_.size(); ++t)
    for (int i = 0; i < 3; ++i)
      if (nbr_[t][static_cast<std::size_t>(i)] > static_cast<int>(t)) stack_.emplace_back(static_cast<int>(t), i);
  while (!stack_.empty()) {
    const auto [t, i] = stack_.back();
    stack_.pop_back();
    const int u = nbr_[static_cast<std::size_t>(t)][static_cast<std::size_t>(i)];
    if (u < 0) continue;
    const auto& tt = tri_[static_cast<std::size_t>(t)];
    const int c = tt[static_cast<std::size_t>(i)], a = tt[static_cast<std::size_t>((i + 1) % 3)], b = tt[static_cast<std::size_t>((i + 2) % 3)];
    const auto& tu = tri_[static_cast<std::size_t>(u)];
    int j = 0;
    while (tu[static_cast<std::size_t>(j)] == a || tu[static_cast<std::size_t>(j)] == b) ++j;
    const int d = tu[static_cast<std::size_t>(j)];
    // A valid triangulation's non-locally-Delaunay edge has a strictly convex quadrilateral, so
    // the flip keeps every triangle counter-clockwise.
    if (predicates::incircle(points_[static_cast<std::size_t>(c)], points_[static_cast<std::size_t>(a)],
                             points_[static_cast<std::size_t>(b)], points_[static_cast<std::size_t>(d)]) == Sign::Positive)
      flip(t, i);
  }
}

void SiteDelaunay::flip(int t, int i) {
  // t = (c, a, b) with edge ab opposite c shared with u = (d, b, a). After: t = (c, a, d), u = (d, b, c).
  const auto ts = static_cast<std::size_t>(t);
  const int u = nbr_[ts][static_cast<std::size_t>(i)];
  const auto us = static_cast<std::size_t>(u);
  const int c = tri_[ts][static_cast<std::size_t>(i)], a = tri_[ts][static_cast<std::size_t>((i + 1) % 3)],
            b = tri_[ts][static_cast<std::size_t>((i + 2) % 3)];
  const int t_bc = nbr_[ts][static_cast<std::size_t>((i + 1) % 3)], t_ca = nbr_[ts][static_cast<std::size_t>((i + 2) % 3)];
  int j = 0;
  while (tri_[us][static_cast<std::size_t>(j)] == a || tri_[us][static_cast<std::size_t>(j)] == b) ++j;
  const int d = tri_[us][static_cast<std::size_t>(j)];
  // In u = (d, b, a) from corner j: the edge opposite b is ad, the one opposite a is db.
  const int u_ad = nbr_[us][static_cast<std::size_t>((j + 1) % 3)], u_db = nbr_[us][static_cast<std::size_t>((j + 2) % 3)];
  tri_[ts] = {c, a, d};
  nbr_[ts] = {u_ad, u, t_ca};
  tri_[us] = {d, b, c};
  nbr_[us] = {t_bc, t, u_db};
  auto repoint = [&](int x, int from, int to) {
    if (x < 0) return;
    for (int& y : nbr_[static_cast<std::size_t>(x)])
      if (y == from) y = to;
  };
  repoint(t_bc, t, u);
  repoint(u_ad, u, t);
  ++flips_;
  stack_.emplace_back(t, 0);
  stack_.emplace_back(t, 2);
  stack_.emplace_back(u, 0);
  stack_.emplace_back(u, 2);
}

void SiteDelaunay::build_adjacency() {
  const std::size_t n = n_sites_;
  const auto site = [&](int v) { return static_cast<std::size_t>(v) < n; };
  start_.assign(n + 1, 0);
  // Every directed edge a -> b of a triangle gives b to a (the frame's triangles close the hull,
  // so every edge between sites has both directions); the frame is nobody's neighbour.
  for (std::size_t t = 0; t < tri_.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = tri_[t][static_cast<std::size_t>((i + 1) % 3)], b = tri_[t][static_cast<std::size_t>((i + 2) % 3)];
      if (site(a) && site(b)) ++start_[static_cast<std::size_t>(a) + 1];
    }
  for (std::size_t i = 0; i < n; ++i) start_[i + 1] += start_[i];
  adjacent_.resize(static_cast<std::size_t>(start_[n]));
  vertex_tri_.assign(n, -1);
  for (std::size_t t = 0; t < tri_.size(); ++t)
    for (int v : tri_[t])
      if (site(v)) vertex_tri_[static_cast<std::size_t>(v)] = static_cast<int>(t);
  incident_start_.assign(start_.begin(), start_.end() - 1);  // fill cursor
  for (std::size_t t = 0; t < tri_.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = tri_[t][static_cast<std::size_t>((i + 1) % 3)], b = tri_[t][static_cast<std::size_t>((i + 2) % 3)];
      if (site(a) && site(b)) adjacent_[static_cast<std::size_t>(incident_start_[static_cast<std::size_t>(a)]++)] = b;
    }
}

}  // namespace acute::detail
