// Independent check that a mesh is a valid triangulation conforming to its input domain, using
// only the mesh's geometry and the Domain (no segment ids or vertex kinds the mesher stored).
#pragma once

#include <acute/core/domain.h>
#include <acute/mesh/check.h>
#include <acute/mesh/mesh.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace acute::test {

/// Empty when `mesh` is valid (check_mesh, Geometry level), keeps every input point as a vertex
/// (exact coordinates), every boundary edge lies on an input segment and every input segment is
/// covered by mesh edges (lengths summed; Steiner points on slanted segments may be off the exact
/// line by rounding, hence the relative tolerance `tol` on the domain's size), and its area is
/// `area` (relative 1e-9). Else the first problem.
inline std::string verify_conforms(const Mesh& mesh, const Domain& domain, double area, double tol = 1e-10) {
  const CheckReport report = check_mesh(mesh, CheckLevel::Geometry);
  if (!report.ok()) return "invalid: " + report.summary(2);
  if (mesh.n_faces() == 0) return "no triangles";

  double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  for (const auto& p : domain.points) lo_x = std::min(lo_x, p.x()), lo_y = std::min(lo_y, p.y()), hi_x = std::max(hi_x, p.x()), hi_y = std::max(hi_y, p.y());
  const double eps = tol * std::max(hi_x - lo_x, hi_y - lo_y);

  std::set<std::pair<double, double>> vertices;
  for (auto vh : mesh.vertices()) vertices.insert({mesh.point(vh)[0], mesh.point(vh)[1]});
  for (std::size_t i = 0; i < domain.points.size(); ++i)
    if (!vertices.count({domain.points[i].x(), domain.points[i].y()})) return "input point " + std::to_string(i) + " is not a vertex";

  auto on_segment = [&](const Point2& p, std::size_t s) {
    const Point2& a = domain.points[static_cast<std::size_t>(domain.segments[s][0])];
    const Point2& b = domain.points[static_cast<std::size_t>(domain.segments[s][1])];
    const Point2 d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * d)).norm() <= eps;
  };
  std::vector<double> covered(domain.segments.size(), 0.0);
  for (auto eh : mesh.edges()) {
    const auto h = mesh.halfedge_handle(eh, 0);
    const Point2 p = point2(mesh, mesh.from_vertex_handle(h)), q = point2(mesh, mesh.to_vertex_handle(h));
    bool on_any = false;
    for (std::size_t s = 0; s < domain.segments.size(); ++s)
      if (on_segment(p, s) && on_segment(q, s)) covered[s] += (q - p).norm(), on_any = true;
    if (mesh.is_boundary(eh) && !on_any)
      return "boundary edge (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")-(" + std::to_string(q.x()) + ", " +
             std::to_string(q.y()) + ") on no input segment";
  }
  for (std::size_t s = 0; s < domain.segments.size(); ++s) {
    const double len = (domain.points[static_cast<std::size_t>(domain.segments[s][1])] - domain.points[static_cast<std::size_t>(domain.segments[s][0])]).norm();
    if (std::abs(covered[s] - len) > 1e-9 * len) return "segment " + std::to_string(s) + " covered over " + std::to_string(covered[s]) + " of " + std::to_string(len);
  }

  double mesh_area = 0;
  for (auto fh : mesh.faces()) {
    Point2 p[3];
    int k = 0;
    for (auto vh : mesh.fv_range(fh)) p[k++] = point2(mesh, vh);
    mesh_area += 0.5 * ((p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x());
  }
  if (std::abs(mesh_area - area) > 1e-9 * area) return "area " + std::to_string(mesh_area) + " instead of " + std::to_string(area);
  return {};
}

inline std::string point_text(const Point2& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x(), p.y());
  return buf;
}

/// Empty when every input segment ab is read back from the mesh as the referee reads it
/// (shared/tools/meshcheck --tolerance tol): a chain of mesh edges from a to b whose vertices each
/// lie within tol * |ab| of the line ab (exact distance, rounded once), inside the bounding box
/// of ab, and advance strictly toward
/// b in x (in y when a.x == b.x) without passing it. Else the first segment that is not.
inline std::string verify_segment_chains(const Mesh& mesh, const Domain& domain, double tol = 1e-10) {
  std::map<std::pair<double, double>, VertexHandle> at;
  for (auto vh : mesh.vertices()) at[{mesh.point(vh)[0], mesh.point(vh)[1]}] = vh;
  for (std::size_t s = 0; s < domain.segments.size(); ++s) {
    const Point2& a = domain.points[static_cast<std::size_t>(domain.segments[s][0])];
    const Point2& b = domain.points[static_cast<std::size_t>(domain.segments[s][1])];
    const auto ia = at.find({a.x(), a.y()}), ib = at.find({b.x(), b.y()});
    if (ia == at.end() || ib == at.end()) return "segment " + std::to_string(s) + ": an endpoint is not a vertex";
    const int axis = a.x() != b.x() ? 0 : 1;
    const bool up = b[axis] > a[axis];
    const double l2 = (b - a).squaredNorm();
    VertexHandle cur = ia->second;
    for (std::size_t steps = 0; cur != ib->second; ++steps) {
      const double c = point2(mesh, cur)[axis];
      VertexHandle next;
      double next_c = 0;
      for (auto w : mesh.vv_range(cur)) {
        const Point2 p = point2(mesh, w);
        const double v = p[axis];
        if (up ? !(c < v && v <= b[axis]) : !(b[axis] <= v && v < c)) continue;
        const int other = 1 - axis;  // and within the segment's extent (not on its line beyond it)
        if (p[other] < std::min(a[other], b[other]) || p[other] > std::max(a[other], b[other])) continue;
        if (std::fabs(predicates::orient2d_value(a, b, p)) / l2 > tol) continue;
        if (!next.is_valid() || (up ? v < next_c : v > next_c)) next = w, next_c = v;
      }
      if (!next.is_valid() || steps > mesh.n_vertices())
        return "segment " + std::to_string(s) + " " + point_text(a) + "-" + point_text(b) + ": no mesh edge continues along it from " +
               point_text(point2(mesh, cur));
      cur = next;
    }
  }
  return {};
}

}  // namespace acute::test
