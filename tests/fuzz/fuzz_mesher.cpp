// libFuzzer target: the default pipeline (method acute, angles in [30, 90)) on a small PSLG decoded
// from the bytes, with a small vertex target and a time limit. Each run ends in a clean
// InvalidInput, or in a mesh that passes the independent verifier (geometry, input points kept,
// segments covered, holes empty) and covers the area of the domain's CDT.
// Layout: flags, vertex target, point count, points (2 bytes each), segment count, segments
// (2 bytes each), hole count, holes (2 bytes each). Missing bytes read as 0.
//   flags bit 0: convex hull (Triangle -c)      bit 1: the points form a closed polygon first
//   flags bits 2-3: grid size 4 / 16 / 64 / 256 bits 4-6: scale and offset (powers of two, exact)
//   flags bit 7: split crossing segments
#include "fuzz_common.h"

#include <acute/mesher.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace acute_fuzz;
  Reader in{data, size};
  const std::uint8_t flags = in.next();
  const std::size_t target = 10 + in.next() % 150;
  const GridCoordinates grid(flags);

  Domain d;
  d.name = "fuzz_mesher";
  d.convex_hull = flags & 1;
  const int n = 3 + in.next() % 10;
  for (int i = 0; i < n; ++i) {
    const double x = grid.point(in.next()), y = grid.point(in.next());
    d.points.emplace_back(x, y);
  }
  if (flags & 2)
    for (int i = 0; i < n; ++i) d.segments.push_back({i, (i + 1) % n});
  const int m = in.next() % 8;
  for (int i = 0; i < m; ++i) {
    const int a = in.next() % n, b = in.next() % n;
    if (a != b) d.segments.push_back({a, b});
  }
  const int h = in.next() % 2;
  for (int i = 0; i < h; ++i) {
    const std::uint8_t x = in.next(), y = in.next();
    d.holes.emplace_back(grid.hole(x), grid.hole(y));
  }

  acute::MeshOptions options;  // method acute, [30, 90)
  options.target_vertices = target;
  options.max_vertices = 4000;
  options.time_limit_s = 2;
  options.cdt.crossing = (flags & 128) ? acute::CrossingSegments::Split : acute::CrossingSegments::Error;
  acute::MeshResult result;
  if (!run_guarded("generate_mesh", [&] { result = acute::generate_mesh(d, options); })) return 0;
  Mesh cdt;
  if (!run_guarded("build_domain_cdt", [&] { cdt = acute::build_domain_cdt(d, options.cdt); }))
    fail("generate_mesh accepted a domain that build_domain_cdt rejects");
  CdtCheckOptions check;
  check.convex_hull = d.convex_hull;
  check.delaunay = false;
  const std::string problem = verify_cdt(result.mesh, d, check);
  if (!problem.empty()) fail("generate_mesh: " + problem);
  const double want = acute::mesh_area(cdt), got = acute::mesh_area(result.mesh);
  if (!(std::abs(got - want) <= area_slack(result.mesh, want))) fail("generate_mesh: area " + num(got) + " != CDT area " + num(want) + " (allowed difference " + num(area_slack(result.mesh, want)) + ")");
  if (result.status == acute::MeshStatus::BoundsNotMet && result.remaining.empty()) fail("generate_mesh: bounds not met but no triangle listed");
  return 0;
}
