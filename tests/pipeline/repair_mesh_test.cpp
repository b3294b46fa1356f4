// acute::repair_mesh / repair() / repair_required_points: the region is kept, the bounds are met,
// invalid meshes are refused with a message naming the element.
#include <acute/core/errors.h>
#include <acute/io/io.h>
#include <acute/mesh/boundary.h>
#include <acute/mesh/check.h>
#include <acute/mesh/geometry.h>
#include <acute/predicates/predicates.h>
#include <acute/repair/repair.h>
#include <acute/repair_mesh.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include "support/cgshop_samples.h"
#include "support/paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace acute {
namespace {

namespace fs = std::filesystem;

double area_of(const Mesh& m) {
  double a = 0;
  for (auto fh : m.faces()) {
    const auto p = face_points(m, fh);
    a += 0.5 * signed_area2(p[0], p[1], p[2]);
  }
  return a;
}

double boundary_length(const Mesh& m) {
  double len = 0;
  for (auto eh : m.edges())
    if (m.is_boundary(eh)) len += m.calc_edge_length(eh);
  return len;
}

std::set<std::pair<double, double>> vertex_set(const Mesh& m, bool boundary_only) {
  std::set<std::pair<double, double>> s;
  for (auto vh : m.vertices())
    if (!m.is_isolated(vh) && (!boundary_only || m.is_boundary(vh))) s.insert({m.point(vh)[0], m.point(vh)[1]});
  return s;
}

/// Empty when `out` is a valid triangulation of the region of `in` that keeps its boundary
/// vertices (and, with all_vertices, every vertex); else the first problem.
std::string conforms(const Mesh& in, const Mesh& out, bool all_vertices) {
  const CheckReport r = check_mesh(out, CheckLevel::Geometry);
  if (!r.ok()) return "invalid: " + r.summary(1);
  const double a0 = area_of(in), a1 = area_of(out);
  if (std::abs(a1 - a0) > 1e-9 * a0) return "area " + std::to_string(a1) + " != " + std::to_string(a0);
  const double l0 = boundary_length(in), l1 = boundary_length(out);
  if (std::abs(l1 - l0) > 1e-9 * l0) return "boundary length " + std::to_string(l1) + " != " + std::to_string(l0);
  const auto have = vertex_set(out, false);
  for (const auto& p : vertex_set(in, !all_vertices))
    if (!have.count(p)) return "input vertex (" + std::to_string(p.first) + ", " + std::to_string(p.second) + ") missing";
  return {};
}

/// Number of triangles with an exactly obtuse angle.
std::size_t exact_obtuse(const Mesh& m) {
  std::size_t n = 0;
  for (auto fh : m.faces()) {
    const auto p = face_points(m, fh);
    bool obtuse = false;
    for (int k = 0; k < 3; ++k)
      obtuse = obtuse || predicates::angle_kind(p[k], p[(k + 1) % 3], p[(k + 2) % 3]) == AngleKind::Obtuse;
    n += obtuse;
  }
  return n;
}

Mesh make_mesh(const std::vector<Point2>& pts, const std::vector<std::array<int, 3>>& tris) {
  Mesh m;
  for (const auto& p : pts) m.add_vertex(Mesh::Point(p.x(), p.y(), 0));
  for (const auto& t : tris) m.add_face(VertexHandle(t[0]), VertexHandle(t[1]), VertexHandle(t[2]));
  return m;
}

/// A 10 x 1 rectangle whose top and bottom are split into n pieces, triangulated as a zig-zag of
/// needles (every triangle uses a bottom vertex and the far top corner fan): many angles near 0 and 180.
Mesh needle_mesh(int n) {
  std::vector<Point2> pts;
  for (int i = 0; i <= n; ++i) pts.emplace_back(10.0 * i / n, 0.0);
  pts.emplace_back(10.0, 1.0);
  pts.emplace_back(0.0, 1.0);
  std::vector<std::array<int, 3>> tris;
  const int tr = n + 1, tl = n + 2;
  for (int i = 0; i < n; ++i) tris.push_back({i, i + 1, tl});  // fan from the top-left corner
  tris.push_back({n, tr, tl});
  return make_mesh(pts, tris);
}

/// A jittered 6 x 6 grid triangulated along the "wrong" diagonals (not Delaunay), with a few
/// interior points pushed close to edges: valid, ugly, badly graded.
Mesh ugly_mesh() {
  const int n = 6;
  std::vector<Point2> pts;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = i, y = j;
      if (i > 0 && i < n && j > 0 && j < n) {
        x += 0.35 * std::sin(3.1 * i + 7.7 * j);
        y += 0.35 * std::cos(5.3 * i + 1.9 * j);
      }
      pts.emplace_back(x * (1 + 0.15 * x), y);  // graded in x
    }
  std::vector<std::array<int, 3>> tris;
  auto at = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      const Point2 &pa = pts[a], &pb = pts[b], &pc = pts[c], &pd = pts[d];
      // pick the diagonal that makes the worse (non-Delaunay) pair, when both are valid
      const bool ac_ok = predicates::orient2d(pa, pb, pc) == Sign::Positive && predicates::orient2d(pa, pc, pd) == Sign::Positive;
      const bool bd_ok = predicates::orient2d(pa, pb, pd) == Sign::Positive && predicates::orient2d(pb, pc, pd) == Sign::Positive;
      const bool use_ac = ac_ok && (!bd_ok || predicates::incircle(pa, pb, pc, pd) == Sign::Positive);
      if (use_ac) {
        tris.push_back({a, b, c});
        tris.push_back({a, c, d});
      } else {
        tris.push_back({a, b, d});
        tris.push_back({b, c, d});
      }
    }
  return make_mesh(pts, tris);
}

