// Test support for the delaunay layer: an independent verifier of constrained Delaunay
// triangulations and small domain builders.
#pragma once

#include <acute/core/domain.h>
#include <acute/mesh/mesh.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace cdt_test {

using acute::Domain;
using acute::Mesh;
using acute::Point2;
using acute::Sign;
namespace pr = acute::predicates;

struct VerifyOptions {
  bool brute_force = false;        ///< O(F*V) empty-circumcircle check with visibility
  double expected_area = -1;       ///< compared with 1e-9 relative tolerance when >= 0
  bool all_points_required = false;
};

inline std::vector<std::array<int, 3>> faces_of(const Mesh& mesh) {
  std::vector<std::array<int, 3>> out;
  for (auto fh : mesh.faces()) {
    std::array<int, 3> f{};
    int k = 0;
    for (auto v : mesh.fv_range(fh)) f[static_cast<std::size_t>(k++)] = v.idx();
    out.push_back(f);
  }
  return out;
}

// Does the open segment pq cross the closed segment ab (a constrained edge) so as to block
// visibility? Touching at an endpoint of ab does not block.
inline bool blocks(const Point2& p, const Point2& q, const Point2& a, const Point2& b) {
  const auto k = pr::intersect_segments(p, q, a, b);
  if (k == pr::SegmentIntersection::Proper) return true;
  return false;
}

// A face around vertex v whose angle at v strictly contains the direction to q, or -1.
inline int face_entered(const Mesh& mesh, int v, const Point2& q) {
  const auto vh = Mesh::VertexHandle(v);
  const Point2 pv = acute::point2(mesh, vh);
  for (auto heh : mesh.voh_range(vh)) {
    const auto fh = mesh.face_handle(heh);
    if (!fh.is_valid()) continue;
    const Point2 x = acute::point2(mesh, mesh.to_vertex_handle(heh));
    const Point2 y = acute::point2(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(heh)));
    if (pr::orient2d(pv, x, q) == Sign::Positive && pr::orient2d(pv, y, q) == Sign::Negative) return fh.idx();
  }
  return -1;
}

