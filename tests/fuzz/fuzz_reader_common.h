// What the reader targets do with a domain that was read: validate it again (must pass), and
// mesh it with build_cdt when it is small, checking the result independently.
#pragma once

#include "fuzz_common.h"

#include <acute/io/io.h>

namespace acute_fuzz {

inline void check_read_domain(const Domain& d, const char* what) {
  // The readers end with validate_domain: validating again must not throw.
  try {
    acute::io::validate_domain(d);
  } catch (const std::exception& e) {
    fail(std::string(what) + ": returned a domain that validate_domain rejects: " + e.what());
    return;
  }
  if (d.points.size() != d.point_markers.size() && !d.point_markers.empty()) return fail(std::string(what) + ": point_markers size mismatch");
  if (d.segments.size() != d.segment_markers.size() && !d.segment_markers.empty()) return fail(std::string(what) + ": segment_markers size mismatch");
  if (d.points.size() > 64 || d.segments.size() > 64) return;  // keep executions fast
  Mesh mesh;
  if (!run_guarded("build_cdt", [&] { mesh = acute::build_cdt(d); })) return;
  CdtCheckOptions check;
  check.convex_hull = d.convex_hull;
  const std::string problem = verify_cdt(mesh, d, check);
  if (!problem.empty()) fail(std::string(what) + " + build_cdt: " + problem);
}

}  // namespace acute_fuzz