void expect_repaired(const Mesh& in, const RepairMeshResult& r, const std::string& name, bool expect_bounds = true) {
  EXPECT_EQ(conforms(in, r.mesh, false), "") << name;
  if (expect_bounds) {
    EXPECT_EQ(r.status, RepairMeshStatus::Ok) << name << ": " << r.n_bad << " bad triangles left";
    EXPECT_EQ(r.n_bad, 0u) << name;
    EXPECT_GE(r.min_angle_deg, 30.0 - 1e-9) << name;
    EXPECT_LT(r.max_angle_deg, 90.0) << name;
  }
}

TEST(RepairMesh, needle_fan_becomes_acute_with_boundary_kept) {
  const Mesh in = needle_mesh(20);
  ASSERT_TRUE(check_mesh(in).ok()) << "needle input";
  const RepairMeshResult r = repair_mesh(in);
  expect_repaired(in, r, "needle_mesh(20)");
}

TEST(RepairMesh, non_delaunay_ugly_mesh_becomes_acute) {
  const Mesh in = ugly_mesh();
  ASSERT_TRUE(check_mesh(in).ok()) << "ugly input: " << check_mesh(in).summary();
  ASSERT_FALSE(check_mesh(in, CheckLevel::Delaunay).ok()) << "ugly input should not be Delaunay";
  const RepairMeshResult r = repair_mesh(in);
  expect_repaired(in, r, "ugly_mesh");
}

/// The unit square as an n x n grid of right triangles (every one has a 90-degree angle).
Mesh grid_mesh(int n) {
  std::vector<Point2> pts;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) pts.emplace_back(static_cast<double>(i) / n, static_cast<double>(j) / n);
  std::vector<std::array<int, 3>> tris;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      tris.push_back({a, b, c});
      tris.push_back({a, c, d});
    }
  return make_mesh(pts, tris);
}

TEST(RepairMesh, fine_input_keeps_its_resolution) {
  // 961 vertices; the feature-graded field alone (a square has no small feature) gives about 400:
  // a repair must not coarsen what the user made fine, nor inflate it.
  const Mesh in = grid_mesh(30);
  const RepairMeshResult r = repair_mesh(in);
  expect_repaired(in, r, "grid_mesh(30)");
  EXPECT_GE(r.n_vertices, in.n_vertices() * 8 / 10);
  EXPECT_LE(r.n_vertices, in.n_vertices() * 13 / 10);
}

