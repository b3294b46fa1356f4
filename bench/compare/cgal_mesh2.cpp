// Benchmark driver: CGAL Mesh_2 on a Triangle .poly, written as OFF (17 digits).
//   cgal_mesh2 IN.poly OUT.off --angle DEG --size S [--lloyd ITER]
// Refinement with Delaunay_mesh_size_criteria_2(B = sin^2(angle), S) (S bounds the longest edge),
// then optionally lloyd_optimize_mesh_2. Prints one JSON line: timings (mesh / lloyd) and counts.
// Only the bench uses CGAL; the library never does.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/lloyd_optimize_mesh_2.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Point = K::Point_2;

struct Poly {
  std::vector<Point> points;
  std::vector<std::pair<int, int>> segments;  // 0-based
  std::vector<Point> holes;
};

// Next non-comment, non-empty line split into tokens.
bool next_tokens(std::istream& in, std::vector<std::string>& tok) {
  std::string line;
  while (std::getline(in, line)) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream ss(line);
    tok.clear();
    for (std::string t; ss >> t;) tok.push_back(t);
    if (!tok.empty()) return true;
  }
  return false;
}

[[noreturn]] void fail(const std::string& msg) {
  std::cerr << "cgal_mesh2: " << msg << "\n";
  std::exit(2);
}

Poly read_poly(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail(path + ": cannot open");
  Poly p;
  std::vector<std::string> t;
  if (!next_tokens(in, t)) fail(path + ": empty");
  const long nv = std::stol(t[0]);
  if (nv == 0) fail(path + ": vertices in a .node file are not supported");
  std::map<long, int> index;  // file numbering (0- or 1-based) -> position
  for (long i = 0; i < nv; ++i) {
    if (!next_tokens(in, t) || t.size() < 3) fail(path + ": bad vertex line");
    index[std::stol(t[0])] = static_cast<int>(p.points.size());
    p.points.emplace_back(std::strtod(t[1].c_str(), nullptr), std::strtod(t[2].c_str(), nullptr));
  }
  if (!next_tokens(in, t)) fail(path + ": missing segments");
  const long ns = std::stol(t[0]);
  for (long i = 0; i < ns; ++i) {
    if (!next_tokens(in, t) || t.size() < 3) fail(path + ": bad segment line");
    p.segments.emplace_back(index.at(std::stol(t[1])), index.at(std::stol(t[2])));
  }
  if (next_tokens(in, t)) {
    const long nh = std::stol(t[0]);
    for (long i = 0; i < nh; ++i) {
      if (!next_tokens(in, t) || t.size() < 3) fail(path + ": bad hole line");
      p.holes.emplace_back(std::strtod(t[1].c_str(), nullptr), std::strtod(t[2].c_str(), nullptr));
    }
  }
  return p;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) fail("usage: cgal_mesh2 IN.poly OUT.off --angle DEG --size S [--lloyd ITER]");
  const std::string in_path = argv[1], out_path = argv[2];
  double angle = 20.7, size = 0;
  int lloyd = 0;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--angle") angle = std::atof(argv[i + 1]);
    else if (a == "--size") size = std::atof(argv[i + 1]);
    else if (a == "--lloyd") lloyd = std::atoi(argv[i + 1]);
    else fail("unknown option " + a);
  }
  const auto t_start = std::chrono::steady_clock::now();
  const Poly poly = read_poly(in_path);

  const auto t0 = std::chrono::steady_clock::now();
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  handles.reserve(poly.points.size());
  for (const Point& q : poly.points) handles.push_back(cdt.insert(q));
  for (const auto& [a, b] : poly.segments)
    if (handles[a] != handles[b]) cdt.insert_constraint(handles[a], handles[b]);
  const double sb = std::sin(angle * M_PI / 180.0);
  CGAL::refine_Delaunay_mesh_2(cdt, poly.holes.begin(), poly.holes.end(), Criteria(sb * sb, size));
  const double t_mesh = seconds_since(t0);

  double t_lloyd = 0;
  if (lloyd > 0) {
    const auto t1 = std::chrono::steady_clock::now();
    CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = lloyd,
                                CGAL::parameters::seeds_begin = poly.holes.begin(),
                                CGAL::parameters::seeds_end = poly.holes.end());
    t_lloyd = seconds_since(t1);
  }

  // Only faces in the domain, only the vertices they use.
  std::map<Cdt::Vertex_handle, long> id;
  std::vector<std::array<long, 3>> tris;
  std::vector<Point> verts;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    std::array<long, 3> t{};
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] = id.emplace(f->vertex(k), static_cast<long>(verts.size()));
      if (fresh) verts.push_back(f->vertex(k)->point());
      t[k] = it->second;
    }
    tris.push_back(t);
  }
  std::FILE* out = std::fopen(out_path.c_str(), "w");
  if (!out) fail(out_path + ": cannot write");
  std::fprintf(out, "OFF\n%zu %zu 0\n", verts.size(), tris.size());
  for (const Point& q : verts) std::fprintf(out, "%.17g %.17g 0\n", q.x(), q.y());
  for (const auto& t : tris) std::fprintf(out, "3 %ld %ld %ld\n", t[0], t[1], t[2]);
  std::fclose(out);
  std::printf("{\"n_vertices\": %zu, \"n_triangles\": %zu, \"mesh_s\": %.6f, \"lloyd_s\": %.6f, \"total_s\": %.6f}\n", verts.size(),
              tris.size(), t_mesh, t_lloyd, seconds_since(t_start));
  return 0;
}
