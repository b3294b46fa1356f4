#include "io/io_test_util.h"

#include <acute/io/io.h>
#include <acute/predicates/predicates.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>

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
  const std::string path = std::string(ACUTE_SHARED_DIR) + "/domains/meshes/originals/A.1.node";
  if (!std::ifstream(path)) GTEST_SKIP() << path << " absent";
  const Mesh m = io::read_mesh(path);
  EXPECT_EQ(m.n_vertices(), 29u);
  EXPECT_EQ(n_faces(m), 29u);
  EXPECT_EQ(m.data(VertexHandle(0)).marker, 1) << "node marker kept";
  // Same geometry as the converted OFF.
  const Mesh off = io::read_mesh(std::string(ACUTE_MESHES_DIR) + "/A.1.off");
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
      {"nonmanifold_vertex.off", {"nonmanifold_vertex.off:", "vertex 0 is non-manifold"}},
      {"folded_face.off", {"folded_face.off:11:", "face 2 (vertices 1 2 4) is clockwise"}},
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

TEST(ReadMesh, unknown_extension_and_missing_file_are_io_errors) {
  expect_error<IoError>([] { io::read_mesh(data("x.stl")); }, {"x.stl", "unknown mesh format"}, "x.stl");
  expect_error<IoError>([] { io::read_mesh(data("missing.off")); }, {"missing.off", "cannot open"}, "missing.off");
}
