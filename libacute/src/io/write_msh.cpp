// Gmsh 4.1 ASCII writer: one surface entity, one node block, one block of 3-node triangles, and
// the per-triangle angles as two $ElementData views.
#include "io/atomic_file.h"
#include "io/cell_table.h"
#include "io/io_detail.h"

#include <acute/io/io.h>

#include <algorithm>
#include <limits>

namespace acute::io {

void write_msh(const Mesh& mesh, const std::string& path) {
  const detail::CellTable t = detail::table_of(mesh);
  const std::size_t nv = t.points.size(), nf = t.n_cells();
  double lo[2] = {0, 0}, hi[2] = {0, 0};
  if (nv > 0) {
    lo[0] = lo[1] = std::numeric_limits<double>::infinity();
    hi[0] = hi[1] = -lo[0];
    for (const auto& p : t.points)
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  using detail::format_double;

  detail::AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  // One surface (tag 1) without physical tags or bounding curves.
  out << "$Entities\n0 0 1 0\n1 " << format_double(lo[0]) << ' ' << format_double(lo[1]) << " 0 "
      << format_double(hi[0]) << ' ' << format_double(hi[1]) << " 0 0 0\n$EndEntities\n";

  out << "$Nodes\n";
  if (nv == 0) {
    out << "0 0 0 0\n";
  } else {
    out << "1 " << nv << " 1 " << nv << "\n2 1 0 " << nv << '\n';
    for (std::size_t i = 1; i <= nv; ++i) out << i << '\n';
    for (const auto& p : t.points) out << format_double(p.x()) << ' ' << format_double(p.y()) << " 0\n";
  }
  out << "$EndNodes\n$Elements\n";
  if (nf == 0) {
    out << "0 0 0 0\n";
  } else {
    out << "1 " << nf << " 1 " << nf << "\n2 1 2 " << nf << '\n';
    for (std::size_t i = 0; i < nf; ++i) {
      out << i + 1;
      for (int k = t.offsets[i]; k < t.offsets[i + 1]; ++k) out << ' ' << t.connectivity[k] + 1;
      out << '\n';
    }
  }
  out << "$EndElements\n";
  if (nf > 0)
    for (const auto& f : t.cell_fields) {
      // string tags: view name; real tags: time; integer tags: time step, components, count
      out << "$ElementData\n1\n\"" << f.name << "\"\n1\n0\n3\n0\n1\n" << nf << '\n';
      for (std::size_t i = 0; i < nf; ++i) out << i + 1 << ' ' << detail::format_field_value(f.values[i], f.integer) << '\n';
      out << "$EndElementData\n";
    }
  file.commit();
}

}  // namespace acute::io
