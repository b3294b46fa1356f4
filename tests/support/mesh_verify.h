// Independent test verifiers: topology, orientation, constraints and brute-force Delaunay.
#pragma once

#include <acute/mesh/mesh.h>
#include <acute/predicates/predicates.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace acute::test {

/// Empty string when every face is strictly counter-clockwise, the mesh edge-manifold and every
/// vertex on a segment lies next to two edges of that segment; else the first problem.
inline std::string verify_valid(const Mesh& mesh) {
  std::ostringstream msg;
  for (auto fh : mesh.faces()) {
    Point2 p[3];
    int k = 0;
    for (auto vh : mesh.fv_range(fh)) p[k++] = point2(mesh, vh);
    if (k != 3) return "face " + std::to_string(fh.idx()) + ": not a triangle";
    if (predicates::orient2d(p[0], p[1], p[2]) != Sign::Positive) return "face " + std::to_string(fh.idx()) + ": not counter-clockwise";
  }
  for (auto vh : mesh.vertices()) {
    if (mesh.data(vh).kind != VertexKind::OnSegment) continue;
    int n = 0;
    for (auto heh : mesh.voh_range(vh)) n += mesh.data(mesh.edge_handle(heh)).segment == mesh.data(vh).segment;
    if (n != 2) return "vertex " + std::to_string(vh.idx()) + ": on segment but has " + std::to_string(n) + " segment edges";
  }
  return {};
}

/// Brute force: no vertex strictly inside any face's circumcircle (unconstrained meshes or convex
/// domains where every vertex is visible), O(F * V).
inline std::string verify_delaunay_brute_force(const Mesh& mesh) {
  for (auto fh : mesh.faces()) {
    Point2 p[3];
    int k = 0;
    for (auto vh : mesh.fv_range(fh)) p[k++] = point2(mesh, vh);
    for (auto vh : mesh.vertices())
      if (predicates::incircle(p[0], p[1], p[2], point2(mesh, vh)) == Sign::Positive)
        return "face " + std::to_string(fh.idx()) + ": vertex " + std::to_string(vh.idx()) + " inside its circumcircle";
  }
  return {};
}

/// Sum of face areas.
inline double total_area(const Mesh& mesh) {
  double a = 0;
  for (auto fh : mesh.faces()) {
    Point2 p[3];
    int k = 0;
    for (auto vh : mesh.fv_range(fh)) p[k++] = point2(mesh, vh);
    a += 0.5 * ((p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x());
  }
  return a;
}

}  // namespace acute::test

#define EXPECT_MESH_VALID(mesh) EXPECT_EQ(::acute::test::verify_valid(mesh), "")
#define EXPECT_MESH_DELAUNAY(mesh) EXPECT_EQ(::acute::test::verify_delaunay_brute_force(mesh), "")
