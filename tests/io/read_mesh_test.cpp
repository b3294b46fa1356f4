#include "io/io_test_util.h"
#include "support/paths.h"

#include <acute/io/io.h>
#include <acute/mesh/boundary.h>
#include <acute/mesh/check.h>
#include <acute/predicates/predicates.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <numeric>

using namespace acute;
using acute::test::bad;
using acute::test::data;
using acute::test::expect_error;

namespace {
std::size_t n_faces(const Mesh& m) {
  std::size_t n = 0;
  for (auto fh : m.faces()) n += fh.is_valid();
  return n;
}
void expect_all_ccw(const Mesh& m, const std::string& name) {
  for (auto fh : m.faces()) {
    Point2 p[3];
    int k = 0;
    for (auto fv : m.fv_range(fh)) p[k++] = point2(m, fv);
    EXPECT_EQ(predicates::orient2d(p[0], p[1], p[2]), Sign::Positive) << name << ": face " << fh.idx();
  }
}
}  // namespace

TEST(ReadMesh, obj_with_slashes_relative_indices_and_other_records) {
  const Mesh m = io::read_mesh(data("features.obj"));
  EXPECT_EQ(m.n_vertices(), 4u);
  EXPECT_EQ(n_faces(m), 2u);
  expect_all_ccw(m, "features.obj");
}

TEST(ReadMesh, clockwise_off_is_reversed_with_warning) {
  std::vector<std::string> warnings;
  const Mesh m = io::read_mesh(data("clockwise.off"), [&](const std::string& w) { warnings.push_back(w); });
  EXPECT_EQ(n_faces(m), 2u);
  expect_all_ccw(m, "clockwise.off");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("clockwise"), std::string::npos) << warnings[0];
}

TEST(ReadMesh, ascii_ply_keeps_doubles) {
  const Mesh m = io::read_mesh(data("square.ply"));
  EXPECT_EQ(m.n_vertices(), 4u);
  EXPECT_EQ(n_faces(m), 2u);
  EXPECT_EQ(m.point(VertexHandle(3))[0], 0.1) << "double property read as double";
  expect_all_ccw(m, "square.ply");
}

TEST(ReadMesh, binary_ply_little_and_big_endian) {
  for (const bool big : {false, true}) {
    const std::string path = test::output(big ? "binary_big.ply" : "binary_little.ply");
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat " << (big ? "binary_big_endian" : "binary_little_endian")
        << " 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty float z\n"
           "property uchar red\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    auto put = [&](const void* p, std::size_t n) {
      const char* c = static_cast<const char*>(p);
      std::string bytes(c, n);
      const std::uint16_t one = 1;
      const bool host_little = *reinterpret_cast<const unsigned char*>(&one) == 1;
      if (big == host_little) std::reverse(bytes.begin(), bytes.end());
      out << bytes;
    };
    const double xy[3][2] = {{0.1, 0.2}, {1.0 / 3.0, 0.0}, {0.0, 2.0 / 3.0}};
    for (const auto& p : xy) {
      put(&p[0], 8);
      put(&p[1], 8);
      const float z = 0;
      put(&z, 4);
      const unsigned char red = 200;
      put(&red, 1);
    }
    const unsigned char three = 3;
    put(&three, 1);
    for (const std::int32_t v : {0, 1, 2}) put(&v, 4);
    out.close();
    const Mesh m = io::read_mesh(path);
    ASSERT_EQ(m.n_vertices(), 3u) << path;
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(m.point(VertexHandle(i))[0], xy[i][0]) << path << ": vertex " << i;
      EXPECT_EQ(m.point(VertexHandle(i))[1], xy[i][1]) << path << ": vertex " << i;
    }
    EXPECT_EQ(n_faces(m), 1u) << path;
  }
}

TEST(ReadMesh, node_ele_with_markers) {
  const std::string path = std::string(acute::test::shared_dir()) + "/domains/meshes/originals/A.1.node";
  if (!std::ifstream(path)) GTEST_SKIP() << path << " absent";
  const Mesh m = io::read_mesh(path);
  EXPECT_EQ(m.n_vertices(), 29u);
  EXPECT_EQ(n_faces(m), 29u);
  EXPECT_EQ(m.data(VertexHandle(0)).marker, 1) << "node marker kept";
  // Same geometry as the converted OFF.
  const Mesh off = io::read_mesh(std::string(acute::test::meshes_dir()) + "/A.1.off");
  for (auto vh : m.vertices()) EXPECT_EQ(m.point(vh), off.point(vh)) << "vertex " << vh.idx();
}

