// Layer: cvt. Centroidal Voronoi tessellation meshing: size field, sampling, CDT, then Lloyd and
// L-BFGS on the CVT energy of the clipped Voronoi cells (voronoi.h) with the constrained Delaunay
// property restored after every step. L-BFGS keeps its correction pairs in LBFGS++'s BFGSMat but
// runs its own loop: a requested step cannot always be realised (a move that would invert a
// triangle or leave its segment is shortened), so the pair must use the step actually taken,
// which LBFGSSolver / LBFGSBSolver (whose line searches evaluate exactly the point they ask for)
// cannot do.
#pragma once

#include <acute/core/domain.h>
#include <acute/cvt/sampling.h>
#include <acute/cvt/size_field.h>
#include <acute/cvt/voronoi.h>
#include <acute/mesh/mesh.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace acute {

/// One iteration, reported to CvtParams::observer / CvtOptimizeParams::observer.
struct CvtProgress {
  const char* phase = "";        ///< "lloyd" or "lbfgs"
  int iteration = 0;             ///< counted over both phases, starting at 1
  double energy = 0;             ///< F after the iteration
  double gradient_norm = 0;      ///< |dF/dX| over the moving coordinates (Euclidean)
  double max_move = 0;           ///< max over moving vertices of |v - c_v| / h(v) (projected on segments)
  double rms_move = 0;           ///< root mean square of the same
  std::size_t flips = 0;         ///< Delaunay flips done after the step
  std::size_t blocked = 0;       ///< vertices whose move had to be shortened or dropped
  bool fallback = false;         ///< lbfgs: the line search failed, a Lloyd step was taken
};

struct CvtOptimizeParams {
  int lloyd_iterations = 10;     ///< Lloyd steps first (robust start from random samples)
  int lbfgs_iterations = 200;    ///< then at most this many L-BFGS iterations
  int lbfgs_memory = 7;          ///< stored correction pairs (geogram's default)
  double move_tolerance = 1e-3;      ///< stop when rms |v - c_v| / h(v) < this
  double max_move_tolerance = 1e-4;  ///< or when max |v - c_v| / h(v) < this
  double energy_tolerance = 1e-12;   ///< or when |dF| <= this * F over an iteration
  /// Vertices allowed to move (Input vertices are ignored); empty: every non-input vertex. With a
  /// subset, the energy is taken over the faces around it only (local smoothing).
  std::vector<VertexHandle> subset;
  double time_limit_s = 0;         ///< > 0: stop after this many seconds (not converged)
  /// > 0 (whole-mesh runs only): after the first evaluation, only the vertices whose move
  /// |v - c_v| / h(v) exceeds this, and two rings around them, are optimised, when they are at
  /// most half the movers (a lattice start is centroidal already away from its boundary rows and
  /// level seams). The others keep moves below this; the rms test counts them as still.
  double active_move = 0;
  /// With active_move: the first evaluation of every cell is skipped; the vertices whose cell is
  /// known to have settled (a free interior vertex in a regular hexagon of neighbours where the
  /// size field is too even to move it by active_move / 2) are left out instead of those the
  /// evaluation finds still (found without integrating a cell: the exact set or a little more on
  /// every domain tried; that evaluation is most of the optimisation's time on a lattice start). The
  /// energies reported then hold the frozen cells' energies as those of their hexagons.
  bool predict_settled = false;
  std::function<void(const CvtProgress&)> observer;
};

struct CvtOptimizeResult {
  int lloyd_iterations = 0;
  int lbfgs_iterations = 0;
  int fallbacks = 0;              ///< L-BFGS iterations replaced by a Lloyd step
  double initial_energy = 0;
  double energy = 0;
  double gradient_norm = 0;
  double max_move = 0;
  double rms_move = 0;
  bool converged = false;         ///< a tolerance was met (not the iteration cap)
  std::size_t active = 0;         ///< vertices optimised after the first evaluation (active_move)
};

/// Optimises the vertex positions of a constrained Delaunay mesh (segment table set when it has
/// OnSegment vertices) for the CVT energy: Free vertices in 2D, OnSegment vertices along their
/// segment, Input vertices fixed. After every step the moves are applied with can_relocate/relocate
/// (a move that would invert a triangle is halved up to 8 times, then dropped) and the constrained
/// Delaunay property restored by flips. A move may not bring a vertex closer to a constrained edge
/// of its link than min(its current distance, h/4) (else it is halved too). Deterministic. The mesh keeps its vertex set; faces and
/// edges may be flipped (no garbage collection).
CvtOptimizeResult cvt_optimize(Mesh& mesh, const SizeField& field, const CvtOptimizeParams& params = {});

