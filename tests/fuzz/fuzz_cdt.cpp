// libFuzzer target: build_cdt on a small PSLG decoded from the bytes, verified independently.
// Layout: flags, point count, points (2 bytes each), segment count, segments (2 bytes each),
// hole count, holes (2 bytes each). Missing bytes read as 0.
//   flags bit 0: convex hull (Triangle -c)      bit 1: split crossing segments
//   flags bits 2-3: grid size 4 / 16 / 64 / 256 bits 4-6: scale and offset (powers of two, exact)
#include "fuzz_common.h"

#include <acute/delaunay/cdt.h>
#include <acute/io/io.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace acute_fuzz;
  Reader in{data, size};
  const std::uint8_t flags = in.next();
  const GridCoordinates grid(flags);

  Domain d;
  d.name = "fuzz_cdt";
  d.convex_hull = flags & 1;
  const int n = 3 + in.next() % 18;
  for (int i = 0; i < n; ++i) {
    const double x = grid.point(in.next()), y = grid.point(in.next());
    d.points.emplace_back(x, y);
    d.point_markers.push_back(0);
  }
  const int m = in.next() % 24;
  for (int i = 0; i < m; ++i) {
    const int a = in.next() % n, b = in.next() % n;
    if (a == b) continue;
    d.segments.push_back({a, b});
    d.segment_markers.push_back(1);
  }
  const int h = in.next() % 3;
  for (int i = 0; i < h; ++i) {
    const std::uint8_t x = in.next(), y = in.next();
    d.holes.emplace_back(grid.hole(x), grid.hole(y));
  }

  acute::CdtOptions options;
  options.crossing = (flags & 2) ? acute::CrossingSegments::Split : acute::CrossingSegments::Error;
  Mesh mesh;
  acute::CdtStats stats;
  if (!run_guarded("build_cdt", [&] { mesh = acute::build_cdt(d, options, &stats); })) return 0;
  if (const char* dump = std::getenv("ACUTE_FUZZ_DUMP")) {  // for debugging: the mesh, its constrained edges
    acute::io::write_mesh(mesh, dump);
    for (auto eh : mesh.edges())
      if (acute::is_constrained(mesh, eh))
        std::fprintf(stderr, "constrained edge %d-%d: segment %d\n", mesh.from_vertex_handle(mesh.halfedge_handle(eh, 0)).idx(),
                     mesh.to_vertex_handle(mesh.halfedge_handle(eh, 0)).idx(), mesh.data(eh).segment);
  }
  CdtCheckOptions check;
  check.convex_hull = d.convex_hull;
  check.exact_area = !(flags & 2);
  const std::string problem = verify_cdt(mesh, d, check);
  if (!problem.empty()) fail("build_cdt: " + problem);
  return 0;
}