TEST(ReadMesh, bad_inputs_name_file_line_and_problem) {
  struct Case {
    const char* file;
    std::vector<std::string> pieces;
  };
  const std::vector<Case> cases = {
      {"inf_coordinate.off", {"inf_coordinate.off:5:", "vertex 2 x is not finite"}},
      {"quad_face.off", {"quad_face.off:9:", "face 1 has 4 vertices", "only triangles"}},
      {"quad_face.obj", {"quad_face.obj:5:", "face 1 has 4 vertices"}},
      {"quad_face.ply", {"quad_face.ply:14:", "face 0 has 4 vertices"}},
      {"face_index_out_of_range.off", {"face_index_out_of_range.off:6:", "face 0 uses vertex 3", "3 vertices"}},
      {"face_index_out_of_range.obj", {"face_index_out_of_range.obj:4:", "face 1 uses vertex 4", "3 vertices"}},
      {"repeated_vertex_face.off", {"repeated_vertex_face.off:6:", "face 0 (vertices 0 1 1) repeats a vertex"}},
      {"nonmanifold_edge.off", {"nonmanifold_edge.off:11:", "face 2 (vertices 0 1 3) is a third face on edge 0-1"}},
      {"nonmanifold_vertex.off", {"nonmanifold_vertex.off:15:", "face 4 (vertices 0 5 6) cannot be added", "non-manifold"}},
      {"folded_face.off", {"folded_face.off:11:", "face 2 (vertices 1 2 4) is clockwise"}},
      {"degenerate_pinch.off", {"degenerate_pinch.off:6:", "faces meeting only at vertex 1", "cannot be ordered"}},
      {"same_direction_edge.off", {"same_direction_edge.off:9:", "face 1 (vertices 0 1 3) uses edge 0-1 in the same direction as face 0"}},
      {"truncated_faces.off", {"truncated_faces.off:", "expected 2 faces, file ends after 1"}},
      {"bad_element_index.ele", {"bad_element_index.ele:2:", "triangle 1 uses vertex 4", "3 vertices numbered from 1"}},
  };
  for (const auto& c : cases) {
    try {
      io::read_mesh(bad(c.file));
      ADD_FAILURE() << c.file << ": no exception";
    } catch (const InvalidInput& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << c.file;
      for (const auto& piece : c.pieces)
        EXPECT_NE(message.find(piece), std::string::npos) << c.file << ": '" << message << "' lacks '" << piece << "'";
    }
  }
}

// A pinch vertex (fans of faces meeting only there) is valid input. Whatever order the faces come
// in, the mesh is read, check_mesh accepts it, its boundary splits into simple loops at the pinch
// and domain_of_mesh seeds exactly the holes.
TEST(ReadMesh, pinch_vertices_are_read_in_any_face_order) {
  struct Case {
    const char* file;
    std::vector<std::size_t> loop_sizes;  // sorted
    std::size_t holes;
  };
  for (const Case& c : {Case{"pinch_squares.off", {4, 4}, 0}, Case{"pinch_hole.off", {3, 5}, 1},
                        Case{"pinch_three_fans.off", {4, 4, 4}, 0}}) {
    const Mesh base = io::read_mesh(data(c.file));
    std::vector<std::array<int, 3>> faces;
    for (auto fh : base.faces()) {
      std::array<int, 3> t{};
      int k = 0;
      for (auto fv : base.fv_range(fh)) t[k++] = fv.idx();
      faces.push_back(t);
    }
    std::vector<std::size_t> order(faces.size());
    std::iota(order.begin(), order.end(), 0);
    const std::string path = acute::test::output(std::string("permuted_") + c.file);
    int permutations = 0;
    do {
      {
        std::ofstream out(path);
        out << "OFF\n" << base.n_vertices() << ' ' << faces.size() << " 0\n";
        for (auto vh : base.vertices()) out << base.point(vh)[0] << ' ' << base.point(vh)[1] << " 0\n";
        for (std::size_t f : order) out << "3 " << faces[f][0] << ' ' << faces[f][1] << ' ' << faces[f][2] << '\n';
      }
      const std::string context = std::string(c.file) + " order " + std::to_string(permutations);
      Mesh m;
      try {
        m = io::read_mesh(path);
      } catch (const std::exception& e) {
        ADD_FAILURE() << context << ": " << e.what();
        continue;
      }
      EXPECT_EQ(n_faces(m), faces.size()) << context;
      const CheckReport r = check_mesh(m, CheckLevel::Geometry);
      EXPECT_TRUE(r.ok()) << context << ": " << r.summary();
      // Each boundary halfedge into a pinch vertex is followed by the outgoing one that closes the
      // same gap: no boundary neighbour lies inside the wedge between them (every gap here < 180).
      for (auto vh : m.vertices()) {
        if (!is_pinch_vertex(m, vh)) continue;
        for (auto out : m.voh_range(vh)) {
          const auto in = m.opposite_halfedge_handle(out);
          if (!m.is_boundary(in)) continue;
          const Point2 c0 = point2(m, vh), a = point2(m, m.to_vertex_handle(m.next_halfedge_handle(in))),
                       b = point2(m, m.from_vertex_handle(in));
          for (auto nb : m.vv_range(vh)) {
            const Point2 p = point2(m, nb);
            EXPECT_FALSE(predicates::orient2d(c0, a, p) == Sign::Positive && predicates::orient2d(c0, p, b) == Sign::Positive)
                << context << ": vertex " << nb.idx() << " inside the gap closed at vertex " << vh.idx();
          }
        }
      }
      std::vector<std::size_t> sizes;
      for (const auto& loop : simple_boundary_loops(m)) sizes.push_back(loop.size());
      std::sort(sizes.begin(), sizes.end());
      EXPECT_EQ(sizes, c.loop_sizes) << context;
      const Domain d = io::domain_of_mesh(m);
      ASSERT_EQ(d.holes.size(), c.holes) << context;
      if (c.holes == 1) {  // inside the hole triangle (2, 0), (3, 1), (1, 1)
        const Point2 h = d.holes[0];
        EXPECT_TRUE(h.y() < 1 && h.y() > std::abs(h.x() - 2))
            << context << ": hole seed (" << h.x() << ", " << h.y() << ")";
      }
      ++permutations;
    } while (std::next_permutation(order.begin(), order.end()));
    EXPECT_GT(permutations, 1) << c.file;
  }
}