/// A hexagon of side r cut into equilateral triangles (every angle 60 degrees); `push` moves the
/// first interior vertex right by that much (a few triangles become obtuse).
Mesh hexagon_lattice(int r, double push = 0) {
  std::vector<Point2> pts;
  std::map<std::pair<int, int>, int> index;
  for (int b = -r; b <= r; ++b)
    for (int a = -r; a <= r; ++a)
      if (std::abs(a + b) <= r) {
        index[{a, b}] = static_cast<int>(pts.size());
        pts.emplace_back(a + 0.5 * b, b * std::sqrt(3.0) / 2.0);
      }
  if (push != 0) pts[index.at({0, 0})] += Point2(push, 0.0);
  std::vector<std::array<int, 3>> tris;
  auto add = [&](std::pair<int, int> x, std::pair<int, int> y, std::pair<int, int> z) {
    if (index.count(x) && index.count(y) && index.count(z)) tris.push_back({index[x], index[y], index[z]});
  };
  for (int b = -r; b <= r; ++b)
    for (int a = -r; a <= r; ++a) {
      add({a, b}, {a + 1, b}, {a, b + 1});
      add({a + 1, b}, {a + 1, b + 1}, {a, b + 1});
    }
  return make_mesh(pts, tris);
}

/// The faces as vertex index triples, each rotated to start at its smallest index.
std::set<std::array<int, 3>> face_triples(const Mesh& m) {
  std::set<std::array<int, 3>> out;
  for (auto fh : m.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (auto v : m.fv_range(fh)) t[static_cast<std::size_t>(k++)] = v.idx();
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.insert(t);
  }
  return out;
}

bool same_vertices_and_faces(const Mesh& a, const Mesh& b) {
  if (a.n_vertices() != b.n_vertices() || a.n_faces() != b.n_faces()) return false;
  for (auto vh : a.vertices())
    if (point2(a, vh) != point2(b, vh)) return false;
  return face_triples(a) == face_triples(b);
}

TEST(RepairMesh, an_input_within_the_bounds_comes_back_unchanged) {
  const Mesh in = hexagon_lattice(3);
  RepairMeshOptions o;
  o.features = {{0, 1}};  // a boundary edge given as a feature changes nothing
  RepairMeshResult r = repair_mesh(in, o);
  expect_repaired(in, r, "hexagon_lattice(3)");
  EXPECT_TRUE(same_vertices_and_faces(in, r.mesh));
  EXPECT_EQ(r.iterations, 0);
  // Tighter bounds than its 60 degrees: it is remeshed.
  o.min_angle_deg = 61;
  o.max_angle_deg = 89;
  EXPECT_THROW(repair_mesh(in, o), InvalidInput);  // unsatisfiable: some angle is <= 60
  // A size asked for: remeshed at that size.
  RepairMeshOptions sized;
  sized.size = 0.25;
  r = repair_mesh(in, sized);
  expect_repaired(in, r, "hexagon_lattice(3) at size 0.25");
  EXPECT_GT(r.n_vertices, 4 * in.n_vertices());
}

TEST(RepairMesh, a_repair_cut_short_never_returns_worse_than_its_input) {
  const Mesh in = hexagon_lattice(4, 0.6);
  AngleBounds bounds;
  Mesh marked = in;
  mark_boundary_as_constrained(marked);
  const std::size_t bad_in = bad_triangles(marked, bounds).size();
  ASSERT_GT(bad_in, 0u);
  ASSERT_LT(bad_in, 6u);
  RepairMeshOptions o;
  o.time_limit_s = 1e-9;  // the start is the CDT of the boundary, far worse than the input
  const RepairMeshResult r = repair_mesh(in, o);
  expect_repaired(in, r, "hexagon_lattice(4, 0.6) cut short", false);
  EXPECT_EQ(r.status, RepairMeshStatus::BoundsNotMet);
  EXPECT_EQ(r.n_bad, bad_in);
  EXPECT_TRUE(same_vertices_and_faces(in, r.mesh));
  // Without the limit it is repaired.
  expect_repaired(in, repair_mesh(in), "hexagon_lattice(4, 0.6)");
}