struct CvtParams {
  double size = 0;                 ///< --size H (uniform, or the largest with graded)
  std::size_t target_vertices = 0; ///< --vertices N (uniform, calibrated)
  bool graded = false;             ///< SizeFieldParams::graded (with target_vertices or size)
  double gradation = 1.3;          ///< graded default field
  double lfs_factor = 1.0;
  double hmax = 0;                 ///< 0: diameter / 25
  /// When set: the graded field is at most size_cap(p) (taken at its background points; values
  /// <= 0 or not finite are no cap). No effect on a uniform field (--size, or graded = false).
  std::function<double(const Point2&)> size_cap;
  /// Every size of the field times this (SizeFieldParams::scale; size_cap still caps it): a
  /// restart's slightly finer start (see MeshOptions::restarts).
  double size_scale = 1.0;
  int lloyd_iterations = 10;
  int lbfgs_iterations = 200;
  double move_tolerance = 1e-3;     ///< rms |v - c_v| / h(v) to stop at
  double active_move = 0;           ///< CvtOptimizeParams::active_move (0: every vertex throughout)
  bool predict_settled = false;     ///< CvtOptimizeParams::predict_settled
  unsigned seed = 1;
  InteriorSampling interior = InteriorSampling::Lattice;  ///< the seeds of the interior
  /// > 0: the whole CVT start (size field, sampling, optimisation) stops after this many seconds:
  /// the field's calibration keeps its best so far, the optimisation gets what is left (none when
  /// nothing is; the sampled mesh is valid as it is)
  double time_limit_s = 0;
  /// > 0: at most this many vertices (the field is coarsened and the domain resampled when the
  /// samples exceed it; only the input points alone can exceed it, then CvtResult::over_budget)
  std::size_t max_vertices = 0;
  bool hold_count = false;  ///< SizeFieldParams::hold_count
  double held_count_at_least = 0;  ///< SizeFieldParams::held_count_at_least
  /// No L-BFGS steps when the features decide the vertex count (make_size_field's
  /// features_decide): such a mesh is mostly strips a row or two wide, whose Voronoi cells are all
  /// clipped by the walls, and the steps cost more than they give a repair that follows (debug2 at
  /// 2,000 vertices: the CVT start 613 s with them, 149 s without, the whole run 30.8 min against
  /// 19.5; its 9-degree wedge at 1,000 vertices 52 s against 31 s, side by side)
  bool lloyd_only_where_features_decide = false;
  std::function<void(const CvtProgress&)> observer;
  /// Called once the domain is sampled, before the optimisation: the vertex count, and whether the
  /// features decided it (CvtResult::features_decide). Lets a caller warn early of a long run.
  std::function<void(std::size_t vertices, bool features_decide)> on_sampled;
};

struct CvtResult {
  Mesh mesh;                  ///< the optimised constrained Delaunay mesh (compacted), segment table set
  SizeField size_field;       ///< the field used (for later local smoothing)
  SamplingStats sampling;
  CvtOptimizeResult optimization;
  int iterations = 0;         ///< lloyd + lbfgs
  double energy = 0;
  double gradient_norm = 0;
  bool over_budget = false;   ///< more vertices than max_vertices even at the coarsest field tried
  bool out_of_time = false;   ///< the time limit ended the start before the optimisation did
  bool features_decide = false;  ///< the size field stopped at kCoarsestLfsFactor * lfs (make_size_field)
  bool count_held = false;       ///< hold_count coarsened the field past that (make_size_field's held)
  /// The time limit ran out before there were samples to optimise (a huge domain: its size field
  /// alone outlasts the limit): mesh is empty, the caller keeps a mesh it has (the domain's CDT)
  bool abandoned = false;
};

/// build_cdt(domain) -> size field -> sample_domain -> cvt_optimize.
/// \throws InvalidInput as build_cdt does, or for a non-positive size.
CvtResult cvt_mesh(const Domain& domain, const CvtParams& params = {});

}  // namespace acute
