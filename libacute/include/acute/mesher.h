// Layer: pipeline. One call from a Domain to a mesh: CDT, refinement, CVT, acute repair.
#pragma once

#include <acute/core/domain.h>
#include <acute/delaunay/cdt.h>
#include <acute/mesh/mesh.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace acute {

enum class Method {
  Cdt,     ///< the bare constrained Delaunay triangulation, no Steiner points
  Refine,  ///< Delaunay refinement (Ruppert/Chew with off-centres)
  Cvt,     ///< sampling + CDT + centroidal Voronoi optimisation
  Acute    ///< Cvt followed by the acute repair (the default)
};

/// Parses "cdt", "refine", "cvt", "acute". \throws InvalidInput
Method parse_method(const std::string& name);
const char* to_string(Method method);

struct MeshProgress {
  std::string phase;       ///< "cdt", "refine", "cvt", "repair"
  int iteration = 0;
  std::size_t bad = 0;     ///< bad triangles left (repair)
  double energy = 0;       ///< CVT energy
  double gradient_norm = 0;  ///< CVT: |dF/dX| over the moving coordinates
  const char* step = "";   ///< CVT: "lloyd" or "lbfgs"
};

/// MeshOptions::gradation's default, and the gentlest that an acute method's restart goes to.
constexpr double kDefaultGradation = 1.3;

struct MeshOptions {
  Method method = Method::Acute;
  double min_angle_deg = 30.0;
  double max_angle_deg = 90.0;  ///< angles must be strictly below
  double size = 0;              ///< target edge length (0: graded from the local feature size)
  std::size_t target_vertices = 0;
  /// How fast sizes may grow away from features (the field's slope is gradation - 1). The acute
  /// method follows at most 1.5 (a note says when it capped it), and its restarts grade more
  /// gently, down to the default.
  double gradation = kDefaultGradation;
  /// > 0: the graded field's largest edge length (default: kDefaultMaxSizeRatio * the diameter)
  double max_size = 0;
  /// When set: a position-dependent largest edge length for the graded field (CvtParams::size_cap)
  std::function<double(const Point2&)> size_cap;
  unsigned seed = 1;
  /// With Method::Cvt: optimise as the acute method's start (a short optimisation, room for
  /// interior vertices in strips between input points), not to convergence: for callers that run
  /// the acute repair themselves (acute::repair_mesh)
  bool cvt_as_repair_start = false;
  int max_iterations = 0;       ///< 0: the method's default
  std::size_t max_vertices = 50'000'000;
  double time_limit_s = 0;      ///< 0: none
  /// Method::Acute: when the repair stalls with a few bad triangles left (not at the time limit,
  /// the vertex budget or a max_iterations given), run again from a start with another seed and a
  /// size field 5% finer each time (about 10% more vertices), up to this many times, within what
  /// is left of the time limit; the best result is kept (see notes).
  int restarts = 2;
  CdtOptions cdt;
  std::function<void(const MeshProgress&)> observer;
  /// Remarks worth telling the user while the run goes on (e.g. that the domain's features need
  /// many times the vertices requested, so the run will be long); MeshResult::notes has the rest.
  std::function<void(const std::string&)> on_note;
};

enum class MeshStatus {
  Ok,              ///< every angle within the bounds (forced input corners excepted)
  BoundsNotMet,    ///< the best mesh found still has bad triangles (listed)
  NotApplicable    ///< methods without angle bounds (cdt, cvt)
};

struct BadTriangle {
  std::array<Point2, 3> corners;
  double min_angle_deg = 0, max_angle_deg = 0;
};

struct MeshResult {
  Mesh mesh;
  MeshStatus status = MeshStatus::NotApplicable;
  int iterations = 0;
  std::size_t cvt_vertices = 0;        ///< vertices of the start mesh (the CVT, or a refinement) before the hub patches
  std::size_t start_vertices = 0;      ///< vertices the repair began from: the start with its hub patches
  std::vector<BadTriangle> remaining;  ///< bad triangles left (first 100)
  CdtStats cdt;
  std::vector<std::string> notes;      ///< warnings and remarks for the user
};

/// Meshes a domain. \throws InvalidInput for an unusable domain or options.
MeshResult generate_mesh(const Domain& domain, const MeshOptions& options = {});

/// The CDT of a domain with the segment table stored in the mesh (build_cdt + set_segment_table).
/// Border edges on no input segment (the hull edges of a convex_hull domain) become segments too,
/// numbered domain.segments.size() + k in the table (their ends are input points).
Mesh build_domain_cdt(const Domain& domain, const CdtOptions& options = {}, CdtStats* stats = nullptr);

/// Area enclosed by the domain's mesh (sum of triangle areas of its CDT).
double mesh_area(const Mesh& mesh);

}  // namespace acute
