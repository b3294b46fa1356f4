// Layer: mesh. The circumcentric (Voronoi) dual of a triangle mesh, for covolume, finite-volume and
// DEC users, and the exact check that the mesh is well-centred (every circumcentre strictly inside
// its triangle), which is what makes the dual cells proper and orthogonal to the primal edges.
#pragma once

#include <acute/core/types.h>
#include <acute/mesh/mesh.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace acute {

/// What a dual vertex is.
enum class DualPointKind : std::uint8_t {
  Circumcenter,  ///< circumcentre of a primal triangle (source = face index)
  EdgeMidpoint,  ///< midpoint of a primal boundary edge (source = edge index)
  PrimalVertex   ///< a primal boundary vertex itself (source = vertex index)
};

/// The dual as a polygon mesh. Cell i is the dual cell of primal vertex cell_vertex[i]: the
/// circumcentres of the triangles around it in counter-clockwise order; around a boundary vertex v
/// the polygon is v, the midpoint of the boundary edge after v, the circumcentres, the midpoint of
/// the boundary edge before v (counter-clockwise, the cell is clipped at the boundary). A vertex
/// whose triangles form several fans gets one cell per fan. Isolated vertices get no cell.
/// Each dual point is stored once (cells share them).
struct DualMesh {
  std::vector<Point2> points;
  std::vector<DualPointKind> point_kinds;  ///< one per point
  std::vector<int> point_sources;          ///< primal handle index per point (see DualPointKind)
  std::vector<std::vector<int>> cells;     ///< indices into points, counter-clockwise
  std::vector<int> cell_vertex;            ///< primal vertex index per cell
  std::vector<std::uint8_t> cell_on_boundary;  ///< 1 when the primal vertex is on the boundary

  std::size_t n_points() const { return points.size(); }
  std::size_t n_cells() const { return cells.size(); }
};

/// Builds the circumcentric dual (deleted elements ignored). Circumcentres are floating-point
/// constructions (acute::circumcenter); for a triangle that is not well-centred the circumcentre
/// lies on or outside it and the cells overlap or fold (see check_well_centered).
DualMesh circumcentric_dual(const Mesh& mesh);

/// Signed area of a dual cell (shoelace, floating point). The signed areas of all cells sum to the
/// area of the mesh for any mesh; for a well-centred mesh every cell area is positive.
double cell_area(const DualMesh& dual, std::size_t cell);

/// A triangle whose circumcentre is not strictly inside it.
struct BadDualFace {
  FaceHandle face;
  int corner = -1;          ///< 0, 1, 2: the corner (in face_vertices order) with the angle >= 90°
  AngleKind kind = AngleKind::Right;  ///< Right (circumcentre on the opposite edge) or Obtuse (outside)
  double angle_deg = 0;     ///< that angle, for reporting
};

struct DualCheck {
  std::size_t n_faces = 0;
  std::size_t n_right = 0;    ///< triangles with a right angle
  std::size_t n_obtuse = 0;   ///< triangles with an obtuse angle
  std::vector<BadDualFace> first_bad;  ///< the first offending faces in face order (at most max_reported)

  bool well_centered() const { return n_right == 0 && n_obtuse == 0; }
  std::size_t n_bad() const { return n_right + n_obtuse; }
};

/// Checks that every circumcentre lies strictly inside its triangle. Exact: a triangle is
/// well-centred iff its three angles are acute, decided by predicates::angle_kind.
DualCheck check_well_centered(const Mesh& mesh, std::size_t max_reported = 10);

}  // namespace acute
