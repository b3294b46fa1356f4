// Layer: pipeline. Repairing an existing triangle mesh: remesh its region (boundary kept exactly)
// so every angle is within bounds, or keep every input vertex and only remove obtuse angles
// (the CG:SHOP 2025 "non-obtuse triangulation with required points" problem).
#pragma once

#include <acute/core/domain.h>
#include <acute/mesh/mesh.h>
#include <acute/mesher.h>

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace acute {

struct RepairMeshProgress {
  std::string phase;     ///< "check", "cvt", "repair"
  int iteration = 0;
  std::size_t bad = 0;   ///< bad triangles left (repair)
};

/// The start of the required-points repair.
enum class RequiredStart {
  /// With allow_right: the dedicated non-obtuse Steiner triangulation (non_obtuse_triangulation,
  /// exact rationals); when it leaves obtuse triangles, Refine then Cvt made non-obtuse by the
  /// acute repair and finished and pruned exactly (non_obtuse_from_start); the first exactly
  /// non-obtuse result is returned, else the one with fewest obtuse triangles. Without:
  /// Cdt, then Refine, then Cvt until one meets the bound (fewest Steiner points first)
  Auto,
  Cdt,     ///< the bare constrained Delaunay triangulation of the points
  Refine,  ///< Delaunay refinement of it (min angle 20)
  Cvt      ///< the CVT mesh with every input point fixed
};

struct RepairMeshOptions {
  /// Keep every input vertex exactly (interior ones too) and only bound the max angle: the
  /// required-points mode. Bounds default to min 0, max 90 (strict) then.
  bool keep_vertices = false;
  /// With keep_vertices: right angles are fine (max bound 90 + 1e-6, exact right angles accepted).
  bool allow_right = false;
  double min_angle_deg = 30.0;   ///< ignored with keep_vertices
  double max_angle_deg = 90.0;   ///< angles must be strictly below; ignored with keep_vertices
  /// > 0: consecutive boundary edges turning by less than this (every edge of the run within this
  /// angle of the run's chord) become one segment; their inner vertices are no longer kept. This
  /// changes the region unless the run is exactly straight. Not with keep_vertices.
  double feature_angle_deg = 0;
  /// Interior edges to keep (vertex index pairs of the input mesh; must be mesh edges).
  std::vector<std::array<int, 2>> features;
  RequiredStart start = RequiredStart::Auto;  ///< keep_vertices only
  Method method = Method::Acute;  ///< default mode only
  double size = 0;                 ///< target edge length (0: graded)
  std::size_t target_vertices = 0; ///< 0 (and size 0): graded by the features, never coarser than the input's mean spacing
  unsigned seed = 1;
  int max_iterations = 0;          ///< 0: the repair's default
  std::size_t max_vertices = 50'000'000;
  double time_limit_s = 0;         ///< the whole repair (start mesh and repair; all starts together with keep_vertices); 0: none
  std::function<void(const RepairMeshProgress&)> progress;
  std::function<bool()> cancel;    ///< polled during the repair; true stops it (best mesh kept)
};

enum class RepairMeshStatus {
  Ok,            ///< every angle within the bounds (forced input corners excepted)
  BoundsNotMet,  ///< the best mesh found still has bad triangles
  Cancelled,     ///< stopped by options.cancel (best mesh so far returned)
  NotApplicable  ///< methods without angle bounds (cdt, cvt)
};

struct RepairMeshResult {
  RepairMeshStatus status = RepairMeshStatus::NotApplicable;
  Mesh mesh;                    ///< the repaired mesh (libacute kinds and constraints set)
  Domain domain;                ///< the domain that was meshed (input points are the kept vertices)
  std::size_t n_input_vertices = 0, n_vertices = 0, n_triangles = 0;
  std::size_t n_steiner = 0;    ///< vertices not at a domain point
  std::size_t n_bad = 0;        ///< triangles outside the bounds (float angles, as meshcheck)
  std::size_t n_obtuse_exact = 0;  ///< triangles with an exactly obtuse angle (predicates)
  std::size_t n_right_exact = 0;   ///< triangles with an exactly right angle
  double min_angle_deg = 0, max_angle_deg = 0;
  int iterations = 0;
  std::string start;            ///< required points: the start that was kept ("non-obtuse", "cdt", "refine", "cvt")
  /// Exact coordinates ("p" or "p/q") of every mesh vertex by index when the mesh holds rational
  /// points (the non-obtuse mode); empty when the doubles are the points. Pass to the io writers.
  std::vector<std::array<std::string, 2>> exact_coordinates;
  std::vector<BadTriangle> remaining;  ///< first bad triangles left (up to 100)
  std::vector<std::string> notes;
};

/// Throws InvalidInput naming the first offending element when the mesh is not a valid planar
/// triangulation we can repair: no faces, non-triangles, inverted or degenerate faces, repeated
/// positions, boundary loops that cross, touch or nest wrongly (a region covered twice).
void check_repairable(const Mesh& mesh);

/// The domain the repair keeps: boundary edges as segments, boundary vertices (all vertices with
/// keep_vertices) as points, hole seeds, feature edges as interior segments; boundary runs merged
/// by feature_angle_deg. Point k of the domain is input vertex vertex_of_point[k] when given.
Domain repair_domain(const Mesh& mesh, const RepairMeshOptions& options, std::vector<int>* vertex_of_point = nullptr);

/// Repairs a mesh read with io::read_mesh or from_openmesh (kinds and constraints of the input
/// are ignored). \throws InvalidInput for an invalid mesh, features or options.
RepairMeshResult repair_mesh(const Mesh& input, const RepairMeshOptions& options = {});

/// Required-points mode on a domain (e.g. a CG:SHOP instance). With allow_right and
/// RequiredStart::Auto: the exact non-obtuse solver and its fallbacks (see RequiredStart::Auto;
/// result.exact_coordinates set; 40% of the time limit for the CDT search). Else a
/// start mesh holding every input point (options.start), then the repair with min 0, max 90.
/// With RequiredStart::Auto the starts are tried in order of cost in Steiner points, each with a
/// share of the time limit, until one meets the bound exactly; else the one with fewest bad triangles.
RepairMeshResult repair_required_points(const Domain& domain, const RepairMeshOptions& options = {});

/// The library entry point for a user's OpenMesh triangle mesh of any traits: repairs it and
/// writes the result back into `mesh` (cleared first; float or double points, z = 0).
template <class UserMesh>
RepairMeshResult repair(UserMesh& mesh, const RepairMeshOptions& options = {}) {
  RepairMeshResult result = repair_mesh(from_openmesh(mesh), options);
  to_openmesh(result.mesh, mesh);
  return result;
}

const char* to_string(RepairMeshStatus status);

}  // namespace acute
