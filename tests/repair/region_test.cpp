#include <acute/mesher.h>
#include <acute/ops/insert.h>
#include <acute/repair/angle_bounds.h>

#include "repair/region.h"
#include "support/mesh_verify.h"
#include "support/region_verify.h"
#include "support/wedge_domains.h"

namespace acute {
namespace {

Domain square_with_hole() {
  Domain d;
  d.points = {Point2(0, 0), Point2(4, 0), Point2(4, 4), Point2(0, 4), Point2(1.5, 1.5), Point2(2.5, 1.5), Point2(2.5, 2.5), Point2(1.5, 2.5)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  d.holes = {Point2(2, 2)};
  return d;
}

TEST(Region, unchanged_copy_written_back_leaves_an_equivalent_mesh) {
  MeshOptions options;
  options.method = Method::Cvt;
  options.target_vertices = 300;
  Mesh mesh = generate_mesh(square_with_hole(), options).mesh;
  const double area = test::total_area(mesh);
  const std::size_t faces = mesh.n_faces();
  const auto forced = forced_corner_vertices(mesh, 30);
  std::vector<VertexHandle> movable;
  for (auto vh : mesh.vertices())
    if (movable.size() < 12 && (vh.idx() % 7) == 0) movable.push_back(vh);
  detail::Region region;
  ASSERT_TRUE(detail::extract_region(mesh, movable, forced, region));
  detail::commit_region(mesh, region, region.sub);
  mesh.garbage_collection();
  EXPECT_MESH_VALID(mesh);
  EXPECT_EQ(detail::constraint_violation(mesh), "");
  EXPECT_EQ(mesh.n_faces(), faces);
  EXPECT_NEAR(test::total_area(mesh), area, 1e-12 * area);
}

TEST(Region, edits_in_the_copy_never_touch_the_frozen_border) {
  MeshOptions options;
  options.method = Method::Cvt;
  options.target_vertices = 300;
  Mesh mesh = generate_mesh(square_with_hole(), options).mesh;
  const double area = test::total_area(mesh);
  const auto forced = forced_corner_vertices(mesh, 30);
  std::vector<VertexHandle> movable;
  for (auto vh : mesh.vertices())
    if (!is_input(mesh, vh) && movable.size() < 5) movable.push_back(vh);
  detail::Region region;
  ASSERT_TRUE(detail::extract_region(mesh, movable, forced, region));
  Mesh sub = region.sub;
  // Insert at every face centroid of the copy: points on the frozen border would be refused.
  std::vector<FaceHandle> faces(sub.faces().begin(), sub.faces().end());
  for (auto fh : faces) {
    if (sub.status(fh).deleted()) continue;
    Point2 c(0, 0);
    for (auto vh : sub.fv_range(fh)) c += point2(sub, vh) / 3.0;
    insert_point(sub, c, fh);
  }
  test::expect_commit_keeps_the_mesh(mesh, region, sub, area);
}

TEST(Region, an_input_vertex_in_the_region_keeps_its_handle_and_its_forced_flag) {
  // The forced-corner flags are indexed by handle: an input vertex that a commit deleted and
  // re-added came back unflagged, and the clusters after it in the same iteration scored the
  // forced corner's thin triangles as bad.
  Domain d;
  d.points = {Point2(0, 0), Point2(4, 0), Point2(4, 1)};  // a 14-degree corner at (0, 0)
  d.segments = {{0, 1}, {1, 2}, {2, 0}};
  MeshOptions options;
  options.method = Method::Cvt;
  options.target_vertices = 200;
  Mesh mesh = generate_mesh(d, options).mesh;
  const auto forced = forced_corner_vertices(mesh, 30);
  const VertexHandle corner = test::vertex_at(mesh, Point2(0, 0));
  ASSERT_TRUE(corner.is_valid());
  ASSERT_TRUE(forced[static_cast<std::size_t>(corner.idx())]);
  std::vector<VertexHandle> movable{corner};
  for (auto w : mesh.vv_range(corner)) movable.push_back(w);
  detail::Region region;
  ASSERT_TRUE(detail::extract_region(mesh, movable, forced, region));
  const VertexHandle in_copy = test::vertex_at(region.sub, Point2(0, 0));
  ASSERT_TRUE(in_copy.is_valid());
  EXPECT_TRUE(region.forced[static_cast<std::size_t>(in_copy.idx())]) << "flagged in the copy";
  EXPECT_EQ(region.to_big[static_cast<std::size_t>(in_copy.idx())], corner) << "mapped to its big-mesh handle";
  detail::commit_region(mesh, region, region.sub);
  EXPECT_FALSE(mesh.status(corner).deleted()) << "not deleted and re-added";
  EXPECT_EQ(point2(mesh, corner), Point2(0, 0));
  EXPECT_FALSE(mesh.is_isolated(corner));
  mesh.garbage_collection();
  EXPECT_MESH_VALID(mesh);
  const auto after = forced_corner_vertices(mesh, 30);
  std::size_t flagged = 0;
  for (auto vh : mesh.vertices()) flagged += after[static_cast<std::size_t>(vh.idx())] && point2(mesh, vh) == Point2(0, 0);
  EXPECT_EQ(flagged, 1u);
}

}  // namespace
}  // namespace acute