TEST(RepairMesh, a_nearly_good_input_is_repaired_in_place) {
  const Mesh in = hexagon_lattice(8, 0.6);  // 384 triangles, a few bad around the pushed vertex
  const RepairMeshResult r = repair_mesh(in);
  expect_repaired(in, r, "hexagon_lattice(8, 0.6)");
  // The rest of the lattice is kept: nearly every input vertex is still there.
  const auto before = vertex_set(in, false), after = vertex_set(r.mesh, false);
  std::size_t kept = 0;
  for (const auto& p : before) kept += after.count(p);
  EXPECT_GE(kept + 8, before.size());
  EXPECT_LE(r.n_vertices, in.n_vertices() + 8);
  bool in_place = false;
  for (const auto& note : r.notes) in_place = in_place || note.find("in place") != std::string::npos;
  EXPECT_TRUE(in_place);
}

TEST(RepairMesh, interior_feature_edges_are_kept) {
  const Mesh in = ugly_mesh();
  // a polyline of interior edges through the middle row
  RepairMeshOptions o;
  const int n = 6;
  for (int i = 0; i < n; ++i) o.features.push_back({3 * (n + 1) + i, 3 * (n + 1) + i + 1});
  const RepairMeshResult r = repair_mesh(in, o);
  expect_repaired(in, r, "ugly_mesh with features");
  // every feature vertex is kept, and each feature edge is covered by constrained edges
  const auto have = vertex_set(r.mesh, false);
  for (const auto& f : o.features)
    for (int v : f) EXPECT_TRUE(have.count({in.point(VertexHandle(v))[0], in.point(VertexHandle(v))[1]})) << "feature vertex " << v;
  double constrained = 0, expected = 0;
  for (auto eh : r.mesh.edges())
    if (is_constrained(r.mesh, eh) && !r.mesh.is_boundary(eh)) constrained += r.mesh.calc_edge_length(eh);
  for (const auto& f : o.features) expected += (in.point(VertexHandle(f[0])) - in.point(VertexHandle(f[1]))).norm();
  EXPECT_NEAR(constrained, expected, 1e-9 * expected) << "interior constrained length";
}

TEST(RepairMesh, feature_angle_merges_collinear_boundary_vertices) {
  const Mesh in = needle_mesh(20);  // 19 collinear vertices inside the bottom edge
  RepairMeshOptions o;
  o.feature_angle_deg = 1;
  std::vector<int> vop;
  const Domain d = repair_domain(in, o, &vop);
  EXPECT_EQ(d.points.size(), 4u) << "only the rectangle's corners stay";
  EXPECT_EQ(d.segments.size(), 4u);
  const RepairMeshResult r = repair_mesh(in, o);
  EXPECT_EQ(r.status, RepairMeshStatus::Ok) << "needle with --feature-angle 1";
  const double a0 = area_of(in), a1 = area_of(r.mesh);
  EXPECT_NEAR(a1, a0, 1e-9 * a0) << "region unchanged (the run is exactly straight)";
}

// Meshes whose region touches itself at a vertex (as gmsh and CGAL write the fish domains): read,
// repaired to the bounds with the pinch vertex kept where the loops meet, written and read back.
TEST(RepairMesh, pinch_vertex_meshes_are_repaired_and_keep_the_pinch) {
  struct Case {
    const char* file;
    Point2 pinch;
  };
  for (const Case& c : {Case{"pinch_squares.off", Point2(1, 1)}, Case{"pinch_hole.off", Point2(2, 0)}})
    for (double feature : {0.0, 10.0}) {
      const std::string name = std::string(c.file) + " --feature-angle " + std::to_string(feature);
      const Mesh in = io::read_mesh(std::string(acute::test::test_data_dir()) + "/" + c.file);
      RepairMeshOptions o;
      o.feature_angle_deg = feature;
      const RepairMeshResult r = repair_mesh(in, o);
      expect_repaired(in, r, name);
      const auto path = (fs::path(acute::test::test_output_dir()) / ("repaired_" + std::string(c.file))).string();
      io::write_mesh(r.mesh, path);
      const Mesh back = io::read_mesh(path);
      EXPECT_EQ(conforms(in, back, false), "") << name << ", read back";
      int pinches = 0;
      for (auto vh : back.vertices())
        if (is_pinch_vertex(back, vh)) {
          ++pinches;
          EXPECT_EQ(point2(back, vh), c.pinch) << name;
        }
      EXPECT_EQ(pinches, 1) << name;
      EXPECT_EQ(simple_boundary_loops(back).size(), 2u) << name;
    }
}

