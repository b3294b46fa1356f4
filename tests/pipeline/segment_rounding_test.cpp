// Regressions from the stress domains (scripts/stress): Steiner points on segments whose doubles
// cannot lie exactly on the segment. Each mesh must be read back by the referee's rule
// (verify_segment_chains: within 1e-10 of the segment's length of its line, strictly advancing),
// whatever the angle bounds reached.
#include <acute/io/io.h>
#include <acute/mesher.h>

#include "support/domain_verify.h"

#include <gtest/gtest.h>

#include <string>

namespace acute {
namespace {

void expect_segments_read_back(const std::string& name) {
  const Domain domain = io::read_poly(std::string(ACUTE_TEST_DATA_DIR) + "/regressions/" + name + ".poly");
  MeshOptions options;
  options.target_vertices = 300;
  options.time_limit_s = 3;  // a safety net: validity is asserted whatever stopped the run
  const MeshResult result = generate_mesh(domain, options);
  const double area = mesh_area(build_domain_cdt(domain));
  EXPECT_EQ(test::verify_conforms(result.mesh, domain, area), "") << name;
  EXPECT_EQ(test::verify_segment_chains(result.mesh, domain, 1e-10), "") << name;
}

// Sides ~4e-5 long at -1000, where an ulp is ~3e-9 of them: rounded midpoints left the line.
TEST(SegmentRounding, tiny_slanted_hole_far_from_origin) { expect_segments_read_back("tiny_slanted_hole_far_from_origin"); }

// Segments 4-5 ulps wide in x: more Steiner points than distinct x values made chains stall.
TEST(SegmentRounding, nearly_vertical_segment_few_ulps_wide) { expect_segments_read_back("nearly_vertical_segment_few_ulps_wide"); }

}  // namespace
}  // namespace acute
