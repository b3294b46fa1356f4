// Verifier for the repair's region copies: what a rebuilt copy leaves when written back.
#pragma once

#include <acute/mesh/mesh.h>

#include "repair/region.h"
#include "support/mesh_verify.h"

#include <gtest/gtest.h>

namespace acute::test {

/// Writes sub back into mesh: the mesh stays valid, conforming and of the same area.
inline void expect_commit_keeps_the_mesh(Mesh& mesh, const detail::Region& region, const Mesh& sub, double area) {
  detail::commit_region(mesh, region, sub);
  mesh.garbage_collection();
  EXPECT_MESH_VALID(mesh);
  EXPECT_EQ(detail::constraint_violation(mesh), "");
  EXPECT_NEAR(test::total_area(mesh), area, 1e-12 * area);
}

}  // namespace acute::test