TEST(RepairMesh, shared_meshes_conform_and_meet_the_bounds) {
  const fs::path dir = fs::path(acute::test::shared_dir()) / "domains" / "meshes";
  if (!fs::is_directory(dir)) GTEST_SKIP() << dir << " absent";
  int n = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string path = entry.path().string();
    if (!entry.is_regular_file() || !io::is_mesh_path(path)) continue;
    const std::string name = entry.path().filename().string();
    const Mesh in = io::read_mesh(path);
    if (in.n_vertices() > 3000) continue;  // large ones (greenland, bump-domain, circle): the CLI sweep covers them
    RepairMeshOptions o;
    o.time_limit_s = 20;
    const RepairMeshResult r = repair_mesh(in, o);
    EXPECT_EQ(conforms(in, r.mesh, false), "") << name;
    EXPECT_EQ(r.n_bad, 0u) << name << ": bounds not met, angles " << r.min_angle_deg << ".." << r.max_angle_deg;
    ++n;
  }
  EXPECT_GE(n, 5) << "meshes repaired from " << dir;
}

// --- invalid input -------------------------------------------------------------------------

std::string repair_error(const Mesh& m) {
  try {
    repair_mesh(m);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(RepairMeshInvalid, overlapping_squares_are_refused) {
  // two unit squares, the second shifted by (0.5, 0.5): boundaries cross
  const Mesh m = make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}},
                           {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}});
  const std::string msg = repair_error(m);
  EXPECT_NE(msg.find("crosses"), std::string::npos) << msg;
  EXPECT_NE(msg.find("edge"), std::string::npos) << msg;
}

TEST(RepairMeshInvalid, nested_square_covered_twice_is_refused) {
  // a small square mesh lying inside a big one, both counter-clockwise: covered twice
  const Mesh m = make_mesh({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {2, 1}, {2, 2}, {1, 2}},
                           {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}});
  const std::string msg = repair_error(m);
  EXPECT_NE(msg.find("covered 2 times"), std::string::npos) << msg;
}

TEST(RepairMeshInvalid, inverted_face_is_refused) {
  // a fan around vertex 4 that was pushed outside its ring: one face turns clockwise
  const Mesh m = make_mesh({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {2.5, 1}}, {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  const std::string msg = repair_error(m);
  EXPECT_NE(msg.find("face 1"), std::string::npos) << msg;
}

TEST(RepairMeshInvalid, t_junction_is_refused) {
  // triangle 2 touches the middle of the other square's edge without sharing a vertex
  const Mesh m = make_mesh({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {2, 1}, {3, 0}, {3, 2}},
                           {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}});
  const std::string msg = repair_error(m);
  EXPECT_NE(msg.find("vertex 4 lies on boundary edge"), std::string::npos) << msg;
}

TEST(RepairMeshInvalid, empty_and_bad_features_are_refused) {
  EXPECT_NE(repair_error(Mesh()).find("no triangles"), std::string::npos) << "empty mesh";
  RepairMeshOptions o;
  o.features = {{0, 4}};
  const Mesh in = needle_mesh(4);
  try {
    repair_mesh(in, o);
    ADD_FAILURE() << "feature (0, 4) is not an edge";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("not an edge"), std::string::npos) << e.what();
  }
}

TEST(RepairMeshInvalid, non_manifold_files_are_refused_naming_the_element) {
  const fs::path bad = fs::path(acute::test::test_data_dir()) / "bad";
  for (const char* file : {"nonmanifold_edge.off", "nonmanifold_vertex.off", "overlapping_fans.off", "folded_face.off"}) {
    try {
      const Mesh m = io::read_mesh((bad / file).string());
      repair_mesh(m);
      ADD_FAILURE() << file << ": accepted";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find_first_of("0123456789"), std::string::npos) << file << ": " << e.what();
    }
  }
}