/// Returns violations (empty when the mesh is a valid CDT of the domain).
inline std::vector<std::string> verify_cdt(const Mesh& mesh, const Domain& domain, const VerifyOptions& opt = {}) {
  std::vector<std::string> bad;
  auto report = [&](const std::string& s) {
    if (bad.size() < 20) bad.push_back(s);
  };
  // 1. Triangles strictly counter-clockwise, no duplicate positions.
  double area = 0;
  for (auto fh : mesh.faces()) {
    std::vector<Point2> p;
    for (auto v : mesh.fv_range(fh)) p.push_back(acute::point2(mesh, v));
    if (p.size() != 3) {
      report("face " + std::to_string(fh.idx()) + ": not a triangle");
      continue;
    }
    if (pr::orient2d(p[0], p[1], p[2]) != Sign::Positive) report("face " + std::to_string(fh.idx()) + ": not counter-clockwise");
    area += 0.5 * ((p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x());
  }
  {
    std::vector<std::pair<double, double>> pos;
    for (auto vh : mesh.vertices()) pos.emplace_back(mesh.point(vh)[0], mesh.point(vh)[1]);
    std::sort(pos.begin(), pos.end());
    if (std::adjacent_find(pos.begin(), pos.end()) != pos.end()) report("duplicate vertex positions");
  }
  // 2. Local constrained Delaunay property on every interior unconstrained edge.
  for (auto eh : mesh.edges()) {
    if (mesh.is_boundary(eh) || acute::is_constrained(mesh, eh)) continue;
    const auto h0 = mesh.halfedge_handle(eh, 0), h1 = mesh.halfedge_handle(eh, 1);
    const Point2 a = acute::point2(mesh, mesh.from_vertex_handle(h0));
    const Point2 b = acute::point2(mesh, mesh.to_vertex_handle(h0));
    const Point2 c = acute::point2(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h0)));
    const Point2 d = acute::point2(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h1)));
    if (pr::incircle(a, b, c, d) == Sign::Positive) report("edge " + std::to_string(eh.idx()) + ": unconstrained, not locally Delaunay");
  }
  // 3. Brute force: no vertex visible from a triangle's centroid lies strictly in its circumcircle.
  if (opt.brute_force) {
    std::vector<std::array<Point2, 2>> cons;
    for (auto eh : mesh.edges())
      if (acute::is_constrained(mesh, eh) || mesh.is_boundary(eh)) {
        const auto h = mesh.halfedge_handle(eh, 0);
        cons.push_back({acute::point2(mesh, mesh.from_vertex_handle(h)), acute::point2(mesh, mesh.to_vertex_handle(h))});
      }
    for (auto fh : mesh.faces()) {
      std::vector<Point2> p;
      for (auto v : mesh.fv_range(fh)) p.push_back(acute::point2(mesh, v));
      const Point2 g = (p[0] + p[1] + p[2]) / 3.0;
      for (auto vh : mesh.vertices()) {
        const Point2 q = acute::point2(mesh, vh);
        if (pr::incircle(p[0], p[1], p[2], q) != Sign::Positive) continue;
        bool hidden = false;
        for (const auto& s : cons)
          if (blocks(g, q, s[0], s[1])) {
            hidden = true;
            break;
          }
        if (!hidden) report("face " + std::to_string(fh.idx()) + ": vertex " + std::to_string(vh.idx()) + " visible inside its circumcircle");
      }
    }
  }
  // 4. Every segment with domain on some side is a chain of collinear edges.
  std::map<std::pair<double, double>, int> where;
  for (auto vh : mesh.vertices()) where[{mesh.point(vh)[0], mesh.point(vh)[1]}] = vh.idx();
  auto find_vertex = [&](const Point2& p) {
    auto it = where.find({p.x(), p.y()});
    return it == where.end() ? -1 : it->second;
  };
  std::set<int> ids_present;
  for (auto eh : mesh.edges())
    if (acute::is_constrained(mesh, eh)) ids_present.insert(mesh.data(eh).segment);
  for (std::size_t s = 0; s < domain.segments.size(); ++s) {
    const Point2 pa = domain.points[static_cast<std::size_t>(domain.segments[s][0])];
    const Point2 pb = domain.points[static_cast<std::size_t>(domain.segments[s][1])];
    if (pa == pb) continue;
    const int a = find_vertex(pa), b = find_vertex(pb);
    if (a < 0 || b < 0) {
      if (ids_present.count(static_cast<int>(s))) report("segment " + std::to_string(s) + ": endpoint missing but edges labelled");
      continue;  // dropped (outside the domain)
    }
    int cur = a;
    int steps = 0;
    bool ok = true;
    while (cur != b && ok) {
      int next = -1;
      const Point2 pc = acute::point2(mesh, Mesh::VertexHandle(cur));
      for (auto heh : mesh.voh_range(Mesh::VertexHandle(cur))) {
        const Point2 q = acute::point2(mesh, mesh.to_vertex_handle(heh));
        if (pr::locate_on_segment(q, pc, pb) == pr::SegmentLocation::Outside) continue;
        if (q == pc) continue;
        next = mesh.to_vertex_handle(heh).idx();
        if (!acute::is_constrained(mesh, mesh.edge_handle(heh)) && !mesh.is_boundary(mesh.edge_handle(heh)))
          report("segment " + std::to_string(s) + ": edge to vertex " + std::to_string(next) + " not constrained");
        break;
      }
      if (next < 0) {
        // Allowed only when the segment has no domain there (dropped): report if its id is used, or
        // if the segment leaves cur through the inside of a mesh triangle.
        if (ids_present.count(static_cast<int>(s)))
          report("segment " + std::to_string(s) + ": chain broken at vertex " + std::to_string(cur));
        else if (const int f = face_entered(mesh, cur, pb); f >= 0)
          report("segment " + std::to_string(s) + ": missing, leaves vertex " + std::to_string(cur) + " through face " + std::to_string(f));
        ok = false;
      }
      cur = next;
      if (++steps > 1000000) ok = false;
    }
  }
  // 5. Area and required points.
  if (opt.expected_area >= 0 && std::abs(area - opt.expected_area) > 1e-9 * std::max(1.0, std::abs(opt.expected_area)))
    report("area " + std::to_string(area) + " != expected " + std::to_string(opt.expected_area));
  if (opt.all_points_required)
    for (std::size_t i = 0; i < domain.points.size(); ++i)
      if (find_vertex(domain.points[i]) < 0) report("input point " + std::to_string(i) + " missing");
  return bad;
}

inline std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

// Builders.
inline Domain polygon(const std::vector<Point2>& pts, const std::string& name) {
  Domain d;
  d.name = name;
  d.points = pts;
  for (std::size_t i = 0; i < pts.size(); ++i) d.segments.push_back({static_cast<int>(i), static_cast<int>((i + 1) % pts.size())});
  return d;
}
inline void add_loop(Domain& d, const std::vector<Point2>& pts) {
  const int base = static_cast<int>(d.points.size());
  for (const auto& p : pts) d.points.push_back(p);
  for (std::size_t i = 0; i < pts.size(); ++i)
    d.segments.push_back({base + static_cast<int>(i), base + static_cast<int>((i + 1) % pts.size())});
}
inline std::vector<Point2> rect(double x0, double y0, double x1, double y1) {
  return {Point2(x0, y0), Point2(x1, y0), Point2(x1, y1), Point2(x0, y1)};
}

inline double polygon_area(const Domain& d, const std::vector<int>& loop) {
  double a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Point2& p = d.points[static_cast<std::size_t>(loop[i])];
    const Point2& q = d.points[static_cast<std::size_t>(loop[(i + 1) % loop.size()])];
    a += p.x() * q.y() - p.y() * q.x();
  }
  return 0.5 * a;
}

}  // namespace cdt_test
