// Layer: mesh. The sectors at a vertex: the fans of faces between consecutive "wall" spokes
// (outgoing halfedges on input segments, on the mesh boundary, ... as the caller decides), swept
// counter-clockwise. The angles are floating-point measures for choosing, not for topology.
#pragma once

#include <acute/mesh/mesh.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace acute {

/// How a sweep ended.
enum class SectorEnd : std::uint8_t {
  Wall,        ///< at the next wall spoke: a whole sector
  Closed,      ///< back at the start spoke without meeting another wall (the full star)
  Border,      ///< at a mesh boundary halfedge that is no wall: a partial fan (e.g. a frozen border)
  Unfinished   ///< max_triangles faces swept without reaching an end
};

struct SectorSweep {
  double radians = 0;  ///< sum of the corner angles at the vertex, each atan2(|cross|, dot)
  double degrees = 0;  ///< the same corners, each converted to degrees before summing
  int triangles = 0;   ///< faces swept
  HalfedgeHandle end;  ///< the spoke it stopped at (outgoing from the vertex; without a face at a Border)
  SectorEnd how = SectorEnd::Unfinished;
};

/// Whether a spoke (a halfedge going out of the vertex) bounds sectors.
using WallTest = std::function<bool(HalfedgeHandle)>;

/// The usual wall: the spoke's edge is an input segment (constrained) or on the mesh boundary.
bool is_segment_or_boundary(const Mesh& mesh, HalfedgeHandle spoke);

/// Sweeps the faces around the vertex `start` leaves, counter-clockwise from `start` (a spoke with
/// a face on its left; it need not be a wall), one face at a time, and stops at the first spoke
/// that is `start` again (Closed), else one is_wall accepts (Wall), else a boundary halfedge
/// (Border); Unfinished after max_triangles faces. A start without a face: Border, no triangles.
SectorSweep sweep_sector(const Mesh& mesh, HalfedgeHandle start, const WallTest& is_wall, int max_triangles = 1024);

/// Called for each sector of a vertex's star: `first` its spoke counter-clockwise, `closed` when the
/// star has no wall (one sector, the whole star).
using SectorVisitor = std::function<void(HalfedgeHandle first, const SectorSweep& sector, bool closed)>;

/// Visits the sectors of vh between its segment or boundary spokes counter-clockwise (its whole star
/// when it has none; nothing for a boundary vertex without such a spoke), sweeping at most
/// max_triangles faces in all; a fan that reaches a boundary halfedge that is no wall (SectorEnd::Border,
/// e.g. a region copy's frozen border) is visited and ends the walk.
void for_each_sector(const Mesh& mesh, VertexHandle vh, int max_triangles, const SectorVisitor& visit);

/// A whole sector at a vertex: the fan between two consecutive segment spokes.
struct SegmentSector {
  HalfedgeHandle first, last;  ///< the segment spokes it lies between, counter-clockwise from first to last
  double radians = 0;
};

/// The whole sectors at vh between consecutive spokes on input segments (constrained edges; the
/// domain boundary is made of segments), in the order of vh's outgoing halfedges. A fan that does
/// not end at a segment spoke (it reaches a mesh boundary that is no segment, e.g. the frozen
/// border of a region copy, or goes all the way round because vh has one segment) is left out and
/// sets *partial. The returned handles are valid until the mesh is edited.
std::vector<SegmentSector> segment_sectors(const Mesh& mesh, VertexHandle vh, bool* partial = nullptr);

/// The segment spoke (constrained edge) of vh whose direction is the unit vector u (within 1e-12
/// of its cosine), or an invalid handle. For finding a wall again after edits at vh, whose handles
/// they invalidate (a choice of direction, not a topological test).
HalfedgeHandle segment_spoke_along(const Mesh& mesh, VertexHandle vh, const Point2& u);

}  // namespace acute
