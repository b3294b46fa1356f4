// Writers for the exchange formats (.vtk .vtu .msh .ply) and for the dual: the files are read
// back number by number, and by meshio / gmsh when those are installed.
#include "io/io_test_util.h"

#include <acute/io/io.h>
#include <acute/mesh/dual.h>
#include <acute/mesh/quality.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

using namespace acute;
using acute::test::output;

namespace {

// A jittered grid with full-mantissa coordinates and a marker.
Mesh jittered_mesh(int n = 6) {
  Mesh m;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) m.add_vertex(Mesh::Point((i + jitter(rng)) / 3.0, (j + jitter(rng)) / 7.0 - 1e5, 0.0));
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      m.add_face(VertexHandle(a), VertexHandle(b), VertexHandle(d));
      m.add_face(VertexHandle(a), VertexHandle(d), VertexHandle(c));
    }
  m.data(VertexHandle(7)).marker = 3;
  return m;
}

// Equilateral triangles filling a hexagon of side n: well-centred.
Mesh hexagon_mesh(int n) {
  Mesh m;
  std::map<std::pair<int, int>, VertexHandle> at;  // axial coordinates (q, r)
  const double h = std::sqrt(3.0) / 2;
  auto vertex = [&](int q, int r) {
    auto it = at.find({q, r});
    if (it != at.end()) return it->second;
    return at[{q, r}] = m.add_vertex(Mesh::Point(q + 0.5 * r, h * r, 0.0));
  };
  auto inside = [n](int q, int r) { return std::abs(q) <= n && std::abs(r) <= n && std::abs(q + r) <= n; };
  for (int q = -n; q <= n; ++q)
    for (int r = -n; r <= n; ++r) {
      if (inside(q, r) && inside(q + 1, r) && inside(q, r + 1)) m.add_face(vertex(q, r), vertex(q + 1, r), vertex(q, r + 1));
      if (inside(q + 1, r) && inside(q + 1, r + 1) && inside(q, r + 1))
        m.add_face(vertex(q + 1, r), vertex(q + 1, r + 1), vertex(q, r + 1));
    }
  return m;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> tokens_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

// Exact parse (the writers use 17 significant digits).
double num(const std::string& s) { return std::stod(s); }
long long integer(const std::string& s) { return std::stoll(s); }

struct Expected {
  std::vector<Point2> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<double> min_angle, max_angle;
};

Expected expected_of(const Mesh& m) {
  Expected e;
  std::vector<int> number(m.n_vertices(), -1);
  for (auto vh : m.vertices()) {
    number[vh.idx()] = static_cast<int>(e.points.size());
    e.points.push_back(point2(m, vh));
  }
  for (auto fh : m.faces()) {
    std::array<int, 3> t{};
    Point2 p[3];
    int k = 0;
    for (auto fv : m.fv_range(fh)) p[k] = point2(m, fv), t[k++] = number[fv.idx()];
    e.triangles.push_back(t);
    const auto a = triangle_angles_deg(p[0], p[1], p[2]);
    e.min_angle.push_back(std::min({a[0], a[1], a[2]}));
    e.max_angle.push_back(std::max({a[0], a[1], a[2]}));
  }
  return e;
}

// Runs a shell command; its stdout, or nullopt when it failed.
std::optional<std::string> run(const std::string& command) {
  FILE* pipe = popen((command + " 2>/dev/null").c_str(), "r");
  if (!pipe) return std::nullopt;
  std::string out;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  if (pclose(pipe) != 0) return std::nullopt;
  return out;
}

// A python3 that can import meshio (Debian's python3-meshio lives under /usr/bin/python3, which a
// pyenv python3 on PATH may hide), or "".
const std::string& meshio_python() {
  static const std::string found = [] {
    for (const char* py : {"python3", "/usr/bin/python3"})
      if (run(std::string(py) + " -c 'import meshio'")) return std::string(py);
    return std::string();
  }();
  return found;
}

// meshio's view of each file (one python start for all: importing meshio is slow): per path,
// "points cells" then the cell block types, "data name count" per cell data array. A file meshio
// cannot read gets "error ...".
std::map<std::string, std::string> meshio_summaries(const std::vector<std::string>& paths) {
  const std::string script =
      "import sys, meshio\n"
      "for path in sys.argv[1:]:\n"
      "    print('== ' + path)\n"
      "    try:\n"
      "        m = meshio.read(path)\n"
      "    except BaseException as e:\n"
      "        print('error', type(e).__name__, str(e).replace('\\n', ' '))\n"
      "        continue\n"
      "    print(len(m.points), sum(len(c.data) for c in m.cells))\n"
      "    print(' '.join(sorted(set(c.type for c in m.cells))))\n"
      "    for k, v in m.cell_data.items(): print('data', k, sum(len(a) for a in v))\n";
  const std::string script_path = output("formats_meshio.py");
  std::ofstream(script_path) << script;
  std::string command = meshio_python() + " " + script_path;
  for (const auto& p : paths) command += " '" + p + "'";
  std::map<std::string, std::string> out;
  const auto text = run(command);
  if (!text) return out;
  std::istringstream in(*text);
  std::string line, current;
  while (std::getline(in, line)) {
    if (line.rfind("== ", 0) == 0) current = line.substr(3);
    else if (!current.empty() && !line.empty()) out[current] += line + "\n";
  }
  return out;
}

// "points cells" from a summary.
std::pair<std::size_t, std::size_t> counts_of(const std::string& summary) {
  std::istringstream in(summary);
  std::size_t n_points = 0, n_cells = 0;
  in >> n_points >> n_cells;
  return {n_points, n_cells};
}

}  // namespace

