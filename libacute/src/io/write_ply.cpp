// ASCII PLY writer (triangle meshes and polygon meshes), doubles with 17 significant digits.
#include "io/atomic_file.h"
#include "io/cell_table.h"
#include "io/io_detail.h"

#include <acute/io/io.h>

namespace acute::io {

namespace detail {

void write_ply_table(const CellTable& t, const std::string& path) {
  AtomicFile file(path);
  std::ostream& out = file.stream();
  const std::size_t nc = t.n_cells();
  std::size_t largest = 0;
  for (std::size_t i = 0; i < nc; ++i) largest = std::max(largest, t.cell_size(i));
  // Face properties only for triangle meshes: readers split mixed polygons into blocks by size
  // and some (meshio 5) then fail on per-face data.
  static const std::vector<CellField> none;
  const std::vector<CellField>& cell_fields = t.all_triangles() ? t.cell_fields : none;
  out << "ply\nformat ascii 1.0\ncomment " << t.title << "\nelement vertex " << t.points.size()
      << "\nproperty double x\nproperty double y\nproperty double z\n";
  for (const auto& f : t.point_fields) out << "property " << (f.integer ? "int " : "double ") << f.name << '\n';
  out << "element face " << nc << "\nproperty list " << (largest < 256 ? "uchar" : "uint") << " int vertex_indices\n";
  for (const auto& f : cell_fields) out << "property " << (f.integer ? "int " : "double ") << f.name << '\n';
  out << "end_header\n";
  for (std::size_t i = 0; i < t.points.size(); ++i) {
    out << format_double(t.points[i].x()) << ' ' << format_double(t.points[i].y()) << " 0";
    for (const auto& f : t.point_fields) out << ' ' << format_field_value(f.values[i], f.integer);
    out << '\n';
  }
  for (std::size_t i = 0; i < nc; ++i) {
    out << t.cell_size(i);
    for (int k = t.offsets[i]; k < t.offsets[i + 1]; ++k) out << ' ' << t.connectivity[k];
    for (const auto& f : cell_fields) out << ' ' << format_field_value(f.values[i], f.integer);
    out << '\n';
  }
  file.commit();
}

}  // namespace detail

void write_ply(const Mesh& mesh, const std::string& path) { detail::write_ply_table(detail::table_of(mesh), path); }

}  // namespace acute::io