// --- library API -------------------------------------------------------------------------------

TEST(RepairApi, user_openmesh_float_mesh_is_repaired_in_place) {
  using UserMesh = OpenMesh::TriMesh_ArrayKernelT<>;  // float points
  UserMesh user;
  const Mesh needle = needle_mesh(10);
  for (auto vh : needle.vertices()) user.add_vertex(UserMesh::Point(float(needle.point(vh)[0]), float(needle.point(vh)[1]), 0.f));
  for (auto fh : needle.faces()) {
    std::vector<UserMesh::VertexHandle> f;
    for (auto fv : needle.fv_range(fh)) f.push_back(UserMesh::VertexHandle(fv.idx()));
    user.add_face(f);
  }
  int calls = 0;
  RepairMeshOptions o;
  o.progress = [&](const RepairMeshProgress&) { ++calls; };
  const RepairMeshResult r = repair(user, o);
  EXPECT_EQ(r.status, RepairMeshStatus::Ok) << "needle via repair()";
  EXPECT_EQ(user.n_faces(), r.mesh.n_faces()) << "result copied back";
  EXPECT_GT(calls, 0) << "progress callback";
}

TEST(RepairApi, cancel_stops_the_repair) {
  RepairMeshOptions o;
  o.cancel = [] { return true; };
  const Mesh in = ugly_mesh();
  const RepairMeshResult r = repair_mesh(in, o);
  EXPECT_TRUE(r.status == RepairMeshStatus::Cancelled || r.status == RepairMeshStatus::Ok) << to_string(r.status);
  EXPECT_EQ(conforms(in, r.mesh, false), "") << "cancelled result is still a valid mesh of the region";
}

// --- required points -----------------------------------------------------------------------

TEST(RepairKeepVertices, every_vertex_kept_and_no_obtuse_angle) {
  const Mesh in = ugly_mesh();
  RepairMeshOptions o;
  o.keep_vertices = true;
  const RepairMeshResult r = repair_mesh(in, o);
  EXPECT_EQ(conforms(in, r.mesh, true), "") << "ugly_mesh --keep-vertices";
  EXPECT_EQ(exact_obtuse(r.mesh), 0u) << "ugly_mesh --keep-vertices";
  EXPECT_EQ(r.status, RepairMeshStatus::Ok) << "ugly_mesh --keep-vertices";
}

void repair_small_cgshop_instances(bool require_non_obtuse) {
  const auto instances = test::small_cgshop_instances();
  if (instances.empty()) GTEST_SKIP() << "the shared CG:SHOP instances are absent";
  int n = 0;
  for (const auto& [uid, path] : instances) {
    const Domain d = io::read_cgshop(path.string());
    RepairMeshOptions o;
    o.allow_right = true;
    o.time_limit_s = 10;
    const RepairMeshResult r = repair_required_points(d, o);
    EXPECT_EQ(check_mesh(r.mesh).summary(), "ok") << uid;
    const auto have = vertex_set(r.mesh, false);
    for (std::size_t i = 0; i < d.points.size(); ++i)
      EXPECT_TRUE(have.count({d.points[i].x(), d.points[i].y()})) << uid << ": input point " << i << " missing";
    if (require_non_obtuse) {
      // Steiner points on slanted segments are rationals: decided on r.exact_coordinates (the
      // repair layer's tests check those independently), not on the mesh's doubles.
      EXPECT_EQ(r.status, RepairMeshStatus::Ok) << uid << " (" << r.n_steiner << " Steiner points)";
      EXPECT_EQ(r.n_obtuse_exact, 0u) << uid;
      EXPECT_EQ(r.exact_coordinates.size(), r.mesh.n_vertices()) << uid;
    }
    ++n;
  }
  EXPECT_GE(n, 1);
}

TEST(RepairKeepVertices, small_cgshop_instances_keep_every_point_and_become_non_obtuse) { repair_small_cgshop_instances(true); }

}  // namespace
}  // namespace acute
