// Layer: io (private). A mesh flattened for the polygon-capable writers (VTK legacy, VTU, PLY,
// OFF/OBJ of the dual): dense points, cells as offsets + connectivity, named per-point and
// per-cell fields.
#pragma once

#include <acute/core/types.h>
#include <acute/mesh/dual.h>
#include <acute/mesh/mesh.h>

#include <string>
#include <vector>

namespace acute::io::detail {

struct CellField {
  std::string name;
  std::vector<double> values;
  bool integer = false;  ///< values are whole numbers (written without a decimal point)
};

struct CellTable {
  std::vector<Point2> points;
  std::vector<int> offsets{0};   ///< cell i is connectivity[offsets[i] .. offsets[i+1])
  std::vector<int> connectivity;
  std::vector<CellField> point_fields;
  std::vector<CellField> cell_fields;
  std::string title;             ///< one-line description (VTK header, PLY comment)

  std::size_t n_cells() const { return offsets.size() - 1; }
  std::size_t cell_size(std::size_t i) const { return static_cast<std::size_t>(offsets[i + 1] - offsets[i]); }
  bool all_triangles() const;
};

/// Live vertices (dense, in order) and triangles of a mesh; point field "marker", cell fields
/// "min_angle" and "max_angle" (degrees).
CellTable table_of(const Mesh& mesh);

/// The cells of a dual; point field "kind" (0 circumcentre, 1 edge midpoint, 2 primal vertex),
/// cell fields "primal_vertex", "boundary", "area".
CellTable table_of(const DualMesh& dual);

/// Writers of a table (atomic). Triangles are VTK type 5, other cells polygons (type 7).
void write_vtk_table(const CellTable& table, const std::string& path);
void write_vtu_table(const CellTable& table, const std::string& path);
void write_ply_table(const CellTable& table, const std::string& path);
void write_off_table(const CellTable& table, const std::string& path);
void write_obj_table(const CellTable& table, const std::string& path);

/// A whole number for an integer field, else 17 significant digits.
std::string format_field_value(double x, bool integer);

}  // namespace acute::io::detail
