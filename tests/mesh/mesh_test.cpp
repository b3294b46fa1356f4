#include "mesh/builders.h"

#include <acute/mesh/check.h>
#include <acute/mesh/mesh.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace acute {
namespace {

struct FloatTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3f;
};
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
using FloatMesh = OpenMesh::TriMesh_ArrayKernelT<FloatTraits>;
using DoubleMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

template <class M>
M user_fan() {
  // A hexagon-ish fan around (0.5, 0.25); coordinates exact in float. z is ignored on import.
  M m;
  using P = typename M::Point;
  std::vector<typename M::VertexHandle> v;
  v.push_back(m.add_vertex(P(0.5f, 0.25f, 3.0f)));
  const float ring[6][2] = {{1.5f, 0.25f}, {1.0f, 1.125f}, {0.0f, 1.125f}, {-0.5f, 0.25f}, {0.0f, -0.625f}, {1.0f, -0.625f}};
  for (auto& q : ring) v.push_back(m.add_vertex(P(q[0], q[1], 0.0f)));
  for (int i = 0; i < 6; ++i) m.add_face(v[0], v[1 + i], v[1 + (i + 1) % 6]);
  return m;
}

template <class M>
void expect_same_mesh(const M& a, const M& b, const char* what) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices()) << what;
  ASSERT_EQ(a.n_faces(), b.n_faces()) << what;
  for (auto vh : a.vertices()) {
    EXPECT_EQ(a.point(vh)[0], b.point(typename M::VertexHandle(vh.idx()))[0]) << what << " vertex " << vh.idx();
    EXPECT_EQ(a.point(vh)[1], b.point(typename M::VertexHandle(vh.idx()))[1]) << what << " vertex " << vh.idx();
  }
  for (auto fh : a.faces()) {
    std::vector<int> fa, fb;
    for (auto fv : a.fv_range(fh)) fa.push_back(fv.idx());
    for (auto fv : b.fv_range(typename M::FaceHandle(fh.idx()))) fb.push_back(fv.idx());
    EXPECT_EQ(fa, fb) << what << " face " << fh.idx();
  }
}

TEST(FromOpenMesh, float_points_round_trip_exactly) {
  const FloatMesh in = user_fan<FloatMesh>();
  const Mesh m = from_openmesh(in);
  EXPECT_EQ(m.n_vertices(), 7u);
  EXPECT_EQ(m.n_faces(), 6u);
  for (auto vh : m.vertices()) {
    EXPECT_EQ(m.point(vh)[2], 0.0) << "vertex " << vh.idx() << ": z dropped";
    EXPECT_EQ(m.data(vh).kind, VertexKind::Free) << "vertex " << vh.idx();
  }
  for (auto eh : m.edges()) EXPECT_FALSE(is_constrained(m, eh)) << "edge " << eh.idx();
  EXPECT_TRUE(check_mesh(m, CheckLevel::Geometry).ok()) << check_mesh(m).summary();
  FloatMesh back;
  to_openmesh(m, back);
  FloatMesh flat = in;
  for (auto vh : flat.vertices()) flat.point(vh)[2] = 0.0f;
  expect_same_mesh(flat, back, "float round trip");
  for (auto vh : back.vertices()) EXPECT_EQ(back.point(vh)[2], 0.0f) << "vertex " << vh.idx();
}

TEST(FromOpenMesh, double_points_round_trip_exactly) {
  DoubleMesh in;
  const double xs[4][2] = {{0.1, 0.2}, {1.0 / 3.0, 0.7}, {-0.3, 1e-300}, {0.9, 0.95}};
  std::vector<DoubleMesh::VertexHandle> v;
  for (auto& q : xs) v.push_back(in.add_vertex(DoubleMesh::Point(q[0], q[1], 0.0)));
  in.add_face(v[0], v[3], v[1]);
  in.add_face(v[0], v[1], v[2]);
  const Mesh m = from_openmesh(in);
  DoubleMesh back;
  to_openmesh(m, back);
  expect_same_mesh(in, back, "double round trip");
}

TEST(FromOpenMesh, keeps_face_vertex_order) {
  const Mesh m = test::make_mesh({{0, 0}, {1, 0}, {0, 1}, {1, 1}}, {{1, 3, 2}, {2, 0, 1}});
  const Mesh c = from_openmesh(m);
  const std::vector<std::vector<int>> expected = {{1, 3, 2}, {2, 0, 1}};
  for (auto fh : c.faces()) {
    std::vector<int> f;
    for (auto fv : c.fv_range(fh)) f.push_back(fv.idx());
    EXPECT_EQ(f, expected[fh.idx()]) << "face " << fh.idx();
  }
}

TEST(MarkBoundary, constrains_every_boundary_edge_once_along_the_loop) {
  Mesh m = test::grid(3);
  const int n = mark_boundary_as_constrained(m);
  EXPECT_EQ(n, 12);
  std::set<int> ids;
  for (auto eh : m.edges()) {
    if (m.is_boundary(eh)) {
      EXPECT_TRUE(is_constrained(m, eh)) << "boundary edge " << eh.idx();
      ids.insert(m.data(eh).segment);
    } else {
      EXPECT_FALSE(is_constrained(m, eh)) << "interior edge " << eh.idx();
    }
  }
  EXPECT_EQ(ids.size(), 12u);
  EXPECT_EQ(*ids.begin(), 0);
  EXPECT_EQ(*ids.rbegin(), 11);
  // Consecutive ids are consecutive edges of the loop.
  for (auto heh : m.halfedges()) {
    if (!m.is_boundary(heh)) continue;
    const int a = m.data(m.edge_handle(heh)).segment, b = m.data(m.edge_handle(m.next_halfedge_handle(heh))).segment;
    EXPECT_EQ((a + 1) % 12, b) << "boundary halfedge " << heh.idx();
  }
  for (auto vh : m.vertices())
    EXPECT_EQ(is_input(m, vh), m.is_boundary(vh)) << "vertex " << vh.idx();
}

TEST(Compacted, drops_deleted_elements_and_keeps_data) {
  Mesh g = test::grid(2);
  mark_boundary_as_constrained(g);
  g.data(VertexHandle(8)).marker = 7;
  g.delete_face(FaceHandle(0), true);  // corner triangle (0,0),(1,0),(1,1): isolates nothing
  const Mesh d = compacted(g);
  EXPECT_EQ(d.n_faces(), 7u);
  EXPECT_EQ(d.n_vertices(), 9u);
  EXPECT_TRUE(check_mesh(d, CheckLevel::Geometry).ok()) << check_mesh(d).summary();
  EXPECT_EQ(d.data(VertexHandle(8)).marker, 7);
  EXPECT_EQ(d.point(VertexHandle(8)), Mesh::Point(2, 2, 0));
  int constrained = 0;
  for (auto eh : d.edges()) constrained += is_constrained(d, eh);
  EXPECT_EQ(constrained, 7) << "boundary constraints of the original grid survive (one edge went with the face)";
  for (auto eh : d.edges()) {
    const auto h = d.halfedge_handle(eh, 0);
    const auto oh = g.find_halfedge(VertexHandle(d.from_vertex_handle(h).idx()), VertexHandle(d.to_vertex_handle(h).idx()));
    ASSERT_TRUE(oh.is_valid()) << "edge " << eh.idx();
    EXPECT_EQ(d.data(eh).segment, g.data(g.edge_handle(oh)).segment) << "edge " << eh.idx();
  }
}

}  // namespace
}  // namespace acute
