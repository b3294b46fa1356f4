// Procedural meshes for tests: small, deterministic, with the constraint data a CDT would give.
#pragma once

#include <acute/mesh/mesh.h>
#include <acute/mesh/segments.h>

namespace acute::test {

/// An n x n grid of unit squares over [0, n]^2, each square cut by one diagonal (alternating),
/// boundary edges constrained (segments 0..3 = bottom, right, top, left), corners Input,
/// other boundary vertices OnSegment.
inline Mesh grid_mesh(int n, bool alternate = true) {
  Mesh mesh;
  std::vector<VertexHandle> v((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) v[j * (n + 1) + i] = mesh.add_vertex(Mesh::Point(i, j, 0));
  auto at = [&](int i, int j) { return v[j * (n + 1) + i]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (!alternate || (i + j) % 2 == 0) {
        mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      } else {
        mesh.add_face(at(i, j), at(i + 1, j), at(i, j + 1));
        mesh.add_face(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
    }
  set_segment_table(mesh, {{{Point2(0, 0), Point2(n, 0)}}, {{Point2(n, 0), Point2(n, n)}},
                           {{Point2(n, n), Point2(0, n)}}, {{Point2(0, n), Point2(0, 0)}}});
  auto seg_of = [&](const Point2& a, const Point2& b) {
    if (a.y() == 0 && b.y() == 0) return 0;
    if (a.x() == n && b.x() == n) return 1;
    if (a.y() == n && b.y() == n) return 2;
    return 3;
  };
  for (auto eh : mesh.edges()) {
    if (!mesh.is_boundary(eh)) continue;
    const auto h = mesh.halfedge_handle(eh, 0);
    const Point2 a = point2(mesh, mesh.from_vertex_handle(h)), b = point2(mesh, mesh.to_vertex_handle(h));
    mesh.data(eh).segment = seg_of(a, b);
    for (auto vh : {mesh.from_vertex_handle(h), mesh.to_vertex_handle(h)}) {
      mesh.data(vh).kind = VertexKind::OnSegment;
      mesh.data(vh).segment = seg_of(a, b);
    }
  }
  for (auto vh : {at(0, 0), at(n, 0), at(n, n), at(0, n)}) {
    mesh.data(vh).kind = VertexKind::Input;
    mesh.data(vh).segment = -1;
  }
  return mesh;
}

}  // namespace acute::test
