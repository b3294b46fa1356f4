// A triangle mesh read as a domain (`acute mesh grid.obj`): its boundary bounds the new mesh, and
// the edges the file tags (OBJ polylines) are kept as interior segments.
#include <acute/io/io.h>
#include <acute/mesher.h>
#include <acute/repair/repair.h>

#include "support/domain_verify.h"
#include "support/paths.h"

#include <gtest/gtest.h>

#include <string>

namespace acute {
namespace {

TEST(MeshDomain, obj_polyline_is_kept_as_a_chain_of_edges_and_the_bounds_are_met) {
  const std::string path = std::string(acute::test::test_data_dir()) + "/tagged_polyline.obj";
  const Domain domain = io::read_domain(path);
  MeshOptions options;
  options.target_vertices = 300;
  options.time_limit_s = 30;  // a safety net: the properties are asserted whatever stopped the run
  const MeshResult r = generate_mesh(domain, options);
  EXPECT_EQ(test::verify_conforms(r.mesh, domain, 9.0), "") << path;  // the polyline's segments covered too
  EXPECT_EQ(bad_triangles(r.mesh, AngleBounds{}).size(), 0u) << path << ": [30, 90) on a square with a bent interior polyline";
  EXPECT_GE(r.mesh.n_vertices(), 150u);
}

}  // namespace
}  // namespace acute
