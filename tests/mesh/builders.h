// Small meshes for the mesh-layer tests.
#pragma once

#include <acute/mesh/mesh.h>

#include <array>
#include <utility>
#include <vector>

namespace acute::test {

/// A mesh from points and triangles (vertex indices, in the given order).
inline Mesh make_mesh(const std::vector<std::pair<double, double>>& pts, const std::vector<std::array<int, 3>>& tris) {
  Mesh m;
  std::vector<VertexHandle> vs;
  for (auto [x, y] : pts) vs.push_back(m.add_vertex(Mesh::Point(x, y, 0.0)));
  for (const auto& t : tris) m.add_face(vs[t[0]], vs[t[1]], vs[t[2]]);
  return m;
}

/// The unit square split along the diagonal (0,0)-(1,1): two right triangles.
inline Mesh unit_square() { return make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}); }

/// An n x n grid of unit squares, each split along its diagonal.
inline Mesh grid(int n) {
  std::vector<std::pair<double, double>> pts;
  std::vector<std::array<int, 3>> tris;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) pts.emplace_back(i, j);
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return make_mesh(pts, tris);
}

}  // namespace acute::test
