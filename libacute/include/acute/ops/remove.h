// Layer: ops. Vertex removal (re-triangulation of the star, constrained Delaunay) and half-edge
// collapse. Input vertices are never removed; a vertex on a segment is removed along it.
//
//   collapse(v0v1): v0 disappears, its triangles fan from v1
//        vl                 vl
//       /  \               /  \ .
//     v0----v1    ->          v1
//       \  /               \  /
//        vr                 vr
#pragma once

#include <acute/ops/flip.h>

#include <vector>

namespace acute {

/// Ok when vh is not an input vertex and its star can be re-triangulated without it.
OpVerdict can_remove_vertex(const Mesh& mesh, VertexHandle vh);

/// Removes vh, re-triangulates its star (constrained Delaunay, segments re-joined) and restores
/// the Delaunay property. Returns false (mesh unchanged) when refused.
bool remove_vertex(Mesh& mesh, VertexHandle vh);

/// Removes every vertex of `vertices` it can (remove_vertex each), in rounds of vertices no two of
/// which are neighbours: a removal then re-triangulates the star the vertex had, not a hole its
/// removed neighbours grew (removing a disk of k vertices one after another in index order grew
/// links to O(k) vertices: seconds for one sharp corner of a refined mesh). Returns true when all
/// of them are gone.
bool remove_vertices(Mesh& mesh, const std::vector<VertexHandle>& vertices);

/// Ok when collapsing v0 into v1 keeps a valid triangulation: v0 not Input; a v0 on a segment
/// moves only along it; the link condition holds; no triangle inverts.
OpVerdict can_collapse(const Mesh& mesh, HalfedgeHandle v0v1);

/// Collapses v0 into v1 and restores the Delaunay property. \pre can_collapse(...) == Ok
void collapse(Mesh& mesh, HalfedgeHandle v0v1);

}  // namespace acute
