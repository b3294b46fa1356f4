#include <acute/mesher.h>

#include <acute/core/errors.h>
#include <acute/cvt/cvt.h>
#include <acute/mesh/geometry.h>
#include <acute/mesh/quality.h>
#include <acute/mesh/segments.h>
#include <acute/refine/refine.h>
#include <acute/repair/repair.h>

#include "cvt/in_place.h"
#include "pipeline/hub_patch.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace acute {

Method parse_method(const std::string& name) {
  if (name == "cdt") return Method::Cdt;
  if (name == "refine") return Method::Refine;
  if (name == "cvt") return Method::Cvt;
  if (name == "acute") return Method::Acute;
  throw InvalidInput("unknown method '" + name + "' (expected cdt, refine, cvt or acute)");
}

const char* to_string(Method method) {
  switch (method) {
    case Method::Cdt: return "cdt";
    case Method::Refine: return "refine";
    case Method::Cvt: return "cvt";
    case Method::Acute: return "acute";
  }
  return "?";
}

Mesh build_domain_cdt(const Domain& domain, const CdtOptions& options, CdtStats* stats) {
  Mesh mesh = build_cdt(domain, options, stats);
  SegmentTable table;
  table.reserve(domain.segments.size());
  for (const auto& s : domain.segments) table.push_back({domain.points[static_cast<std::size_t>(s[0])], domain.points[static_cast<std::size_t>(s[1])]});
  // A border edge that is no input segment (a -c hull edge) bounds the domain all the same: it
  // gets its own segment id after the input segments (as sample_domain gives them for the CVT
  // start), so that refinement and repair place points on its exact line and slide them only
  // along it. Left unconstrained, its Steiner points were free vertices at rounded midpoints
  // which the repair then moved off the hull (issue #9: hull_area_grows, hull_area_tiny_scale).
  for (auto eh : mesh.edges()) {
    if (is_constrained(mesh, eh) || !mesh.is_boundary(eh)) continue;
    const auto h = mesh.halfedge_handle(eh, 0);
    mesh.data(eh).segment = static_cast<int>(table.size());
    mesh.data(eh).marker = 0;
    table.push_back({point2(mesh, mesh.from_vertex_handle(h)), point2(mesh, mesh.to_vertex_handle(h))});
  }
  set_segment_table(mesh, std::move(table));
  return mesh;
}

double mesh_area(const Mesh& mesh) {
  double area = 0;
  for (auto fh : mesh.faces()) {
    const auto p = face_points(mesh, fh);
    area += 0.5 * signed_area2(p[0], p[1], p[2]);
  }
  return area;
}

