// Layer: cvt. The Voronoi diagram of the mesh vertices clipped to the domain (restricted Voronoi
// diagram), with the integrals the CVT energy needs (mass, first moment, energy) under the
// density rho = 1/h^4.
//
// What is computed: the domain (the union of the mesh triangles) is split into regions by the
// constrained edges (triangles connected through unconstrained edges form a region). Within a
// region, the cell of a vertex of the region is the set of points of the region nearer to it than
// to any other vertex of the region (Euclidean distance). So cells are cut by the domain boundary
// and by interior segments that separate regions; a vertex on such a segment has a cell on each
// side. A dangling interior segment (the same region on both sides) does not cut cells; the
// optimiser instead keeps vertices from creeping onto it (see cvt_optimize).
// Why cut by constraints: mesh vertices cannot cross a constrained edge, so a cell reaching across
// one would pull its vertex against the segment (flat triangles), and the CDT is not Delaunay
// there anyway; with the cut every cell's centroid is on its vertex's side.
//
// How: per region, the unconstrained Delaunay triangulation of its vertices (kept across calls in
// the workspace, repaired by flips) gives every cell its bounding bisectors. Every triangle T of
// the region is split among the cells that meet it: starting from T's corners, a cell's piece is
// T clipped by the half-planes of the vertex's Delaunay neighbours (Sutherland-Hodgman), and the
// neighbours whose bisector bounds the piece are visited next (the cells meeting a convex T are
// connected through shared edges). So the pieces tile T up to rounding whatever T's shape (obtuse,
// not Delaunay), and a cell may have several components (across a hole). Shortcut: a cell whose
// Voronoi polygon lies in the disk inscribed in its vertex's star (no constrained edge at the
// vertex) is inside the domain and integrated whole; a triangle whose corners and their Delaunay
// neighbours all have such cells holds no other piece and is skipped.
// Integrals: pieces are fanned into triangles, rho is evaluated at the piece corners and
// interpolated linearly (exact for a uniform field), the polynomial integrals are exact.
// Degenerate input (cocircular or collinear vertices) only produces zero-length edges or
// zero-area pieces: the clipping divides only by a difference of strictly opposite signs.
#pragma once

#include <acute/cvt/size_field.h>
#include <acute/mesh/mesh.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace acute {

/// Per-vertex cell integrals, indexed by vertex idx (vertices without faces have zeros).
struct CellIntegrals {
  std::vector<double> area;    ///< |cell|
  std::vector<double> mass;    ///< m_v = integral of rho over the cell
  std::vector<Point2> moment;  ///< integral of rho x over the cell
  std::vector<Point2> shift;   ///< integral of rho (x - v) over the cell = m_v (c_v - v), without cancellation
  double energy = 0;           ///< F = sum_v integral over cell_v of rho |x - v|^2
  double total_area = 0;       ///< sum of the triangle areas (the domain area)
  std::size_t pieces = 0;      ///< (triangle, cell) pieces of positive area

  /// c_v = moment / mass.
  Point2 centroid(int v) const { return moment[static_cast<std::size_t>(v)] / mass[static_cast<std::size_t>(v)]; }
};

namespace detail {
struct CellScratch;
}

/// Reusable evaluation state: the Delaunay triangulation of the vertices, walk hints into the
/// size field's background mesh, clipping buffers (no allocation per cell).
struct CellWorkspace {
  CellWorkspace();
  ~CellWorkspace();
  CellWorkspace(CellWorkspace&&) noexcept;
  CellWorkspace& operator=(CellWorkspace&&) noexcept;

  std::vector<int> vertex_hint;    ///< per vertex: background triangle of the size field
  std::vector<double> vertex_rho;  ///< per vertex: rho at the vertex (filled by compute_cells)
  std::size_t delaunay_rebuilds() const;  ///< Delaunay triangulations built from scratch so far
  std::size_t delaunay_flips() const;     ///< flips done repairing it

  std::unique_ptr<detail::CellScratch> scratch;
};

/// Cells of every vertex (faces = nullptr), or only their pieces within the given faces (then the
/// integrals of vertices outside them are partial; vectors are still sized to n_vertices and
/// zeroed). With faces, the sites are the vertices of the faces up to four face steps away within
/// the region (others are assumed not to reach the faces), so the cost is local.
void compute_cells(const Mesh& mesh, const SizeField& field, CellIntegrals& out, CellWorkspace& workspace,
                   const std::vector<FaceHandle>* faces = nullptr);

}  // namespace acute
