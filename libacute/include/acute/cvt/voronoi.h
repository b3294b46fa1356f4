// Layer: cvt. Voronoi cells of the mesh vertices restricted to the domain, with the integrals
// the CVT energy needs (mass, first moment, energy) under the density rho = 1/h^4.
//
// What is computed, precisely: every triangle T = (a, b, c) of the mesh is split among its corners
// by the perpendicular bisectors of its edges, each point of T going to the nearest corner of T:
//  - T non-obtuse: a gets the quadrilateral (a, m_ab, o, m_ca), o the circumcentre (inside T);
//  - T obtuse at a: b gets (b, p, m_ab), c gets (c, m_ca, q), a the pentagon (a, m_ab, p, q, m_ca),
//    p and q where the bisectors of ab and ca meet bc.
// The cell of v is the union of its pieces over the triangles around v. The cells tile the domain
// exactly (their areas add up to the mesh area up to rounding) and, for a Delaunay mesh with no
// obtuse triangle, they are exactly the Voronoi cells clipped to the domain. Elsewhere a piece of T
// goes to the nearest corner of T rather than to the nearest vertex overall (a difference confined
// to obtuse triangles). Integrals: pieces are fanned into triangles from their site; rho is
// interpolated linearly between its values at the sub-triangle corners (exact for a uniform field),
// and the polynomial integrals are exact.
#pragma once

#include <acute/cvt/size_field.h>
#include <acute/mesh/mesh.h>

#include <array>
#include <vector>

namespace acute {

/// Per-vertex cell integrals, indexed by vertex idx (vertices without faces have zeros).
struct CellIntegrals {
  std::vector<double> area;    ///< |cell|
  std::vector<double> mass;    ///< m_v = integral of rho over the cell
  std::vector<Point2> moment;  ///< integral of rho x over the cell
  double energy = 0;           ///< F = sum_v integral over cell_v of rho |x - v|^2
  double total_area = 0;

  /// c_v = moment / mass.
  Point2 centroid(int v) const { return moment[static_cast<std::size_t>(v)] / mass[static_cast<std::size_t>(v)]; }
};

/// Reusable evaluation state (walk hints into the size field's background mesh).
struct CellWorkspace {
  std::vector<int> vertex_hint;    ///< per vertex: background triangle of the size field
  std::vector<double> vertex_rho;  ///< per vertex: rho at the vertex (filled by compute_cells)
};

/// Cells of every vertex (faces = nullptr) or only the pieces within the given faces (then the
/// integrals of vertices outside them are partial; vectors are still sized to n_vertices and zeroed).
void compute_cells(const Mesh& mesh, const SizeField& field, CellIntegrals& out, CellWorkspace& workspace,
                   const std::vector<FaceHandle>* faces = nullptr);

/// The piece of triangle (a, b, c) (counter-clockwise) owned by each corner, as counter-clockwise
/// polygons (3 to 5 points) starting at the corner.
std::array<std::vector<Point2>, 3> triangle_pieces(const Point2& a, const Point2& b, const Point2& c);

}  // namespace acute
