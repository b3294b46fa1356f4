// Layer: mesh. Boundary loops of a mesh whose region may touch itself at a vertex (a pinch vertex:
// several fans of faces meeting only there, e.g. a hole touching the outer boundary, or two parts
// of the domain sharing a corner). OpenMesh holds such a vertex with several boundary gaps; the
// order of its fans depends on the order faces were added (order_pinch_vertices in mesh.h fixes it).
#pragma once

#include <acute/mesh/mesh.h>

#include <cstddef>
#include <vector>

namespace acute {

/// The boundary as simple closed loops of vertices in boundary-halfedge order (region on the
/// right): a walk through a pinch vertex twice is split there, so a vertex occurs at most once per
/// loop (a pinch vertex lies on several loops).
std::vector<std::vector<VertexHandle>> simple_boundary_loops(const Mesh& mesh);

/// True when the vertex has more than one boundary gap (several fans).
bool is_pinch_vertex(const Mesh& mesh, VertexHandle vh);

}  // namespace acute