TEST(WriteVtk, legacy_file_reads_back_exactly) {
  const Mesh m = jittered_mesh();
  const Expected e = expected_of(m);
  const std::string path = output("formats.vtk");
  io::write_vtk(m, path);
  const auto tok = tokens_of(slurp(path));
  ASSERT_GT(tok.size(), 20u) << path;
  std::size_t i = 0;
  auto find = [&](const std::string& key) {
    while (i < tok.size() && tok[i] != key) ++i;
    return i < tok.size();
  };
  ASSERT_TRUE(find("UNSTRUCTURED_GRID")) << path;
  ASSERT_TRUE(find("POINTS")) << path;
  ASSERT_EQ(integer(tok[i + 1]), static_cast<long long>(e.points.size())) << path;
  EXPECT_EQ(tok[i + 2], "double") << path;
  i += 3;
  for (std::size_t v = 0; v < e.points.size(); ++v, i += 3) {
    EXPECT_EQ(num(tok[i]), e.points[v].x()) << path << " point " << v;
    EXPECT_EQ(num(tok[i + 1]), e.points[v].y()) << path << " point " << v;
    EXPECT_EQ(num(tok[i + 2]), 0.0) << path << " point " << v;
  }
  ASSERT_EQ(tok[i], "CELLS") << path;
  EXPECT_EQ(integer(tok[i + 1]), static_cast<long long>(e.triangles.size())) << path;
  EXPECT_EQ(integer(tok[i + 2]), static_cast<long long>(4 * e.triangles.size())) << path;
  i += 3;
  for (std::size_t f = 0; f < e.triangles.size(); ++f, i += 4) {
    EXPECT_EQ(tok[i], "3") << path << " cell " << f;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(integer(tok[i + 1 + k]), e.triangles[f][k]) << path << " cell " << f;
  }
  ASSERT_EQ(tok[i], "CELL_TYPES") << path;
  i += 2;
  for (std::size_t f = 0; f < e.triangles.size(); ++f) EXPECT_EQ(tok[i++], "5") << path << " cell type " << f;
  ASSERT_EQ(tok[i], "CELL_DATA") << path;
  for (const auto& [name, values] : {std::pair{"min_angle", &e.min_angle}, std::pair{"max_angle", &e.max_angle}}) {
    ASSERT_TRUE(find("SCALARS")) << path << " " << name;
    EXPECT_EQ(tok[i + 1], name) << path;
    i += 6;  // SCALARS name double 1 LOOKUP_TABLE default
    for (std::size_t f = 0; f < values->size(); ++f) EXPECT_EQ(num(tok[i++]), (*values)[f]) << path << " " << name << " " << f;
  }
  ASSERT_TRUE(find("POINT_DATA")) << path;
  ASSERT_TRUE(find("marker")) << path;
  EXPECT_EQ(tok[i + 5 + 7], "3") << path << " marker of vertex 7";
}

