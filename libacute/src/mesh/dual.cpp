#include <acute/mesh/dual.h>

#include <acute/mesh/geometry.h>
#include <acute/mesh/quality.h>
#include <acute/predicates/predicates.h>

namespace acute {

namespace {

// Dual points created on first use, so cells share them.
class DualBuilder {
 public:
  DualBuilder(const Mesh& mesh, DualMesh& dual)
      : mesh_(mesh), dual_(dual),
        face_point_(mesh.n_faces(), -1), edge_point_(mesh.n_edges(), -1), vertex_point_(mesh.n_vertices(), -1) {}

  int circumcenter_of(FaceHandle fh) {
    int& id = face_point_[fh.idx()];
    if (id < 0) {
      const auto p = face_points(mesh_, fh);
      id = add(circumcenter(p[0], p[1], p[2]), DualPointKind::Circumcenter, fh.idx());
    }
    return id;
  }
  int midpoint_of(EdgeHandle eh) {
    int& id = edge_point_[eh.idx()];
    if (id < 0) {
      const auto h = mesh_.halfedge_handle(eh, 0);
      const Point2 a = point2(mesh_, mesh_.from_vertex_handle(h)), b = point2(mesh_, mesh_.to_vertex_handle(h));
      id = add(0.5 * (a + b), DualPointKind::EdgeMidpoint, eh.idx());
    }
    return id;
  }
  int vertex_of(VertexHandle vh) {
    int& id = vertex_point_[vh.idx()];
    if (id < 0) id = add(point2(mesh_, vh), DualPointKind::PrimalVertex, vh.idx());
    return id;
  }

 private:
  int add(const Point2& p, DualPointKind kind, int source) {
    dual_.points.push_back(p);
    dual_.point_kinds.push_back(kind);
    dual_.point_sources.push_back(source);
    return static_cast<int>(dual_.points.size() - 1);
  }

  const Mesh& mesh_;
  DualMesh& dual_;
  std::vector<int> face_point_, edge_point_, vertex_point_;
};

}  // namespace

DualMesh circumcentric_dual(const Mesh& mesh) {
  DualMesh dual;
  DualBuilder build(mesh, dual);
  // Turning counter-clockwise around v: from the outgoing halfedge h (face on its left) to the
  // outgoing halfedge on the other side of that face.
  auto ccw = [&](HalfedgeHandle h) { return mesh.opposite_halfedge_handle(mesh.prev_halfedge_handle(h)); };
  auto add_cell = [&](VertexHandle vh, std::vector<int> cell, bool boundary) {
    dual.cells.push_back(std::move(cell));
    dual.cell_vertex.push_back(vh.idx());
    dual.cell_on_boundary.push_back(boundary ? 1 : 0);
  };
  for (auto vh : mesh.vertices()) {
    if (mesh.is_isolated(vh)) continue;
    bool boundary = false;
    // One cell per fan: each fan starts at an outgoing halfedge with a face whose clockwise
    // neighbour is the boundary.
    for (auto h0 : mesh.voh_range(vh)) {
      if (mesh.is_boundary(h0) || !mesh.is_boundary(mesh.opposite_halfedge_handle(h0))) continue;
      boundary = true;
      std::vector<int> cell{build.vertex_of(vh), build.midpoint_of(mesh.edge_handle(h0))};
      HalfedgeHandle h = h0;
      while (!mesh.is_boundary(h)) {
        cell.push_back(build.circumcenter_of(mesh.face_handle(h)));
        h = ccw(h);
      }
      cell.push_back(build.midpoint_of(mesh.edge_handle(h)));
      add_cell(vh, std::move(cell), true);
    }
    if (boundary) continue;
    std::vector<int> cell;
    const HalfedgeHandle h0 = mesh.halfedge_handle(vh);
    HalfedgeHandle h = h0;
    do {
      cell.push_back(build.circumcenter_of(mesh.face_handle(h)));
      h = ccw(h);
    } while (h != h0);
    add_cell(vh, std::move(cell), false);
  }
  return dual;
}

double cell_area(const DualMesh& dual, std::size_t cell) {
  const auto& c = dual.cells.at(cell);
  if (c.size() < 3) return 0.0;
  // Relative to the first point, for accuracy far from the origin.
  const Point2 o = dual.points[c[0]];
  double twice = 0;
  for (std::size_t i = 1; i + 1 < c.size(); ++i) {
    const Point2 a = dual.points[c[i]] - o, b = dual.points[c[i + 1]] - o;
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

DualCheck check_well_centered(const Mesh& mesh, std::size_t max_reported) {
  DualCheck check;
  for (auto fh : mesh.faces()) {
    ++check.n_faces;
    const auto p = face_points(mesh, fh);
    int corner = -1;
    AngleKind kind = AngleKind::Acute;
    for (int k = 0; k < 3 && corner < 0; ++k) {
      kind = predicates::angle_kind(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
      if (kind != AngleKind::Acute) corner = k;
    }
    if (corner < 0) continue;
    (kind == AngleKind::Right ? check.n_right : check.n_obtuse)++;
    if (check.first_bad.size() < max_reported) {
      const auto angles = triangle_angles_deg(p[0], p[1], p[2]);
      check.first_bad.push_back({fh, corner, kind, angles[corner]});
    }
  }
  return check;
}

}  // namespace acute
