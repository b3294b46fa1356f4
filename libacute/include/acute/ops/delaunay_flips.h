// Layer: ops. Lawson's flip algorithm: restores the constrained Delaunay property by flipping
// non-locally-Delaunay edges, starting from a queue of suspect edges.
#pragma once

#include <acute/mesh/mesh.h>

#include <vector>

namespace acute {

/// Flips until every edge reachable from `queue` is locally Delaunay. The queue is consumed.
/// Returns the number of flips. \post the edges of every face touched are locally Delaunay.
/// With `touched`, the four corners of every flipped quadrilateral are appended to it (the
/// vertices whose stars the flips changed; with repeats).
std::size_t restore_delaunay(Mesh& mesh, std::vector<EdgeHandle>& queue, std::vector<VertexHandle>* touched = nullptr);

/// Lawson on the whole mesh. \post check_mesh(mesh, CheckLevel::Delaunay).ok() for a valid input.
std::size_t make_delaunay(Mesh& mesh);

/// Pushes the edges of every face around vh (the link and the spokes) onto queue.
void push_star_edges(const Mesh& mesh, VertexHandle vh, std::vector<EdgeHandle>& queue);

}  // namespace acute