namespace {

void check_options(const MeshOptions& o) {
  if (!(o.min_angle_deg >= 0) || !(o.max_angle_deg <= 180) || !(o.min_angle_deg < o.max_angle_deg))
    throw InvalidInput("angle bounds must satisfy 0 <= min < max <= 180");
  if (o.max_angle_deg <= 60 || o.min_angle_deg >= 60)
    throw InvalidInput("unsatisfiable angle bounds: every triangle has an angle >= 60 and one <= 60 degrees");
  if (o.size < 0 || !std::isfinite(o.size)) throw InvalidInput("--size must be a positive number");
  if (o.max_size < 0 || !std::isfinite(o.max_size)) throw InvalidInput("--max-size must be a positive number");
  if (!(o.gradation >= 1.0)) throw InvalidInput("--gradation must be at least 1");
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Target edge length from --size or --vertices (equilateral density: N = 2A / (sqrt(3) h^2)).
double target_edge(const MeshOptions& o, double area) {
  if (o.size > 0) return o.size;
  if (o.target_vertices > 0) return std::sqrt(2.0 * area / (std::sqrt(3.0) * static_cast<double>(o.target_vertices)));
  return 0;
}

/// A note naming the input sectors where the bounds cannot hold (the repair then keeps the best mesh
/// it finds and reports the rest), or "" when there is none.
std::string unsatisfiable_note(const Domain& domain, const MeshOptions& o) {
  const std::vector<ForcedCorner> sectors = unsatisfiable_sectors(domain, o.min_angle_deg, o.max_angle_deg);
  if (sectors.empty()) return "";
  const ForcedCorner& s = sectors.front();
  const Point2& p = domain.points[static_cast<std::size_t>(s.point)];
  char what[256];
  if (s.angle_deg < o.min_angle_deg)
    std::snprintf(what, sizeof what, "the %.4g-degree sector at (%.9g, %.9g) leaves its triangle an angle of at least %.4g degrees, not below the max %.4g",
                  s.angle_deg, p.x() + 0.0, p.y() + 0.0, 90.0 - 0.5 * s.angle_deg, o.max_angle_deg);
  else
    std::snprintf(what, sizeof what, "the %.4g-degree sector at (%.9g, %.9g) cannot be cut into triangle corners within [%.4g, %.4g)", s.angle_deg,
                  p.x() + 0.0, p.y() + 0.0, o.min_angle_deg, o.max_angle_deg);
  return "unsatisfiable bounds at " + std::to_string(sectors.size()) + " input corner(s) of this domain, e.g. " + what;
}

/// Under a time limit the features' own density is kept up to this many vertices per second of
/// the limit: a cautious rate for the acute pipeline on hard domains (CG:SHOP
/// simple-polygon-exterior_10_74050e4d at ~100 vertices: its strips' 12,700 vertices met the
/// bounds in 4.8 s, where held to 1,600 they kept 800 obtuse triangles for 60 s).
constexpr double kHeldVerticesPerSecond = 1000;

/// Degrees above (180 - sector) / 2 that the repair lets the base angles of an unsatisfiable
/// sector's apex triangle reach (AngleBounds::unsatisfiable_apex_slack_deg).
constexpr double kUnsatisfiableApexSlackDeg = 0.5;

/// Restarts are for a few stuck triangles, not for a mesh the repair could not get near the bounds.
constexpr std::size_t kRestartAtMost = 16;
/// A restart's seed: far from the seeds a user steps through (1, 2, 3 ...).
constexpr unsigned kRestartSeedStep = 7919;
/// Restart k also makes the start's size field this factor to the k finer. Another seed alone
/// often meets the same plateau: it comes from where the field puts the walls' points (CG:SHOP
/// simple-polygon-exterior_40_785575e7 at the default size kept one 90.0008-degree triangle at a
/// 34-degree corner with three seeds, and met the bounds in 1-4 s at 0.95 and 0.9 of the size).
constexpr double kRestartSizeScale = 0.95;

/// A number in a note: 1.5, 3, 1.35.
std::string format_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

/// The size gradation the acute method follows at most. The field's slope (gradation - 1) is how
/// much an edge may grow per unit of distance from a feature, and steeper fields lead the repair
/// into plateaus it does not escape: of the 150 CG:SHOP instances at their default size, 129 met
/// the bounds at 2 within 60 s; of the 21 misses (all exterior instances, with strips and narrow
/// sectors) 13 met them at 1.7 and all 21 at 1.5 and 1.4. At 3, Constrained_Sweden started with
/// 5,733 of its 6,280 triangles bad.
constexpr double kMaxAcuteGradation = 1.5;

/// Restart k's gradation: the excess over the default halved k times, never below the default.
/// A steep gradation's plateaus come from where sizes change fast, which another seed alone keeps
/// (square_with_crack at 1.5-2: a 28.8-degree triangle at a corner of its slot, three small
/// triangles between edges three times longer, with every seed).
double restart_gradation(double gradation, int k) {
  if (gradation <= kDefaultGradation) return gradation;
  return std::max(kDefaultGradation, 1.0 + (gradation - 1.0) * std::pow(0.5, k));
}

/// A run that a restart may follow stops after this many iterations without a new best
/// (RepairParams::stagnation_limit_before_restart); the last one keeps the repair's default.
constexpr int kStagnationBeforeRestart = 50;

/// One run of the method; `stalled` tells whether an acute repair ended on its own iteration
/// cap or stagnation (not at the time limit, the vertex budget or a cancel). size_scale: the
/// start's size field times this (CvtParams::size_scale); restart_may_follow: a stall with a few
/// bad triangles is given up sooner.
MeshResult generate_mesh_once(const Domain& domain, const MeshOptions& options, bool& stalled, double size_scale = 1.0,
                              bool restart_may_follow = false);

}  // namespace

MeshResult generate_mesh(const Domain& domain, const MeshOptions& options) {
  check_options(options);
  const auto start = std::chrono::steady_clock::now();
  bool stalled = false;
  MeshOptions first = options;
  std::string capped;
  if (options.method == Method::Acute && options.gradation > kMaxAcuteGradation) {
    first.gradation = kMaxAcuteGradation;
    capped = "gradation " + format_number(options.gradation) + " is steeper than the acute method follows: " + format_number(kMaxAcuteGradation) + " used";
  }
  MeshResult best = generate_mesh_once(domain, first, stalled, 1.0, options.restarts > 0);
  // The repair's search is local: on some domains one seed's start leads it into a plateau (a
  // few triangles that no edit improves) that another seed's start avoids. A run that stalls
  // with a few bad triangles is restarted from another seed, within what is left of the time
  // limit; the best result is kept.
  for (int k = 1; k <= options.restarts; ++k) {
    if (options.method != Method::Acute || best.status != MeshStatus::BoundsNotMet || !stalled || options.max_iterations > 0 ||
        best.remaining.size() > kRestartAtMost)
      break;
    // (Asked only here: it measures every input corner again, which most runs need not.)
    if (k == 1 && !unsatisfiable_note(domain, options).empty()) break;
    MeshOptions again = first;
    again.seed = options.seed + static_cast<unsigned>(k) * kRestartSeedStep;
    again.gradation = restart_gradation(first.gradation, k);
    if (options.time_limit_s > 0) {
      again.time_limit_s = options.time_limit_s - seconds_since(start);
      if (again.time_limit_s < 0.25 * options.time_limit_s) break;
    }
    const double size_scale = std::pow(kRestartSizeScale, k);
    MeshResult r = generate_mesh_once(domain, again, stalled, size_scale, k < options.restarts);
    const long finer_percent = std::lround(100 * (1 - size_scale));
    const std::string what = "the repair stalled with " + std::to_string(best.remaining.size()) + " bad triangle(s); restarted with seed " +
                             std::to_string(again.seed) + " and a " + std::to_string(finer_percent) + "% finer size" +
                             (again.gradation < first.gradation ? " graded at " + format_number(again.gradation) : std::string()) + ": " +
                             (r.status == MeshStatus::Ok ? "bounds met" : std::to_string(r.remaining.size()) + " left");
    if (r.status == MeshStatus::Ok || r.remaining.size() < best.remaining.size()) {
      r.iterations += best.iterations;
      best = std::move(r);
    }
    best.notes.push_back(what);
  }
  // (Here: a restart's result replaces the first run's, notes and all.)
  if (!capped.empty()) best.notes.insert(best.notes.begin(), capped);
  return best;
}

namespace {

MeshResult generate_mesh_once(const Domain& domain, const MeshOptions& options, bool& stalled, double size_scale, bool restart_may_follow) {
  stalled = false;
  const auto start = std::chrono::steady_clock::now();
  MeshResult result;
  auto notify = [&](const char* phase) {
    if (options.observer) options.observer(MeshProgress{phase, 0, 0, 0});
  };
  notify("cdt");
  result.mesh = build_domain_cdt(domain, options.cdt, &result.cdt);
  for (const auto& w : result.cdt.warnings) result.notes.push_back(w);
  switch (options.method) {
    case Method::Cdt: break;
    case Method::Refine: {
      notify("refine");
      RefineParams params;
      params.min_angle_deg = options.min_angle_deg;
      params.max_edge = target_edge(options, mesh_area(result.mesh));
      params.max_vertices = options.max_vertices;
      if (options.time_limit_s > 0) params.time_limit_s = std::max(options.time_limit_s - seconds_since(start), 1e-9);
      const RefineResult r = refine(result.mesh, params);
      if (r.status == RefineStatus::BudgetExhausted) result.notes.push_back("refinement stopped at the vertex budget");
      if (r.status == RefineStatus::OutOfTime) result.notes.push_back("refinement stopped at the time limit");
      break;
    }
    case Method::Cvt:
    case Method::Acute: {
      notify("cvt");
      CvtParams cp;
      cp.size = options.size;
      cp.target_vertices = options.target_vertices;
      // The acute repair needs the features resolved: with --size too, finer where they need it.
      cp.graded = options.size <= 0 || options.method == Method::Acute || options.cvt_as_repair_start;
      cp.gradation = options.gradation;
      cp.hmax = options.max_size;
      cp.size_cap = options.size_cap;
      cp.size_scale = size_scale;
      cp.seed = options.seed;
      // Share a time limit between the CVT (at most half) and the repair (the rest).
      if (options.time_limit_s > 0) cp.time_limit_s = std::max(0.5 * options.time_limit_s - seconds_since(start), 1e-9);
      cp.max_vertices = options.max_vertices;
      // Under a time limit a domain whose features need many times the vertex count and more than
      // the limit can mesh could not be meshed at their density in time anyway: the count stays
      // near the request.
      cp.hold_count = options.time_limit_s > 0;
      cp.held_count_at_least = kHeldVerticesPerSecond * options.time_limit_s;
      if (options.method == Method::Acute || options.cvt_as_repair_start) {
        // The repair does not need a converged CVT, only well-spread vertices: a short optimisation.
        cp.lbfgs_iterations = 40;
        cp.lfs_factor = 0.7;  // room for interior vertices in strips between input points
        cp.move_tolerance = 3e-3;
        cp.active_move = 1e-3;  // the lattice away from its boundary rows and seams is centroidal already
        cp.predict_settled = true;
        cp.lloyd_only_where_features_decide = true;
      }
      if (options.observer)
        cp.observer = [&](const CvtProgress& p) { options.observer(MeshProgress{"cvt", p.iteration, 0, p.energy, p.gradient_norm, p.phase}); };
      if (options.on_note && options.target_vertices > 0)
        cp.on_sampled = [&](std::size_t vertices, bool features_decide) {
          if (!features_decide) return;
          options.on_note("the domain's small features need " + std::to_string(vertices) + " vertices for the " +
                          std::to_string(options.target_vertices) +
                          " requested: expect a long run (--max-vertices bounds the count, --time-limit the time)");
        };
      // The fallback start: the CDT refined within the vertex budget and `seconds` (with a time limit).
      auto refine_start = [&](double seconds) {
        RefineParams rp;
        rp.min_angle_deg = std::min(options.min_angle_deg, 30.0);
        rp.max_edge = target_edge(options, mesh_area(result.mesh));
        rp.max_vertices = options.max_vertices;
        if (options.time_limit_s > 0) rp.time_limit_s = std::max(seconds, 1e-9);
        if (refine(result.mesh, rp).status == RefineStatus::OutOfTime) result.notes.push_back("the refinement start stopped at its share of the time limit");
      };
      // The CVT builds its start in result.mesh (no copy: see cvt/in_place.h); the fallbacks
      // refine the domain's CDT, built again.
      auto domain_cdt_again = [&] { result.mesh = build_domain_cdt(domain, options.cdt); };
      try {
        CvtResult cvt;
        detail::cvt_mesh_into(result.mesh, cvt, domain, cp);
        if (cvt.out_of_time && !cvt.abandoned) result.notes.push_back("the CVT start stopped at its share of the time limit");
        if (cvt.count_held)
          result.notes.push_back("the domain's small features need more vertices than the time limit allows at their density: held at about " +
                                 std::to_string(result.mesh.n_vertices()) + ", where thin parts seldom meet the bounds (a longer --time-limit keeps them)");
        if (cvt.abandoned || cvt.over_budget) {
          // A domain whose size field alone outlasts the time share, or whose CVT start needs more
          // vertices than allowed: its CDT, refined within what is left of the share and the budget,
          // is the best valid start the limits allow.
          if (cvt.abandoned)
            result.notes.push_back("the CVT start ran out of its share of the time limit in its size field; using a Delaunay refinement start");
          else
            result.notes.push_back("the CVT start needs " + std::to_string(result.mesh.n_vertices()) + " vertices, over the budget of " +
                                   std::to_string(options.max_vertices) + "; using a Delaunay refinement start within it");
          domain_cdt_again();
          // When the CVT's half is gone: up to 70% of the limit (at least 15% of it), the rest for the repair.
          refine_start(cvt.abandoned ? std::max(0.7 * options.time_limit_s - seconds_since(start), 0.15 * options.time_limit_s)
                                     : 0.5 * options.time_limit_s - seconds_since(start));
        } else {
          result.iterations = cvt.iterations;
        }
      } catch (const InvalidInput& e) {
        // The domain itself is fine (its CDT was built above): fall back to a refinement start.
        result.notes.push_back(std::string("CVT start failed (") + e.what() + "); using a Delaunay refinement start");
        domain_cdt_again();
        // As the CVT start: at most half the time limit, the repair has the rest.
        refine_start(0.5 * options.time_limit_s - seconds_since(start));
      }
      if (options.method == Method::Cvt) break;
      const std::string unsatisfiable = unsatisfiable_note(domain, options);
      if (!unsatisfiable.empty()) result.notes.push_back(unsatisfiable);
      // Strip hubs: the start's disk around each graded in log-polar coordinates (with a time limit,
      // within 30% of the time left: without a patch such a hub seldom meets the bounds at all).
      result.cvt_vertices = result.mesh.n_vertices();
      const double patch_seconds = options.time_limit_s > 0 ? std::max(0.3 * (options.time_limit_s - seconds_since(start)), 1e-9) : 0;
      const std::vector<Point2> patched_hubs = detail::patch_strip_hubs(result.mesh, options, patch_seconds);
      result.start_vertices = result.mesh.n_vertices();
      notify("repair");
      RepairParams params;
      params.bounds.min_deg = options.min_angle_deg;
      params.bounds.max_deg = options.max_angle_deg;
      // Where the bounds provably cannot hold, the apex triangles of the sectors too narrow for the
      // max bound count as good to the repair while nearly isosceles: else it spent itself on them
      // and left the rest (a tree of 10-degree forks at [35, 85): 56 obtuse triangles up to 143
      // degrees after 60 s). The verdict below is on the bounds asked for.
      if (!unsatisfiable.empty()) params.bounds.unsatisfiable_apex_slack_deg = kUnsatisfiableApexSlackDeg;
      params.graded_corners = patched_hubs;
      if (options.max_iterations > 0) params.max_iterations = options.max_iterations;
      params.max_vertices = options.max_vertices;
      if (restart_may_follow) {
        params.stagnation_limit_before_restart = kStagnationBeforeRestart;
        params.restart_at_most = kRestartAtMost;
      }
      if (options.time_limit_s > 0) params.time_limit_s = std::max(options.time_limit_s - seconds_since(start), 1e-9);
      if (options.observer)
        params.observer = [&](const RepairProgress& p) { options.observer(MeshProgress{"repair", p.iteration, p.bad, 0}); };
      const RepairResult r = repair_acute(result.mesh, params);
      stalled = r.status == RepairStatus::IterationLimit;
      result.iterations += r.iterations;
      result.status = r.status == RepairStatus::Converged ? MeshStatus::Ok : MeshStatus::BoundsNotMet;
      // A converged repair left nothing bad (its last scan found none): no whole-mesh scan again,
      // unless it worked to relaxed bounds.
      if (result.status == MeshStatus::Ok && unsatisfiable.empty()) break;
      AngleBounds asked = params.bounds;
      asked.unsatisfiable_apex_slack_deg = -1;
      const std::vector<FaceHandle> bad = bad_triangles(result.mesh, asked);
      if (!bad.empty()) result.status = MeshStatus::BoundsNotMet;
      for (auto fh : bad) {
        if (result.remaining.size() >= 100) break;
        BadTriangle t;
        t.corners = face_points(result.mesh, fh);
        const auto a = angles_deg(t.corners[0], t.corners[1], t.corners[2]);
        t.min_angle_deg = *std::min_element(a.begin(), a.end());
        t.max_angle_deg = *std::max_element(a.begin(), a.end());
        result.remaining.push_back(t);
      }
      break;
    }
  }
  if (options.target_vertices > 0 && result.mesh.n_vertices() > options.target_vertices + options.target_vertices / 10)
    result.notes.push_back("the mesh has " + std::to_string(result.mesh.n_vertices()) + " vertices for the " +
                           std::to_string(options.target_vertices) +
                           " requested: the domain's small features need a finer size than the request gives");
  return result;
}

}  // namespace

}  // namespace acute