TEST(WriteVtu, xml_file_reads_back_exactly) {
  const Mesh m = jittered_mesh();
  const Expected e = expected_of(m);
  const std::string path = output("formats.vtu");
  io::write_vtu(m, path);
  const std::string text = slurp(path);
  EXPECT_NE(text.find("<VTKFile type=\"UnstructuredGrid\""), std::string::npos) << path;
  // The numbers inside the DataArray named `name`.
  auto array = [&](const std::string& name) {
    const auto at = text.find("Name=\"" + name + "\"");
    EXPECT_NE(at, std::string::npos) << path << " lacks " << name;
    if (at == std::string::npos) return std::vector<std::string>{};
    const auto begin = text.find('>', at) + 1, end = text.find("</DataArray>", begin);
    return tokens_of(text.substr(begin, end - begin));
  };
  const auto pts = array("Points");
  ASSERT_EQ(pts.size(), 3 * e.points.size()) << path;
  for (std::size_t v = 0; v < e.points.size(); ++v) {
    EXPECT_EQ(num(pts[3 * v]), e.points[v].x()) << path << " point " << v;
    EXPECT_EQ(num(pts[3 * v + 1]), e.points[v].y()) << path << " point " << v;
  }
  const auto conn = array("connectivity"), offs = array("offsets"), types = array("types");
  ASSERT_EQ(conn.size(), 3 * e.triangles.size()) << path;
  ASSERT_EQ(offs.size(), e.triangles.size()) << path;
  ASSERT_EQ(types.size(), e.triangles.size()) << path;
  for (std::size_t f = 0; f < e.triangles.size(); ++f) {
    EXPECT_EQ(integer(offs[f]), static_cast<long long>(3 * (f + 1))) << path << " offset " << f;
    EXPECT_EQ(types[f], "5") << path << " type " << f;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(integer(conn[3 * f + k]), e.triangles[f][k]) << path << " cell " << f;
  }
  const auto lo = array("min_angle"), hi = array("max_angle");
  ASSERT_EQ(lo.size(), e.triangles.size()) << path;
  ASSERT_EQ(hi.size(), e.triangles.size()) << path;
  for (std::size_t f = 0; f < e.triangles.size(); ++f) {
    EXPECT_EQ(num(lo[f]), e.min_angle[f]) << path << " min_angle " << f;
    EXPECT_EQ(num(hi[f]), e.max_angle[f]) << path << " max_angle " << f;
  }
}

TEST(WriteMsh, gmsh41_file_reads_back_exactly) {
  const Mesh m = jittered_mesh();
  const Expected e = expected_of(m);
  const std::string path = output("formats.msh");
  io::write_msh(m, path);
  const auto tok = tokens_of(slurp(path));
  std::size_t i = 0;
  auto find = [&](const std::string& key) {
    while (i < tok.size() && tok[i] != key) ++i;
    return i++ < tok.size();
  };
  ASSERT_TRUE(find("$MeshFormat")) << path;
  EXPECT_EQ(tok[i] + " " + tok[i + 1] + " " + tok[i + 2], "4.1 0 8") << path;
  ASSERT_TRUE(find("$Nodes")) << path;
  const long long nv = static_cast<long long>(e.points.size()), nf = static_cast<long long>(e.triangles.size());
  EXPECT_EQ(integer(tok[i]), 1) << path << " node blocks";
  EXPECT_EQ(integer(tok[i + 1]), nv) << path;
  EXPECT_EQ(integer(tok[i + 3]), nv) << path << " max node tag";
  EXPECT_EQ(integer(tok[i + 4]), 2) << path << " entity dimension";
  EXPECT_EQ(integer(tok[i + 7]), nv) << path << " nodes in block";
  i += 8;
  for (long long v = 0; v < nv; ++v) EXPECT_EQ(integer(tok[i + v]), v + 1) << path << " node tag " << v;
  i += nv;
  for (long long v = 0; v < nv; ++v, i += 3) {
    EXPECT_EQ(num(tok[i]), e.points[v].x()) << path << " node " << v + 1;
    EXPECT_EQ(num(tok[i + 1]), e.points[v].y()) << path << " node " << v + 1;
  }
  EXPECT_EQ(tok[i++], "$EndNodes") << path;
  ASSERT_TRUE(find("$Elements")) << path;
  EXPECT_EQ(integer(tok[i + 1]), nf) << path;
  EXPECT_EQ(integer(tok[i + 6]), 2) << path << " element type (3-node triangle)";
  EXPECT_EQ(integer(tok[i + 7]), nf) << path;
  i += 8;
  for (long long f = 0; f < nf; ++f, i += 4) {
    EXPECT_EQ(integer(tok[i]), f + 1) << path << " element " << f + 1;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(integer(tok[i + 1 + k]), e.triangles[f][k] + 1) << path << " element " << f + 1;
  }
  EXPECT_EQ(tok[i], "$EndElements") << path;
  ASSERT_TRUE(find("$ElementData")) << path;
  EXPECT_EQ(tok[i + 1], "\"min_angle\"") << path;
  i += 8;
  EXPECT_EQ(integer(tok[i - 1]), nf) << path;
  for (long long f = 0; f < nf; ++f, i += 2) EXPECT_EQ(num(tok[i + 1]), e.min_angle[f]) << path << " min_angle " << f + 1;
}

