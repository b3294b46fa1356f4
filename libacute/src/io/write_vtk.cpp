// VTK writers: legacy ASCII (.vtk, version 3.0) and XML UnstructuredGrid (.vtu, ASCII), for
// triangle meshes and for polygon meshes (the dual), through a flat cell table.
#include "io/atomic_file.h"
#include "io/cell_table.h"
#include "io/io_detail.h"

#include <acute/io/io.h>
#include <acute/mesh/geometry.h>
#include <acute/mesh/quality.h>

#include <cmath>

namespace acute::io {

namespace detail {

namespace {

constexpr int kVtkTriangle = 5;
constexpr int kVtkPolygon = 7;

int vtk_type(const CellTable& t, std::size_t i) { return t.cell_size(i) == 3 ? kVtkTriangle : kVtkPolygon; }

}  // namespace

bool CellTable::all_triangles() const {
  for (std::size_t i = 0; i < n_cells(); ++i)
    if (cell_size(i) != 3) return false;
  return true;
}

std::string format_field_value(double x, bool integer) {
  if (integer) return std::to_string(static_cast<long long>(x));
  return format_double(x);
}

CellTable table_of(const Mesh& mesh) {
  CellTable t;
  t.title = "libacute triangle mesh";
  std::vector<int> number(mesh.n_vertices(), -1);
  CellField marker{"marker", {}, true};
  for (auto vh : mesh.vertices()) {
    number[vh.idx()] = static_cast<int>(t.points.size());
    t.points.push_back(point2(mesh, vh));
    marker.values.push_back(mesh.data(vh).marker);
  }
  CellField min_angle{"min_angle", {}, false}, max_angle{"max_angle", {}, false};
  for (auto fh : mesh.faces()) {
    Point2 p[3];
    int k = 0;
    for (auto fv : mesh.fv_range(fh)) {
      if (k < 3) p[k] = point2(mesh, fv);
      t.connectivity.push_back(number[fv.idx()]);
      ++k;
    }
    t.offsets.push_back(static_cast<int>(t.connectivity.size()));
    const auto a = triangle_angles_deg(p[0], p[1], p[2]);
    min_angle.values.push_back(std::min({a[0], a[1], a[2]}));
    max_angle.values.push_back(std::max({a[0], a[1], a[2]}));
  }
  t.point_fields.push_back(std::move(marker));
  t.cell_fields.push_back(std::move(min_angle));
  t.cell_fields.push_back(std::move(max_angle));
  return t;
}

CellTable table_of(const DualMesh& dual) {
  CellTable t;
  t.title = "libacute circumcentric dual";
  t.points = dual.points;
  CellField kind{"kind", {}, true};
  for (auto k : dual.point_kinds) kind.values.push_back(static_cast<double>(k));
  CellField vertex{"primal_vertex", {}, true}, boundary{"boundary", {}, true}, area{"area", {}, false};
  for (std::size_t i = 0; i < dual.n_cells(); ++i) {
    t.connectivity.insert(t.connectivity.end(), dual.cells[i].begin(), dual.cells[i].end());
    t.offsets.push_back(static_cast<int>(t.connectivity.size()));
    vertex.values.push_back(dual.cell_vertex[i]);
    boundary.values.push_back(dual.cell_on_boundary[i]);
    area.values.push_back(cell_area(dual, i));
  }
  t.point_fields.push_back(std::move(kind));
  t.cell_fields.push_back(std::move(vertex));
  t.cell_fields.push_back(std::move(boundary));
  t.cell_fields.push_back(std::move(area));
  return t;
}

void write_vtk_table(const CellTable& t, const std::string& path) {
  AtomicFile file(path);
  std::ostream& out = file.stream();
  const std::size_t nc = t.n_cells();
  out << "# vtk DataFile Version 3.0\n" << t.title << "\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out << "POINTS " << t.points.size() << " double\n";
  for (const auto& p : t.points) out << format_double(p.x()) << ' ' << format_double(p.y()) << " 0\n";
  out << "CELLS " << nc << ' ' << nc + t.connectivity.size() << '\n';
  for (std::size_t i = 0; i < nc; ++i) {
    out << t.cell_size(i);
    for (int k = t.offsets[i]; k < t.offsets[i + 1]; ++k) out << ' ' << t.connectivity[k];
    out << '\n';
  }
  out << "CELL_TYPES " << nc << '\n';
  for (std::size_t i = 0; i < nc; ++i) out << vtk_type(t, i) << '\n';
  auto fields = [&](const std::vector<CellField>& list) {
    for (const auto& f : list) {
      out << "SCALARS " << f.name << (f.integer ? " int" : " double") << " 1\nLOOKUP_TABLE default\n";
      for (double x : f.values) out << format_field_value(x, f.integer) << '\n';
    }
  };
  if (!t.cell_fields.empty() && nc > 0) {
    out << "CELL_DATA " << nc << '\n';
    fields(t.cell_fields);
  }
  if (!t.point_fields.empty() && !t.points.empty()) {
    out << "POINT_DATA " << t.points.size() << '\n';
    fields(t.point_fields);
  }
  file.commit();
}

void write_vtu_table(const CellTable& t, const std::string& path) {
  AtomicFile file(path);
  std::ostream& out = file.stream();
  const std::size_t nc = t.n_cells();
  auto array_open = [&](const char* type, const std::string& name, int components) {
    out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\"";
    if (components != 1) out << " NumberOfComponents=\"" << components << "\"";
    out << " format=\"ascii\">\n";
  };
  auto array_close = [&] { out << "        </DataArray>\n"; };
  auto fields = [&](const char* tag, const std::vector<CellField>& list) {
    out << "      <" << tag << '>' << '\n';
    for (const auto& f : list) {
      array_open(f.integer ? "Int32" : "Float64", f.name, 1);
      for (double x : f.values) out << format_field_value(x, f.integer) << '\n';
      array_close();
    }
    out << "      </" << tag << ">\n";
  };
  out << "<?xml version=\"1.0\"?>\n"
      << "<!-- " << t.title << " -->\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << t.points.size() << "\" NumberOfCells=\"" << nc << "\">\n";
  fields("PointData", t.point_fields);
  fields("CellData", t.cell_fields);
  out << "      <Points>\n";
  array_open("Float64", "Points", 3);
  for (const auto& p : t.points) out << format_double(p.x()) << ' ' << format_double(p.y()) << " 0\n";
  array_close();
  out << "      </Points>\n      <Cells>\n";
  array_open("Int64", "connectivity", 1);
  for (std::size_t i = 0; i < nc; ++i) {
    for (int k = t.offsets[i]; k < t.offsets[i + 1]; ++k) out << (k > t.offsets[i] ? " " : "") << t.connectivity[k];
    out << '\n';
  }
  array_close();
  array_open("Int64", "offsets", 1);
  for (std::size_t i = 1; i <= nc; ++i) out << t.offsets[i] << '\n';
  array_close();
  array_open("UInt8", "types", 1);
  for (std::size_t i = 0; i < nc; ++i) out << vtk_type(t, i) << '\n';
  array_close();
  out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  file.commit();
}

}  // namespace detail

void write_vtk(const Mesh& mesh, const std::string& path) { detail::write_vtk_table(detail::table_of(mesh), path); }
void write_vtu(const Mesh& mesh, const std::string& path) { detail::write_vtu_table(detail::table_of(mesh), path); }

}  // namespace acute::io
