// Non-obtuse Steiner triangulation with required points: validity, every input point kept
// exactly, segments covered, and no obtuse angle, decided on the exact rational coordinates.
#include <acute/io/io.h>
#include <acute/mesh/check.h>
#include <acute/repair/non_obtuse.h>

#include <gmpxx.h>
#include "support/cgshop_samples.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace acute {
namespace {

namespace fs = std::filesystem;

struct ExactPoint {
  mpq_class x, y;
};

std::vector<ExactPoint> exact_points(const NonObtuseResult& r) {
  std::vector<ExactPoint> out;
  for (const auto& e : r.exact) out.push_back({mpq_class(e[0]), mpq_class(e[1])});
  for (auto& p : out) p.x.canonicalize(), p.y.canonicalize();
  return out;
}

/// Triangles with an exactly obtuse angle, from the exact coordinates.
std::size_t exact_obtuse(const NonObtuseResult& r) {
  const auto pts = exact_points(r);
  std::size_t n = 0;
  for (auto fh : r.mesh.faces()) {
    std::vector<int> v;
    for (auto fv : r.mesh.fv_range(fh)) v.push_back(fv.idx());
    bool obtuse = false;
    for (int k = 0; k < 3; ++k) {
      const ExactPoint &o = pts[v[k]], &p = pts[v[(k + 1) % 3]], &q = pts[v[(k + 2) % 3]];
      if ((p.x - o.x) * (q.x - o.x) + (p.y - o.y) * (q.y - o.y) < 0) obtuse = true;
    }
    n += obtuse;
  }
  return n;
}

/// Every domain point is a vertex at exactly its coordinates; every Steiner point on a segment
/// edge lies exactly on the segment.
void expect_conforming(const Domain& d, const NonObtuseResult& r, const std::string& what) {
  EXPECT_EQ(check_mesh(r.mesh).summary(), "ok") << what;
  const auto pts = exact_points(r);
  ASSERT_EQ(pts.size(), r.mesh.n_vertices()) << what;
  std::set<std::pair<mpq_class, mpq_class>> have;
  for (const auto& p : pts) have.insert({p.x, p.y});
  for (std::size_t i = 0; i < d.points.size(); ++i)
    EXPECT_TRUE(have.count({mpq_class(d.points[i].x()), mpq_class(d.points[i].y())})) << what << ": input point " << i;
  for (auto eh : r.mesh.edges()) {
    const int s = r.mesh.data(eh).segment;
    if (s < 0 || static_cast<std::size_t>(s) >= d.segments.size()) continue;
    const auto h = r.mesh.halfedge_handle(eh, 0);
    const Point2 &a = d.points[d.segments[s][0]], &b = d.points[d.segments[s][1]];
    for (auto vh : {r.mesh.from_vertex_handle(h), r.mesh.to_vertex_handle(h)}) {
      const ExactPoint& p = pts[vh.idx()];
      const mpq_class cross = (mpq_class(b.x()) - a.x()) * (p.y - a.y()) - (mpq_class(b.y()) - a.y()) * (p.x - a.x());
      EXPECT_EQ(cross, 0) << what << ": vertex " << vh.idx() << " of segment " << s << " is off it";
    }
  }
}

TEST(NonObtuse, obtuse_triangle_gets_its_altitude) {
  Domain d;
  d.points = {Point2(0, 0), Point2(10, 0), Point2(3, 2)};  // obtuse at (3, 2)
  d.segments = {{0, 1}, {1, 2}, {2, 0}};
  const NonObtuseResult r = non_obtuse_triangulation(d);
  expect_conforming(d, r, "triangle");
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(exact_obtuse(r), 0u);
  EXPECT_EQ(r.n_steiner, 1u) << "one foot of the altitude suffices";
}

TEST(NonObtuse, slanted_segment_gets_exact_rational_points) {
  Domain d;  // a quadrilateral with a slanted constraint inside and an obtuse corner on it
  d.points = {Point2(0, 0), Point2(13, 1), Point2(11, 7), Point2(1, 6), Point2(4, 2), Point2(9, 5)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}};
  const NonObtuseResult r = non_obtuse_triangulation(d);
  expect_conforming(d, r, "quad with constraint");
  EXPECT_TRUE(r.ok) << r.n_obtuse << " obtuse";
  EXPECT_EQ(exact_obtuse(r), 0u);
}

TEST(NonObtuse, small_cgshop_instances_become_non_obtuse) {
  const auto instances = test::small_cgshop_instances();
  if (instances.empty()) GTEST_SKIP() << "the shared CG:SHOP instances are absent";
  int n = 0;
  for (const auto& [uid, path] : instances) {
    const Domain d = io::read_cgshop(path.string());
    const NonObtuseResult r = non_obtuse_triangulation(d);
    expect_conforming(d, r, uid);
    EXPECT_TRUE(r.ok) << uid << ": " << r.n_obtuse << " obtuse, " << r.n_steiner << " Steiner";
    EXPECT_EQ(exact_obtuse(r), 0u) << uid;
    ++n;
  }
  EXPECT_GE(n, 1);
}

}  // namespace
}  // namespace acute
