// Layer: io. Reading domains and meshes, writing meshes, by file extension.
// Errors: IoError (cannot open / write), InvalidInput ("path:line: problem"), one line each.
#pragma once

#include <acute/core/domain.h>
#include <acute/mesh/dual.h>
#include <acute/mesh/mesh.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace acute::io {

/// Callback for non-fatal remarks (e.g. "regional attributes ignored"). May be empty.
using WarningSink = std::function<void(const std::string&)>;

/// What the domain readers accept beyond a valid PSLG.
struct ReadOptions {
  /// Crossing and overlapping segments pass validation (for build_cdt with
  /// CrossingSegments::Split, the CLI's --split-crossings); repeated segments are still dropped.
  bool allow_crossing_segments = false;
};

/// Reads a Triangle .poly file (0- or 1-based, from the first vertex index; a vertex count of 0
/// reads the sibling .node). Regional attributes, a missing hole section and repeated segments
/// are reported through `warn` (repeats dropped). Ends with validate_domain; messages are
/// "path:line: ..." in the file's numbering. Indices in the Domain are 0-based.
Domain read_poly(const std::string& path, const WarningSink& warn = {}, const ReadOptions& options = {});

/// Reads a CG:SHOP 2025 instance JSON (points, region_boundary, additional_constraints).
/// Coordinates may be numbers or strings "p/q" (rounded to the nearest double). Boundary segments
/// get marker 1, constraints 0. Ends with validate_domain.
Domain read_cgshop(const std::string& path, const WarningSink& warn = {}, const ReadOptions& options = {});

/// Reads a domain by extension: .poly, .json, or a mesh (.off .obj .ply .node/.ele) whose
/// boundary becomes the segments and whose boundary vertices become the points (domain_of_mesh).
/// A .node file without a sibling .ele is a point set: convex_hull is set.
/// Note: the readers never set convex_hull otherwise (classic/box.poly is meant for it: the CLI
/// has a flag).
Domain read_domain(const std::string& path, const WarningSink& warn = {}, const ReadOptions& options = {});

/// Checks a domain: finite coordinates in the exact range, indices in range, no duplicate points,
/// no zero-length, repeated, crossing or overlapping segments (exact). Segments may touch, and a
/// point may lie inside a segment (see find_points_on_segments). O(n log n + k) for typical
/// inputs. Throws InvalidInput naming the elements (and "source_path: " when set). With
/// allow_crossings, crossing and overlapping segments are accepted (repeated ones are not).
void validate_domain(const Domain& domain, bool allow_crossings = false);

/// A point lying in the interior of a segment that does not end there. Allowed by validate_domain
/// (Triangle splits the segment at such a point), but the mesher has to handle it.
struct PointOnSegment {
  int point = -1;
  int segment = -1;
};

/// Every point lying in the interior of a segment (exact), sorted by segment then point.
std::vector<PointOnSegment> find_points_on_segments(const Domain& domain);

/// The domain a triangle mesh covers: its boundary edges become segments (one per edge, loop by
/// loop), its boundary vertices the points (in vertex order; markers kept), and every hole of the
/// mesh gets a seed point strictly inside it. Deleted elements are ignored.
Domain domain_of_mesh(const Mesh& mesh);

/// Reads a triangle mesh (.off .obj .ply (ascii/binary), Triangle .node/.ele (markers kept)).
/// Throws on non-triangle faces, NaN/inf, out-of-range indices, repeated vertices in a face,
/// non-manifold edges or vertices, and mixed orientation (folds), naming the first bad element.
/// An all-clockwise mesh is reversed and nonzero z dropped, with a warning. Vertices are Free.
Mesh read_mesh(const std::string& path, const WarningSink& warn = {});

/// An edge a mesh file tags: its vertices (0-based, as read_mesh numbers them) and its line.
struct TaggedEdge {
  std::array<int, 2> vertices{};
  int line = 0;
};

/// The edges a mesh file tags: every consecutive pair of an OBJ polyline element (`l a b c ...`;
/// `v/vt` and relative indices as in faces). Other formats tag none. Indices are checked against
/// the file's vertices; whether a pair is an edge of the mesh is for the caller to check.
/// \throws InvalidInput "path:line: problem", IoError when the file cannot be read.
std::vector<TaggedEdge> read_tagged_edges(const std::string& path);

struct WriteOptions {
  double min_angle_deg = 30.0;  ///< for SVG colouring
  double max_angle_deg = 90.0;
  std::string title;            ///< SVG legend title
  bool vertex_labels = false;   ///< SVG: each vertex's index (0-based, vertex order) beside it
  double histogram_bin_deg = 5; ///< write_angle_histogram_svg: bin width in degrees, in (0, 180]
};

/// Writes by extension: .off .obj .ply .vtk .vtu .msh (17 significant digits), .node/.ele (give
/// either; both written), .svg. Written atomically (temporary file + rename). Throws IoError.
void write_mesh(const Mesh& mesh, const std::string& path, const WriteOptions& options = {});

/// SVG picture: triangles, constrained edges bold, bad triangles filled, legend with figures.
void write_svg(const Mesh& mesh, const std::string& path, const WriteOptions& options = {});

/// SVG bar chart of all 3T angles in bins of options.histogram_bin_deg over [0, 180] (180 in the
/// last bin): the angles below min_angle_deg and those not below max_angle_deg (exactly for 90)
/// are stacked on top in the colours of write_svg; the bounds are dashed vertical lines. Each bar
/// is a <rect class="bar" data-count="N">, so the counts sum to 3T. Atomic. Throws IoError, or
/// InvalidInput for a bin width outside (0, 180].
void write_angle_histogram_svg(const Mesh& mesh, const std::string& path, const WriteOptions& options = {});

/// Legacy VTK (ASCII UNSTRUCTURED_GRID, version 3.0): POINTS double (z = 0), triangles (cell type
/// 5), POINT_DATA "marker", CELL_DATA "min_angle" and "max_angle" in degrees. For ParaView/meshio.
void write_vtk(const Mesh& mesh, const std::string& path);

/// VTK XML UnstructuredGrid (.vtu, ASCII), the same data as write_vtk.
void write_vtu(const Mesh& mesh, const std::string& path);

/// Gmsh 4.1 ASCII (.msh): one surface entity holding every node and one block of 3-node
/// triangles (type 2); tags are 1-based in vertex / face order. Angles in an $ElementData view.
void write_msh(const Mesh& mesh, const std::string& path);

/// ASCII PLY: vertex x y z as double (+ int marker), face vertex_indices (uchar count, int
/// indices) + double min_angle, max_angle.
void write_ply(const Mesh& mesh, const std::string& path);

/// Writes the circumcentric dual (acute::circumcentric_dual) by extension: .off .obj .ply .vtk
/// .vtu (polygons; the VTK files carry cell data "primal_vertex", "boundary", "area" and point
/// data "kind", the PLY file no per-cell data) or .svg (the cells over the primal mesh when
/// given, cells with non-positive area filled). Atomic. Throws IoError for other extensions.
void write_dual(const DualMesh& dual, const std::string& path, const Mesh* primal = nullptr,
                const WriteOptions& options = {});

/// Is this extension one write_mesh / write_dual accept?
bool is_mesh_output_path(const std::string& path);
bool is_dual_output_path(const std::string& path);

/// Is this extension a mesh format we can read (.off .obj .ply .node .ele)?
bool is_mesh_path(const std::string& path);

}  // namespace acute::io
