// Layer: delaunay (private).
// OpenMesh meshes declare their destructors, so they have no move constructor or move
// assignment: `mesh = std::move(other)` and `mesh = f()` copy the whole mesh (about 30 ms and
// 100 MB of fresh pages at a million triangles). The pipeline builds its large meshes where they
// stay with these; a returned mesh is only ever used to initialise one.
#pragma once

#include <acute/delaunay/cdt.h>

namespace acute::detail {

/// build_cdt, built in `mesh` (whatever it held is replaced; left as it was when it throws).
void build_cdt_into(Mesh& mesh, const Domain& domain, const CdtOptions& options, CdtStats* stats);

}  // namespace acute::detail
