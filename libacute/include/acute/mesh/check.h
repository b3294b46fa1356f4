// Layer: mesh. The validator shipped with the library: is a mesh a valid, counter-clockwise,
// edge-manifold triangulation, are the constraints present, is it constrained Delaunay?
#pragma once

#include <acute/mesh/mesh.h>

#include <string>
#include <vector>

namespace acute {

enum class CheckLevel {
  Topology,   ///< manifold connectivity, no deleted elements referenced, no duplicate positions
  Geometry,   ///< + every face strictly counter-clockwise (exact)
  Delaunay    ///< + every unconstrained interior edge locally Delaunay (exact incircle)
};

struct CheckReport {
  std::vector<std::string> violations;  ///< one line each, naming the element ("face 7: ...")
  std::size_t total = 0;                 ///< all violations found (violations keeps the first ones)
  bool ok() const { return violations.empty(); }
  /// One line: "ok", or "<total> violations: <first max_lines joined by '; '>[; ...]".
  std::string summary(std::size_t max_lines = 5) const;
};

/// Checks a mesh (deleted elements are skipped); keeps the first max_violations lines. Geometry
/// and Delaunay levels run only when every face is a triangle with sound next/prev links.
/// Boundary edges and constrained edges (data(eh).segment >= 0) are exempt from the Delaunay test.
CheckReport check_mesh(const Mesh& mesh, CheckLevel level = CheckLevel::Geometry, std::size_t max_violations = 20);

}  // namespace acute