TEST(ReadMesh, unknown_extension_and_missing_file_are_io_errors) {
  expect_error<IoError>([] { io::read_mesh(data("x.stl")); }, {"x.stl", "unknown mesh format"}, "x.stl");
  expect_error<IoError>([] { io::read_mesh(data("missing.off")); }, {"missing.off", "cannot open"}, "missing.off");
}

// --- edges tagged in the file (OBJ polylines) ---------------------------------------------

TEST(ReadTaggedEdges, obj_polyline_gives_each_consecutive_pair_with_its_line) {
  const auto edges = io::read_tagged_edges(data("tagged_polyline.obj"));
  ASSERT_EQ(edges.size(), 2u);
  EXPECT_EQ(edges[0].vertices, (std::array<int, 2>{5, 10}));
  EXPECT_EQ(edges[1].vertices, (std::array<int, 2>{10, 9}));
  EXPECT_EQ(edges[0].line, 37);
  EXPECT_EQ(edges[1].line, 37);
  // The mesh itself reads as before: the polyline is not a face.
  EXPECT_EQ(io::read_mesh(data("tagged_polyline.obj")).n_faces(), 18u);
  EXPECT_TRUE(io::read_tagged_edges(std::string(acute::test::meshes_dir()) + "/grid.off").empty()) << "OFF tags no edge";
}

TEST(ReadTaggedEdges, relative_and_slashed_indices_resolve_and_bad_ones_name_the_line) {
  const std::string path = test::output("tagged_relative.obj");
  {
    std::ofstream f(path);
    f << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl -3/1 2/2\n";
  }
  const auto edges = io::read_tagged_edges(path);
  ASSERT_EQ(edges.size(), 1u);
  EXPECT_EQ(edges[0].vertices, (std::array<int, 2>{0, 1}));
  const std::vector<std::pair<std::string, std::vector<std::string>>> bad = {
      {"l 1 9\n", {":5:", "vertex 9", "out of range"}},
      {"l 1\n", {":5:", "polyline"}},
      {"l 2 2\n", {":5:", "repeats vertex 2"}},
      {"l 1 x\n", {":5:", "'x' is not a vertex index"}},
  };
  for (const auto& [line, pieces] : bad) {
    {
      std::ofstream f(path);
      f << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" << line;
    }
    try {
      io::read_tagged_edges(path);
      ADD_FAILURE() << line << ": no error";
    } catch (const InvalidInput& e) {
      for (const auto& piece : pieces) EXPECT_NE(std::string(e.what()).find(piece), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << "names the file: " << e.what();
    }
  }
}
