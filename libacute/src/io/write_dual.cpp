// Writers of the circumcentric dual (polygon mesh): OFF, OBJ, PLY, VTK, VTU and an SVG picture,
// plus the OFF/OBJ writers of a polygon cell table.
#include "io/atomic_file.h"
#include "io/cell_table.h"
#include "io/io_detail.h"
#include "io/svg_canvas.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>

#include <algorithm>

namespace acute::io {

namespace detail {

void write_off_table(const CellTable& t, const std::string& path) {
  AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "OFF\n# " << t.title << '\n' << t.points.size() << ' ' << t.n_cells() << " 0\n";
  for (const auto& p : t.points) out << format_double(p.x()) << ' ' << format_double(p.y()) << " 0\n";
  for (std::size_t i = 0; i < t.n_cells(); ++i) {
    out << t.cell_size(i);
    for (int k = t.offsets[i]; k < t.offsets[i + 1]; ++k) out << ' ' << t.connectivity[k];
    out << '\n';
  }
  file.commit();
}

void write_obj_table(const CellTable& t, const std::string& path) {
  AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "# " << t.title << ": " << t.points.size() << " vertices, " << t.n_cells() << " faces\n";
  for (const auto& p : t.points) out << "v " << format_double(p.x()) << ' ' << format_double(p.y()) << " 0\n";
  for (std::size_t i = 0; i < t.n_cells(); ++i) {
    out << 'f';
    for (int k = t.offsets[i]; k < t.offsets[i + 1]; ++k) out << ' ' << t.connectivity[k] + 1;
    out << '\n';
  }
  file.commit();
}

}  // namespace detail

namespace {

using detail::svg_fixed;

constexpr const char* kBadFill = "#d7191c";       // cell with non-positive area (folded)
constexpr const char* kBoundaryFill = "#e6f0fa";  // cells of boundary vertices

void write_dual_svg(const DualMesh& dual, const std::string& path, const Mesh* primal, const WriteOptions& options) {
  detail::SvgBox box;
  for (const auto& p : dual.points) box.add(p);
  if (primal)
    for (auto vh : primal->vertices()) box.add(point2(*primal, vh));
  const detail::SvgFrame frame(box);
  auto at = [&](const Point2& p) { return frame.at(p); };

  std::string cells, bad, boundary;
  double perimeter = 0;
  std::size_t n_sides = 0, n_bad = 0;
  for (std::size_t i = 0; i < dual.n_cells(); ++i) {
    const auto& c = dual.cells[i];
    std::string d;
    for (std::size_t k = 0; k < c.size(); ++k) {
      d += (k ? 'L' : 'M') + at(dual.points[c[k]]);
      perimeter += (dual.points[c[(k + 1) % c.size()]] - dual.points[c[k]]).norm();
    }
    d += 'Z';
    n_sides += c.size();
    cells += d;
    if (cell_area(dual, i) <= 0) {
      bad += d;
      ++n_bad;
    } else if (dual.cell_on_boundary[i]) {
      boundary += d;
    }
  }
  const double mean_side = n_sides ? perimeter / double(n_sides) * frame.scale() : detail::SvgFrame::kDrawWidth / 10;
  const double thin = std::clamp(0.08 * mean_side, 0.03, 1.0);

  std::string primal_edges;
  std::size_t n_triangles = 0;
  if (primal) {
    for (auto eh : primal->edges()) {
      const auto h = primal->halfedge_handle(eh, 0);
      primal_edges += 'M' + at(point2(*primal, primal->from_vertex_handle(h))) + 'L' +
                      at(point2(*primal, primal->to_vertex_handle(h)));
    }
    for (auto fh : primal->faces()) (void)fh, ++n_triangles;
  }

  std::vector<std::string> legend;
  if (!options.title.empty()) legend.push_back(options.title);
  legend.push_back("circumcentric dual: " + std::to_string(dual.n_cells()) + " cells, " +
                   std::to_string(dual.n_points()) + " points");
  if (primal) {
    const DualCheck check = check_well_centered(*primal, 0);
    legend.push_back(std::to_string(n_triangles) + " primal triangles (grey), " +
                     (check.well_centered() ? std::string("all circumcentres inside")
                                            : std::to_string(check.n_bad()) + " with the circumcentre not inside"));
  }
  legend.push_back(std::to_string(n_bad) + " cells with non-positive area (red)");

  detail::AtomicFile file(path);
  std::ostream& out = file.stream();
  detail::begin_svg(out, frame.page_width(), frame.page_height(legend.size()));
  if (!boundary.empty()) out << "<path fill=\"" << kBoundaryFill << "\" stroke=\"none\" d=\"" << boundary << "\"/>\n";
  if (!bad.empty()) out << "<path fill=\"" << kBadFill << "\" fill-opacity=\"0.6\" stroke=\"none\" d=\"" << bad << "\"/>\n";
  if (!primal_edges.empty())
    out << "<path fill=\"none\" stroke=\"#bbb\" stroke-width=\"" << svg_fixed(thin, 3) << "\" d=\"" << primal_edges << "\"/>\n";
  if (!cells.empty())
    out << "<path fill=\"none\" stroke=\"#2b5797\" stroke-width=\"" << svg_fixed(1.5 * thin, 3)
        << "\" stroke-linejoin=\"round\" d=\"" << cells << "\"/>\n";
  detail::begin_text_group(out);
  detail::write_text_lines(out, legend, frame.margin(), frame.legend_top());
  out << "</g>\n</svg>\n";
  file.commit();
}

}  // namespace

void write_dual(const DualMesh& dual, const std::string& path, const Mesh* primal, const WriteOptions& options) {
  const std::string ext = detail::extension_of(path);
  if (ext == ".svg") return write_dual_svg(dual, path, primal, options);
  if (!is_dual_output_path(path))
    throw IoError(path + ": unknown dual output format '" + ext + "' (expected .off, .obj, .ply, .vtk, .vtu, .svg)");
  const detail::CellTable t = detail::table_of(dual);
  if (ext == ".off") return detail::write_off_table(t, path);
  if (ext == ".obj") return detail::write_obj_table(t, path);
  if (ext == ".ply") return detail::write_ply_table(t, path);
  if (ext == ".vtk") return detail::write_vtk_table(t, path);
  return detail::write_vtu_table(t, path);
}

bool is_dual_output_path(const std::string& path) {
  const std::string ext = detail::extension_of(path);
  for (const char* e : {".off", ".obj", ".ply", ".vtk", ".vtu", ".svg"})
    if (ext == e) return true;
  return false;
}

bool is_mesh_output_path(const std::string& path) {
  const std::string ext = detail::extension_of(path);
  for (const char* e : {".off", ".obj", ".ply", ".vtk", ".vtu", ".msh", ".node", ".ele", ".svg"})
    if (ext == e) return true;
  return false;
}

}  // namespace acute::io