TEST(WritePly, ascii_double_file_reads_back_exactly) {
  const Mesh m = jittered_mesh();
  const Expected e = expected_of(m);
  const std::string path = output("formats.ply");
  io::write_mesh(m, path);
  EXPECT_NE(slurp(path).find("format ascii 1.0"), std::string::npos) << path;
  EXPECT_NE(slurp(path).find("property double x"), std::string::npos) << path;
  const Mesh back = io::read_mesh(path);
  const Expected b = expected_of(back);
  ASSERT_EQ(b.points.size(), e.points.size()) << path;
  ASSERT_EQ(b.triangles.size(), e.triangles.size()) << path;
  for (std::size_t v = 0; v < e.points.size(); ++v) EXPECT_EQ(b.points[v], e.points[v]) << path << " vertex " << v;
  for (std::size_t f = 0; f < e.triangles.size(); ++f) EXPECT_EQ(b.triangles[f], e.triangles[f]) << path << " face " << f;
}

TEST(WriteMesh, dispatches_new_extensions_and_stays_atomic) {
  const Mesh m = jittered_mesh(3);
  const std::string dir = output("formats_dispatch");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (const char* ext : {".vtk", ".vtu", ".msh", ".ply", ".VTK"}) {
    const std::string path = dir + "/m" + ext;
    EXPECT_TRUE(io::is_mesh_output_path(path)) << path;
    io::write_mesh(m, path);
    EXPECT_TRUE(std::filesystem::exists(path)) << path;
  }
  EXPECT_FALSE(io::is_mesh_output_path("m.stl")) << "m.stl";
  acute::test::expect_error<IoError>([&] { io::write_mesh(m, dir + "/m.stl"); }, {"m.stl", ".msh"}, "m.stl");
  acute::test::expect_error<IoError>([&] { io::write_vtk(m, dir + "/missing/m.vtk"); }, {"missing"}, "missing dir");
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST(WriteMesh, empty_mesh_gives_valid_files) {
  const Mesh m;
  for (const char* ext : {".vtk", ".vtu", ".msh", ".ply"}) {
    const std::string path = output(std::string("formats_empty") + ext);
    io::write_mesh(m, path);
    EXPECT_FALSE(slurp(path).empty()) << path;
  }
  EXPECT_NE(slurp(output("formats_empty.msh")).find("$Nodes\n0 0 0 0\n$EndNodes"), std::string::npos);
}

TEST(WriteDual, polygon_files_read_back) {
  const Mesh m = hexagon_mesh(2);
  const DualMesh dual = circumcentric_dual(m);
  const std::string off = output("formats_dual.off");
  io::write_dual(dual, off);
  const auto tok = tokens_of(slurp(off));
  // OFF, "#", comment words..., counts
  std::size_t i = 0;
  while (i < tok.size() && tok[i] != std::to_string(dual.n_points())) ++i;
  ASSERT_LT(i + 2, tok.size()) << off;
  EXPECT_EQ(integer(tok[i + 1]), static_cast<long long>(dual.n_cells())) << off;
  i += 3;
  for (std::size_t p = 0; p < dual.n_points(); ++p, i += 3) {
    EXPECT_EQ(num(tok[i]), dual.points[p].x()) << off << " point " << p;
    EXPECT_EQ(num(tok[i + 1]), dual.points[p].y()) << off << " point " << p;
  }
  for (std::size_t c = 0; c < dual.n_cells(); ++c) {
    ASSERT_EQ(integer(tok[i++]), static_cast<long long>(dual.cells[c].size())) << off << " cell " << c;
    for (int v : dual.cells[c]) EXPECT_EQ(integer(tok[i++]), v) << off << " cell " << c;
  }
  for (const char* ext : {".obj", ".ply", ".vtk", ".vtu", ".svg"}) {
    const std::string path = output(std::string("formats_dual") + ext);
    EXPECT_TRUE(io::is_dual_output_path(path)) << path;
    io::write_dual(dual, path, &m);
    EXPECT_TRUE(std::filesystem::exists(path)) << path;
  }
  const std::string vtk = slurp(output("formats_dual.vtk"));
  EXPECT_NE(vtk.find("\n7\n"), std::string::npos) << "dual .vtk has polygon cells (type 7)";
  EXPECT_NE(vtk.find("SCALARS area double"), std::string::npos) << "dual .vtk has cell areas";
  EXPECT_FALSE(io::is_dual_output_path("d.msh")) << "d.msh";
  acute::test::expect_error<IoError>([&] { io::write_dual(dual, output("d.msh")); }, {"d.msh"}, "d.msh");
}

TEST(Meshio, reads_our_files_with_same_counts) {
  if (meshio_python().empty()) GTEST_SKIP() << "python3 with meshio not found (apt-get install python3-meshio)";
  const Mesh m = jittered_mesh();
  const Expected e = expected_of(m);
  const Mesh hex = hexagon_mesh(3);
  const DualMesh dual = circumcentric_dual(hex);
  std::vector<std::string> mesh_paths, dual_paths;
  for (const char* ext : {".vtk", ".vtu", ".msh", ".ply"}) {
    mesh_paths.push_back(output(std::string("formats_meshio") + ext));
    io::write_mesh(m, mesh_paths.back());
  }
  for (const char* ext : {".vtk", ".vtu", ".obj", ".ply"}) {
    dual_paths.push_back(output(std::string("formats_meshio_dual") + ext));
    io::write_dual(dual, dual_paths.back(), &hex);
  }
  std::vector<std::string> all = mesh_paths;
  all.insert(all.end(), dual_paths.begin(), dual_paths.end());
  const auto summaries = meshio_summaries(all);
  for (const auto& path : mesh_paths) {
    ASSERT_TRUE(summaries.count(path)) << "meshio did not run on " << path;
    const std::string& s = summaries.at(path);
    const auto [n_points, n_cells] = counts_of(s);
    EXPECT_EQ(n_points, e.points.size()) << path << ": " << s;
    EXPECT_EQ(n_cells, e.triangles.size()) << path << ": " << s;
    EXPECT_NE(s.find("\ntriangle\n"), std::string::npos) << path << ": " << s;
    EXPECT_NE(s.find("data min_angle " + std::to_string(e.triangles.size())), std::string::npos) << path << ": " << s;
  }
  for (const auto& path : dual_paths) {
    ASSERT_TRUE(summaries.count(path)) << "meshio did not run on " << path;
    const std::string& s = summaries.at(path);
    const auto [n_points, n_cells] = counts_of(s);
    EXPECT_EQ(n_points, dual.n_points()) << path << ": " << s;
    EXPECT_EQ(n_cells, dual.n_cells()) << path << ": " << s;
  }
  // meshio 5 drops the cell data of polygon cells in legacy VTK files, but reads it from .vtu.
  EXPECT_NE(summaries.at(dual_paths[1]).find("data area " + std::to_string(dual.n_cells())), std::string::npos)
      << dual_paths[1] << ": " << summaries.at(dual_paths[1]);
}

TEST(Gmsh, opens_msh_file) {
  if (!run("gmsh --version")) GTEST_SKIP() << "gmsh not on PATH";
  const Mesh m = jittered_mesh();
  const std::string path = output("formats_gmsh.msh"), again = output("formats_gmsh_again.msh");
  io::write_msh(m, path);
  std::filesystem::remove(again);
  const auto log = run("gmsh -v 2 '" + path + "' -0 -format msh41 -o '" + again + "'");
  ASSERT_TRUE(log) << "gmsh failed on " << path;
  // gmsh's own re-export has the same numbers of nodes and triangles.
  const auto tok = tokens_of(slurp(again));
  std::size_t i = 0;
  while (i < tok.size() && tok[i] != "$Nodes") ++i;
  ASSERT_LT(i + 2, tok.size()) << again;
  EXPECT_EQ(integer(tok[i + 2]), static_cast<long long>(m.n_vertices())) << again;
  while (i < tok.size() && tok[i] != "$Elements") ++i;
  ASSERT_LT(i + 2, tok.size()) << again;
  EXPECT_EQ(integer(tok[i + 2]), static_cast<long long>(m.n_faces())) << again;
}
