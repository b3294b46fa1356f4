#include <acute/repair/repair.h>

#include <acute/mesh/geometry.h>
#include <acute/mesh/sectors.h>
#include <acute/mesh/segments.h>
#include <acute/ops/delaunay_flips.h>
#include <acute/ops/insert.h>
#include <acute/ops/remove.h>
#include <acute/repair/clusters.h>
#include <acute/repair/joint_relaxation.h>
#include <acute/repair/relocation.h>

#include "repair/hub_ring.h"
#include "repair/local_remesh.h"
#include "repair/polar_fan.h"
#include "repair/region.h"
#include "repair/sector_refan.h"

#include <acute/core/errors.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <chrono>
#include <cmath>
#include <functional>

namespace acute {

std::vector<FaceHandle> bad_triangles(const Mesh& mesh, const AngleBounds& bounds) {
  const auto forced = forced_corner_vertices(mesh, bounds.min_deg);
  std::vector<FaceHandle> bad;
  for (auto fh : mesh.faces())
    if (is_bad_triangle(mesh, fh, bounds, forced)) bad.push_back(fh);
  return bad;
}

namespace {

/// On a plateau (this many iterations without a new best), every kKickEvery-th iteration each
/// cluster that no candidate improves takes its best candidate anyway: a local optimum of the
/// search (a segment vertex with two right triangles on one side, where every single edit scores
/// worse) is left for a neighbouring one. The best mesh so far is kept aside, so a kick costs
/// nothing when it leads nowhere.
constexpr int kKickAfter = 10, kKickEvery = 5;

class Repairer {
 public:
  Repairer(Mesh& mesh, const RepairParams& params) : mesh_(mesh), params_(params), bounds_(params.bounds) {}

  RepairResult run() {
    t0_ = std::chrono::steady_clock::now();
    refresh_forced();
    if (paranoid_) {
      const std::string problem = detail::constraint_violation(mesh_);
      if (!problem.empty()) throw InternalError("repair: input mesh: " + problem);
    }
    if (params_.grade_sharp_corners) {
      grade_sharp_corners();
      ring_strip_hubs();
    }
    std::size_t best_bad = SIZE_MAX;
    Mesh best;
    bool current_is_best = true;
    int stagnation = 0;
    for (int it = 0;; ++it) {
      const auto clusters = find_clusters(mesh_, bounds_, forced_);
      std::size_t bad = 0;
      for (const auto& c : clusters) bad += c.bad.size();
      if (it == 0) result_.bad_before = bad;
      result_.iterations = it;
      const bool global = it < params_.global_iterations && bad * params_.global_ratio >= mesh_.n_faces() - deleted_faces_;
      if (params_.observer) params_.observer(RepairProgress{it, bad, global});
      if (trace_) std::fprintf(stderr, "iteration %d: %zu bad in %zu clusters, %zu vertices%s\n", it, bad, clusters.size(), mesh_.n_vertices(), global ? " (global)" : "");
      // The mesh as it is now is the best so far when no earlier one had fewer bad triangles; it
      // is copied aside only when another iteration follows (a copy of an 800k-vertex mesh
      // costs 0.4 s, and a run stopped by its time limit needs none).
      current_is_best = bad <= best_bad;
      const bool improved = bad < best_bad;
      if (improved) {
        best_bad = bad;
        stagnation = 0;
      } else {
        ++stagnation;
      }
      stuck_ = stagnation;
      kick_ = stagnation >= kKickAfter && stagnation % kKickEvery == 0;
      if (bad == 0) {
        result_.status = RepairStatus::Converged;
        break;
      }
      const bool restart_follows = params_.stagnation_limit_before_restart > 0 && best_bad <= params_.restart_at_most;
      if (it >= params_.max_iterations || stagnation > (restart_follows ? params_.stagnation_limit_before_restart : params_.stagnation_limit)) {
        result_.status = RepairStatus::IterationLimit;
        break;
      }
      if (out_of_time()) {
        result_.status = RepairStatus::TimeLimit;
        break;
      }
      if (params_.cancel && params_.cancel()) {
        result_.status = RepairStatus::Cancelled;
        break;
      }
      if (mesh_.n_vertices() - deleted_vertices_ >= params_.max_vertices) {
        result_.status = RepairStatus::VertexBudget;
        break;
      }
      if (improved) best = mesh_;
      iterate(clusters, global, it);
      collect_garbage_when_worth_it();
      refresh_forced();
    }
    if (!current_is_best && best.n_faces() > 0) mesh_ = std::move(best);
    collect_garbage(mesh_);
    // Converged: the last scan found nothing bad, and compaction moves no vertex.
    result_.bad_after = result_.status == RepairStatus::Converged ? 0 : bad_triangles(mesh_, bounds_).size();
    return result_;
  }

 private:
  bool out_of_time() const {
    return params_.time_limit_s > 0 &&
           std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count() > params_.time_limit_s;
  }

  void refresh_forced() { forced_ = forced_corner_vertices(mesh_, bounds_.min_deg); }

  /// Compacts the mesh between iterations only when an eighth of its faces or vertices are
  /// deleted: a collection costs 0.25 s per million triangles however little was deleted, and
  /// every sweep skips deleted elements anyway. Counts what stays deleted (the vertex budget and
  /// the global phase count live elements).
  void collect_garbage_when_worth_it() {
    auto deleted = [&](auto range) {
      std::size_t n = 0;
      for (auto h : range) n += mesh_.status(h).deleted() ? 1 : 0;
      return n;
    };
    deleted_vertices_ = deleted(mesh_.all_vertices());
    deleted_faces_ = deleted(mesh_.all_faces());
    if (8 * deleted_vertices_ <= mesh_.n_vertices() && 8 * deleted_faces_ <= mesh_.n_faces()) return;
    collect_garbage(mesh_);
    deleted_vertices_ = deleted_faces_ = 0;
  }

  /// Rebuilds the disk around the input vertex apex_big: a region copy of the movable vertices
  /// within `radius` of it, `rebuild` on the copy, a few smoothing sweeps, and the copy written back
  /// where it then has fewer infeasible vertices (structural defects no smoothing fixes, which
  /// outweigh more bad triangles where the new part meets the old mesh: the repair smooths those
  /// out) or a better score. True when written back.
  bool rebuild_disk(VertexHandle apex_big, double radius, const char* what, const std::function<bool(Mesh&, VertexHandle)>& rebuild) {
    std::vector<VertexHandle> near = vertices_near(mesh_, apex_big, radius);
    detail::Region region;
    if (near.empty() || !detail::extract_region(mesh_, near, forced_, region)) return false;
    VertexHandle apex;
    for (auto vh : region.sub.vertices()) {
      const auto i = static_cast<std::size_t>(vh.idx());
      if (i < region.to_big.size() && region.to_big[i] == apex_big) apex = vh;
    }
    if (!apex.is_valid()) return false;
    const Score base = score(region.sub, region.forced);
    Mesh sub = region.sub;
    if (!rebuild(sub, apex)) return false;
    smooth_sub(sub, region.forced, 3);
    const Score s = score(sub, region.forced);
    if (trace_) {
      const Point2 c = point2(mesh_, apex_big);
      std::fprintf(stderr, "%s (%.6g, %.6g), disk %.4g: %zu vertices near; infeasible %zu -> %zu, bad %zu -> %zu, worst %.4f -> %.4f\n", what, c.x(), c.y(),
                   radius, near.size(), base.infeasible, s.infeasible, base.bad, s.bad, base.worst, s.worst);
    }
    if (!(s < base || s.infeasible < base.infeasible)) return false;
    detail::commit_region(mesh_, region, sub);
    forced_.resize(mesh_.n_vertices(), false);
    return true;
  }

  /// The disk around each forced corner (a sector narrower than the min bound) rebuilt as a
  /// log-polar fan (detail::build_polar_fan), with a margin for the smoothing to blend the two.
  void grade_sharp_corners() {
    constexpr double kPi = 3.14159265358979323846;
    bool changed = false;
    for (const detail::SharpCorner& corner : detail::find_sharp_corners(mesh_, bounds_.min_deg * kPi / 180)) {
      if (out_of_time()) break;
      if (mesh_.status(corner.apex).deleted() || graded_already(corner.apex)) continue;
      changed = rebuild_disk(corner.apex, 1.5 * corner.radius, "sharp corner", [&](Mesh& sub, VertexHandle apex) {
                  return detail::build_polar_fan(sub, apex, corner.radius, detail::kPolarFanRings, bounds_.max_deg * kPi / 180);
                }) || changed;
    }
    // (The loop's sweeps skip deleted elements: a collection, 0.1 s per million triangles, waits
    // until enough are deleted.)
    if (changed) {
      collect_garbage_when_worth_it();
      refresh_forced();
    }
  }

  /// The wide sectors beside strips at every input vertex rebuilt as rings (detail::rebuild_hub_ring)
  /// over the apex's whole star.
  void ring_strip_hubs() {
    constexpr double kPi = 3.14159265358979323846;
    const double strip_below = bounds_.min_deg * kPi / 180;
    std::vector<std::pair<VertexHandle, double>> hubs;
    for (auto vh : mesh_.vertices())
      if (!mesh_.status(vh).deleted() && is_input(mesh_, vh) && forced(vh) && !graded_already(vh))
        if (const double reach = detail::hub_ring_reach(mesh_, vh, strip_below); reach > 0) hubs.emplace_back(vh, reach);
    bool changed = false;
    for (const auto& [apex, reach] : hubs) {
      if (out_of_time()) break;
      changed = rebuild_disk(apex, 1.6 * reach, "hub ring", [&](Mesh& sub, VertexHandle a) { return detail::rebuild_hub_ring(sub, a, strip_below, bounds_.max_deg * kPi / 180); }) ||
                changed;
    }
    if (changed) {
      collect_garbage_when_worth_it();
      refresh_forced();
    }
  }

  bool graded_already(VertexHandle vh) const {
    const auto& done = params_.graded_corners;
    return std::find(done.begin(), done.end(), point2(mesh_, vh)) != done.end();
  }

  bool forced(VertexHandle vh) const { return is_forced(forced_, vh); }

  void restore_around(VertexHandle vh) {
    queue_.clear();
    push_star_edges(mesh_, vh, queue_);
    restore_delaunay(mesh_, queue_);
  }

  /// Relocates every vertex in `vertices` (a few sweeps), restoring Delaunay after each move.
  void smooth(std::vector<VertexHandle> vertices, int sweeps) {
    for (int s = 0; s < sweeps; ++s) {
      bool moved_any = false;
      std::size_t k = 0;
      for (auto vh : vertices) {
        if ((++k & 63) == 0 && out_of_time()) return;  // a global sweep on a huge mesh outlasts the limit
        if (mesh_.status(vh).deleted()) continue;
        if (relocate_for_angles(mesh_, vh, bounds_, forced_)) {
          ++result_.relocated;
          moved_any = true;
          restore_around(vh);
        }
      }
      if (!moved_any) break;
    }
  }

  /// The vertices of the given ones and their neighbours (1-ring), deduplicated.
  std::vector<VertexHandle> grow(const std::vector<VertexHandle>& seeds, int rings) {
    // Marks kept between calls: no allocation of the mesh's size per cluster.
    return with_rings(mesh_, seeds, rings, seen_);
  }

  void iterate(const std::vector<Cluster>& clusters, bool global, int it) {
    if (global) {
      // Global phase: relocate every vertex whose star is near the bounds, over the whole mesh.
      // Each face's margin once (a vertex's star margin is the least over its faces): a third of
      // the work of asking every vertex for its star's.
      std::vector<VertexHandle> near;
      face_margin_.assign(mesh_.n_faces(), INFINITY);
      std::size_t k = 0;
      for (auto fh : mesh_.faces()) {
        if ((++k & 4095) == 0 && out_of_time()) return;
        face_margin_[static_cast<std::size_t>(fh.idx())] = triangle_margin(mesh_, fh, bounds_, face_is_exempt(mesh_, fh, forced_));
      }
      for (auto vh : mesh_.vertices()) {
        if (is_input(mesh_, vh)) continue;
        double margin = INFINITY;
        for (auto heh : mesh_.voh_range(vh))
          if (!mesh_.is_boundary(heh)) margin = std::min(margin, face_margin_[static_cast<std::size_t>(mesh_.face_handle(heh).idx())]);
        if (margin < 4.0) near.push_back(vh);
      }
      const std::size_t relocated0 = result_.relocated;
      smooth(near, 1);
      if (trace_) std::fprintf(stderr, "global phase: %zu vertices near the bounds, %zu moved\n", near.size(), result_.relocated - relocated0);
    }
    // Local phase: each cluster's neighbourhood is copied, candidate operations are tried on the
    // copy, and the best one is written back when it improves the region.
    const int rings = 1 + it % 4;
    for (const auto& c : clusters) {
      if (out_of_time()) break;
      bool stale = false;
      for (auto fh : c.bad) stale = stale || mesh_.status(fh).deleted();
      for (auto vh : c.vertices) stale = stale || mesh_.status(vh).deleted();
      if (stale) continue;
      std::vector<VertexHandle> movable;
      for (auto vh : grow(c.vertices, rings - 1))
        if (!mesh_.status(vh).deleted()) movable.push_back(vh);
      detail::Region region;
      if (!detail::extract_region(mesh_, movable, forced_, region)) continue;
      const Score base = score(region.sub, region.forced);
      // Nothing bad or infeasible left here (the global phase, or an earlier cluster's edit, fixed
      // it since the clusters were found): a search could only widen margins that already hold.
      // (A quarter of the square's clusters at 1M and three quarters of Constrained_Sweden's.)
      if (base.bad == 0 && base.infeasible == 0) continue;
      if (trace_) {
        const auto p = face_points(mesh_, c.bad[0]);
        std::fprintf(stderr, "it %d cluster at (%.6g, %.6g): %zu bad, region %zu faces, base infeasible %zu bad %zu worst %.4f\n", it, p[0].x(),
                     p[0].y(), c.bad.size(), region.big_faces.size(), base.infeasible, base.bad, base.worst);
      }
      std::shared_ptr<const Mesh> best;
      Score best_score = base;
      kicked_ = false;
      search(region, stuck_ > 1, best, best_score);
      if (trace_)
        std::fprintf(stderr, "  best: candidate %d, infeasible %zu bad %zu worst %.4f%s\n", best_candidate_, best_score.infeasible, best_score.bad, best_score.worst,
                     best_score < base ? " (written back)" : kicked_ ? " (written back: a kick)" : " (kept the region as it was)");
      if (best_score < base || kicked_) {
        if (paranoid_) {
          auto area = [](const Mesh& m) { double a = 0; for (auto fh : m.faces()) { const auto p = face_points(m, fh); a += signed_area2(p[0], p[1], p[2]); } return a; };
          const double a0 = area(region.sub), a1 = area(*best);
          if (std::abs(a0 - a1) > 1e-9 * std::abs(a0))
            throw InternalError("repair: candidate " + std::to_string(best_candidate_) + " changed the region area " + std::to_string(a0) + " -> " + std::to_string(a1));
        }
        detail::commit_region(mesh_, region, *best);
        if (paranoid_) {
          double total = 0;
          for (auto fh : mesh_.faces()) { const auto p = face_points(mesh_, fh); total += signed_area2(p[0], p[1], p[2]); }
          if (paranoid_area_ == 0) paranoid_area_ = total;
          if (std::abs(total - paranoid_area_) > 1e-9 * paranoid_area_)
            throw InternalError("repair: a cluster edit changed the mesh area (candidate " + std::to_string(best_candidate_) + ")");
          const std::string sub_problem = detail::constraint_violation(*best);
          const std::string problem = detail::constraint_violation(mesh_);
          if (!problem.empty()) throw InternalError("repair: after a cluster edit: " + problem + " (region copy: " + sub_problem + ")");
        }
        forced_.resize(mesh_.n_vertices(), false);
        ++result_.committed;
        if (best_kind_ >= 0 && best_score.bad == 0 && best_score.infeasible == 0) ++wins_[static_cast<std::size_t>(best_kind_)];
      }
    }
  }

  /// Lower is better: infeasible vertices (whose angle sum cannot be shared among their triangles
  /// within the bounds: no relocation can fix them), each weighted as several bad triangles, plus
  /// the badness of the bad triangles; ties go to the larger worst margin.
  struct Score {
    static constexpr double kInfeasibleWeight = 6.0;
    std::size_t infeasible = 0;
    std::size_t bad = 0;
    double badness = 0;  ///< sum over bad triangles of 1 + violation / 5 degrees: severity counts too
    double worst = INFINITY;
    bool operator<(const Score& o) const {
      // An infeasible vertex weighs as much as a few bad triangles: an edit that removes one but
      // leaves dozens of new bad triangles behind is no progress.
      const double mine = kInfeasibleWeight * static_cast<double>(infeasible) + badness;
      const double theirs = kInfeasibleWeight * static_cast<double>(o.infeasible) + o.badness;
      if (std::abs(mine - theirs) > 1e-9) return mine < theirs;
      return worst > o.worst + 1e-9;
    }
  };

  Score score(const Mesh& sub, const std::vector<bool>& forced) const {
    Score s;
    for (auto fh : sub.faces()) {
      const double m = triangle_margin(sub, fh, bounds_, face_is_exempt(sub, fh, forced));
      s.worst = std::min(s.worst, m);
      if (m < bounds_.margin_deg) {
        ++s.bad;
        s.badness += 1.0 + (bounds_.margin_deg - m) / 5.0;
      }
    }
    for (auto vh : sub.vertices())
      if (!sub.status(vh).deleted() && !on_frozen_border(sub, vh)) s.infeasible += infeasible_sectors(sub, vh, is_forced(forced, vh));
    return s;
  }

  /// A vertex on an unconstrained boundary edge: the frozen border of a region copy (its star is partial).
  static bool on_frozen_border(const Mesh& sub, VertexHandle vh) {
    for (auto heh : sub.voh_range(vh))
      if (sub.data(sub.edge_handle(heh)).frozen || (sub.is_boundary(sub.edge_handle(heh)) && !is_constrained(sub, sub.edge_handle(heh))))
        return true;
    return false;
  }

  /// Sectors around vh (between constrained or boundary edges; the whole star when none) whose
  /// angle phi split among k triangles cannot meet the bounds: phi / k >= max, or phi / k < min for a
  /// sector not narrower than min at a vertex not `exempt` (at a forced corner's vertex every
  /// triangle is exempt from the min bound: a log-polar hub fans its wide sectors finely). Frozen
  /// border vertices of a region copy are skipped by the caller.
  std::size_t infeasible_sectors(const Mesh& sub, VertexHandle vh, bool exempt) const {
    std::size_t count = 0;
    for_each_sector(sub, vh, 64, [&](HalfedgeHandle, const SectorSweep& sector, bool) {
      const double share = sector.degrees / sector.triangles;
      if (share >= bounds_.max_deg - bounds_.margin_deg || (!exempt && sector.degrees >= bounds_.min_deg && share < bounds_.min_deg)) ++count;
    });
    return count;
  }

  static bool is_forced(const std::vector<bool>& forced, VertexHandle vh) {
    const auto i = static_cast<std::size_t>(vh.idx());
    return i < forced.size() && forced[i];
  }

  static bool face_is_exempt(const Mesh& mesh, FaceHandle fh, const std::vector<bool>& forced) {
    for (auto vh : mesh.fv_range(fh))
      if (is_forced(forced, vh)) return true;
    return false;
  }

  /// Relocates the movable vertices of a region copy (a few sweeps, Delaunay restored after each move).
  /// A vertex that did not move is skipped in later sweeps until its star changes (a neighbour
  /// moved, or a flip changed it): relocation reads no more than the star, so it would stay again.
  void smooth_sub(Mesh& sub, const std::vector<bool>& forced, int sweeps) {
    std::vector<EdgeHandle>& queue = queue_;  // (restore_around's too: never in use at once)
    std::vector<VertexHandle>& touched = sub_touched_;
    std::vector<char>& settled = sub_settled_;  // 1: did not move, star unchanged since
    settled.assign(sub.n_vertices(), 0);
    std::size_t k = 0;
    for (int s = 0; s < sweeps; ++s) {
      bool moved = false;
      for (auto vh : sub.vertices()) {
        // A large region's sweeps outlast a short limit (the sanitizer build took 25 s under 2 s).
        if ((++k & 63) == 0 && out_of_time()) return;
        const auto i = static_cast<std::size_t>(vh.idx());
        if (settled[i] || sub.status(vh).deleted() || is_input(sub, vh)) continue;
        if (!relocate_for_angles(sub, vh, bounds_, forced)) {
          settled[i] = 1;
          continue;
        }
        moved = true;
        queue.clear();
        touched.clear();
        push_star_edges(sub, vh, queue);
        restore_delaunay(sub, queue, &touched);
        for (auto w : sub.vv_range(vh)) touched.push_back(w);
        for (auto w : touched) settled[static_cast<std::size_t>(w.idx())] = 0;
      }
      if (!moved) break;
    }
  }

  /// Joint relaxation of every movable vertex of a region copy, then Delaunay restoration and a
  /// sweep of one-vertex relocation.
  void relax_sub(Mesh& sub, const std::vector<bool>& forced) {
    std::vector<VertexHandle> all;
    for (auto vh : sub.vertices())
      if (!sub.status(vh).deleted()) all.push_back(vh);
    if (!relax_jointly(sub, all, bounds_, forced)) return;
    make_delaunay(sub);
    smooth_sub(sub, forced, 1);
  }

  /// Best of the candidate operations; when `deep`, also every candidate applied to the four best
  /// results of the first level (two-step edits for clusters no single operation improves).
  void search(const detail::Region& region, bool deep, std::shared_ptr<const Mesh>& best, Score& best_score) {
    best_candidate_ = 0;  // (0: no candidate beat the region as it was)
    best_kind_ = -1;
    std::vector<Outcome> level1;
    expand(region.sub, region.forced, level1, /*remesh=*/stuck_ >= 2);
    // Where one-vertex moves are stuck, the best few outcomes also get a joint relaxation.
    std::sort(level1.begin(), level1.end(), [](const Outcome& a, const Outcome& b) { return a.score < b.score; });
    for (std::size_t i = 0; i < std::min<std::size_t>(3, level1.size()); ++i) {
      Outcome& o = level1[i];
      if ((o.score.bad == 0 && o.score.infeasible == 0) || out_of_time()) break;
      auto relaxed = std::make_shared<Mesh>(*o.mesh);
      relax_sub(*relaxed, region.forced);
      const Score r = score(*relaxed, region.forced);
      if (r < o.score) o.mesh = std::move(relaxed), o.score = r;
    }
    for (auto& o : level1)
      if (o.score < best_score) best_score = o.score, best = o.mesh, best_candidate_ = o.candidate, best_kind_ = o.kind;
    const Score base = score(region.sub, region.forced);
    // A kick (see kKickEvery): the best first-level outcome that changes the region, worse or not.
    if (kick_ && best_candidate_ == 0)
      for (auto& o : level1)
        if (base < o.score) {
          best = o.mesh, best_score = o.score, best_candidate_ = o.candidate, best_kind_ = o.kind, kicked_ = true;
          break;
        }
    if (!deep || best_score < base) return;
    std::sort(level1.begin(), level1.end(), [](const Outcome& a, const Outcome& b) { return a.score < b.score; });
    // Outcomes that score as the region did are left out: mostly no-ops (smoothing alone, a flip the
    // smoothing undid), whose expansion repeats the first level. They crowded out the first step
    // that mattered (a 90-degree input corner of one right triangle: the bisector point, then a
    // vertex for its degree-4 star, ranked eighth behind six of them).
    level1.erase(std::remove_if(level1.begin(), level1.end(), [&](const Outcome& o) { return !(o.score < base) && !(base < o.score); }), level1.end());
    // Six first steps: the best five, and the best structural edit at a sharp corner if none is
    // among them (its first step scores worse than the point insertions: an apex point with four
    // neighbours is itself infeasible until a second step gives it a fifth).
    if (level1.size() > 6) {
      auto structural = [](const Outcome& o) { return o.kind == kApexMiddle || o.kind == kWedge || o.kind == kHub || o.kind == kRefan; };
      const auto first_structural = std::find_if(level1.begin(), level1.end(), structural);
      if (first_structural != level1.end() && first_structural - level1.begin() >= 6) std::iter_swap(level1.begin() + 5, first_structural);
      level1.resize(6);
    }
    for (const auto& first : level1) {
      if (out_of_time()) break;
      std::vector<Outcome> level2;
      expand(*first.mesh, region.forced, level2, /*remesh=*/false);
      for (auto& o : level2)
        if (o.score < best_score) best_score = o.score, best = std::move(o.mesh), best_candidate_ = 100 * first.candidate + o.candidate, best_kind_ = first.kind;
    }
  }

  /// A candidate's result. The mesh is held by pointer: OpenMesh meshes have no move, so sorting
  /// or growing a vector of them copied every region mesh several times.
  struct Outcome {
    Score score;
    std::shared_ptr<const Mesh> mesh;
    int candidate = 0;
    int kind = 0;
  };

  /// The kinds of candidate operation (expand), for the statistics that order them.
  enum CandidateKind : int {
    kSmooth, kSplitMidpoint, kSplitFoot, kCircumcentre, kCentroid, kBisector, kLinkSplit, kWallSplit, kLinkFlip,
    kCompoundSplit, kNearBridges, kAllBridges, kCollapse, kRemoveCorner, kRemoveLowDegree, kRemoveLowDegreeRest,
    kWedge, kHub, kEqualiseApexes, kApexMiddle, kRemesh, kRefan, kCandidateKinds
  };

  /// Applies each candidate operation to a copy of sub0 (then relocation) and collects the results.
  void expand(const Mesh& sub0, const std::vector<bool>& forced, std::vector<Outcome>& out, bool remesh) {
    candidate_ = 0;
    bool joint_first = false;  // candidates whose connectivity Delaunay restoration would undo
    bool solved = false;       // a candidate left nothing bad: the rest could only raise the worst margin
    auto run = [&](int kind, bool joint, const std::function<bool(Mesh&)>& operation) {
      ++candidate_;
      if (solved) return;
      if (!out.empty() && out_of_time()) return;  // one cluster's search must not outlast the time limit
      auto owned = std::make_shared<Mesh>(sub0);
      Mesh& sub = *owned;
      if (!operation(sub)) return;  // (no garbage collection: sub vertex indices map to the big mesh)
      if (paranoid_) {
        auto boundary_edges = [](const Mesh& m) { std::size_t n = 0; for (auto eh : m.edges()) n += m.is_boundary(eh) && !is_constrained(m, eh); return n; };
        if (boundary_edges(sub) != boundary_edges(sub0))
          throw InternalError("repair: candidate " + std::to_string(candidate_) + " changed the region boundary: " +
                              std::to_string(boundary_edges(sub0)) + " -> " + std::to_string(boundary_edges(sub)) + " edges");
      }
      if (joint) relax_sub(sub, forced);
      smooth_sub(sub, forced, 3);
      const Score s = score(sub, forced);
      if (trace_) std::fprintf(stderr, "    candidate %d (kind %d): infeasible %zu bad %zu worst %.4f\n", candidate_, kind, s.infeasible, s.bad, s.worst);
      solved = s.bad == 0 && s.infeasible == 0;
      out.push_back(Outcome{s, std::move(owned), candidate_, kind});
    };
    // The topological candidates are queued, then tried in the order of how often each kind has
    // solved a cluster so far (stable: ties keep the order below): the search stops at the first
    // that solves its cluster, and on a domain a few kinds solve most clusters (debug2's 9-degree
    // wedge in fixed order: the bisector point, sixth in line, solved 747 of 2,581, and a solved
    // cluster took 8 candidates on average).
    struct Pending {
      int kind;
      bool joint_first;
      std::function<bool(Mesh&)> operation;
    };
    std::vector<Pending> pending;
    auto attempt = [&](int kind, std::function<bool(Mesh&)> operation) { pending.push_back(Pending{kind, joint_first, std::move(operation)}); };
    run(kSmooth, false, [](Mesh&) { return true; });  // smoothing alone: enough for most clusters
    if (solved) return;

    // The worst face of the region drives the topological candidates.
    FaceHandle worst;
    double worst_margin = INFINITY;
    for (auto fh : sub0.faces()) {
      const double m = triangle_margin(sub0, fh, bounds_, face_is_exempt(sub0, fh, forced));
      if (m < worst_margin) worst_margin = m, worst = fh;
    }
    if (!worst.is_valid() || worst_margin >= bounds_.margin_deg) return;
    const auto v = face_vertices(sub0, worst);
    const auto p = face_points(sub0, worst);
    const auto a = angles_deg(p[0], p[1], p[2]);
    const int kmax = static_cast<int>(std::max_element(a.begin(), a.end()) - a.begin());
    const int kmin = static_cast<int>(std::min_element(a.begin(), a.end()) - a.begin());
    const FaceHandle worst_face = worst;

    // Insertions: on the edge opposite the largest angle (midpoint, altitude foot), circumcentre, centroid.
    const Point2 ea = p[(kmax + 1) % 3], eb = p[(kmax + 2) % 3], ec = p[kmax];
    const double t_foot = std::clamp((ec - ea).dot(eb - ea) / (eb - ea).squaredNorm(), 0.25, 0.75);
    const VertexHandle va = v[(kmax + 1) % 3], vb = v[(kmax + 2) % 3];
    for (double t : {0.5, t_foot})
      attempt(t == 0.5 ? kSplitMidpoint : kSplitFoot, [&, t](Mesh& sub) {
        const EdgeHandle eh = sub.edge_handle(sub.find_halfedge(va, vb));
        if (sub.is_boundary(eh) && !is_constrained(sub, eh)) return false;  // frozen ring edge
        return split_edge(sub, eh, ea + t * (eb - ea)).is_valid();
      });
    // The point on the bisector of the large angle at the distance of its two edges: gives the corner
    // a second triangle (e.g. a 90-degree input corner covered by one right triangle).
    const Point2 bisector = ((ea - ec).normalized() + (eb - ec).normalized()).normalized();
    const Point2 on_bisector = ec + 0.5 * ((ea - ec).norm() + (eb - ec).norm()) * bisector;
    int point_kind = kCircumcentre;  // then kCentroid, kBisector
    for (const Point2& q : {circumcenter(p[0], p[1], p[2]), Point2((p[0] + p[1] + p[2]) / 3.0), on_bisector})
      attempt(point_kind++, [&, q](Mesh& sub) {
        const VertexHandle vh = insert_point(sub, q, worst_face);
        return vh.is_valid() && !is_input(sub, vh);
      });

    // Raise the degree of the vertex with the large angle: split each edge of its link (a boundary
    // vertex with two triangles, or an interior one with four, always has an angle of 90 or more).
    const VertexHandle vmax = v[kmax];
    std::vector<std::array<VertexHandle, 2>> link;
    for (auto heh : sub0.voh_range(vmax))
      if (!sub0.is_boundary(heh)) {
        const auto l = sub0.next_halfedge_handle(heh);
        link.push_back({sub0.from_vertex_handle(l), sub0.to_vertex_handle(l)});
      }
    for (const auto& ends : link)
      attempt(kLinkSplit, [&, ends](Mesh& sub) {
        const auto heh = sub.find_halfedge(ends[0], ends[1]);
        if (!heh.is_valid()) return false;
        const EdgeHandle eh = sub.edge_handle(heh);
        if (sub.is_boundary(eh) && !is_constrained(sub, eh)) return false;
        return split_edge(sub, eh, 0.5 * (point2(sub, ends[0]) + point2(sub, ends[1]))).is_valid();
      });

    // Split the constrained edges around the link of the vertex with the large angle: in a strip one
    // triangle wide, a vertex on one side with too few triangles needs a new neighbour on the other
    // side, which only a point on that side's segment gives.
    std::vector<std::array<VertexHandle, 2>> walls;
    for (auto w : sub0.vv_range(vmax))
      for (auto heh : sub0.voh_range(w)) {
        const EdgeHandle eh = sub0.edge_handle(heh);
        if (!is_constrained(sub0, eh) || sub0.data(eh).frozen) continue;
        const VertexHandle z = sub0.to_vertex_handle(heh);
        if (z == vmax || w == vmax) continue;
        const VertexHandle wv = w;
        std::array<VertexHandle, 2> ends{std::min(wv, z), std::max(wv, z)};
        if (std::find(walls.begin(), walls.end(), ends) == walls.end()) walls.push_back(ends);
      }
    if (walls.size() > 8) walls.resize(8);
    for (const auto& ends : walls)
      attempt(kWallSplit, [&, ends](Mesh& sub) {
        const auto heh = sub.find_halfedge(ends[0], ends[1]);
        if (!heh.is_valid()) return false;
        return split_edge(sub, sub.edge_handle(heh), 0.5 * (point2(sub, ends[0]) + point2(sub, ends[1]))).is_valid();
      });

    // Flip each link edge of the vertex with the large angle: it gains a triangle (its neighbour
    // across loses one). The joint relaxation runs before any Delaunay restoration, which would
    // flip the edge back before the vertices had moved.
    joint_first = true;
    for (const auto& ends : link)
      attempt(kLinkFlip, [&, ends](Mesh& sub) {
        const auto heh = sub.find_halfedge(ends[0], ends[1]);
        if (!heh.is_valid()) return false;
        const EdgeHandle eh = sub.edge_handle(heh);
        if (sub.data(eh).frozen || can_flip(sub, eh) != OpVerdict::Ok) return false;
        flip(sub, eh);
        return true;
      });
    joint_first = false;

    // Re-fan a sector of a worst-face vertex that holds too few triangles for the max bound (two
    // right triangles on a segment vertex's straight side): more spokes, relaxed together. Only
    // once the repair is stuck (like the re-sampling): tried first, it took paths that stalled
    // elsewhere (a strip hub's patch, 1 bad triangle for 150 iterations).
    joint_first = true;
    if (remesh)
      for (auto vh : v)
        for (const detail::CrowdedSector& sector : detail::crowded_sectors(sub0, vh, bounds_.max_deg - bounds_.margin_deg))
          attempt(kRefan, [&, vh, sector](Mesh& sub) { return detail::refan_sector(sub, vh, sector); });
    joint_first = false;

    // Compound: split every splittable edge of the worst face at its midpoint (local refinement for
    // clusters that no single insertion improves, e.g. right triangles between input points).
    attempt(kCompoundSplit, [&](Mesh& sub) {
      int splits = 0;
      for (int k = 0; k < 3; ++k) {
        const auto heh = sub.find_halfedge(v[k], v[(k + 1) % 3]);
        if (!heh.is_valid()) continue;
        const EdgeHandle eh = sub.edge_handle(heh);
        if (sub.is_boundary(eh) && !is_constrained(sub, eh)) continue;
        splits += split_edge(sub, eh, 0.5 * (p[k] + p[(k + 1) % 3])).is_valid();
      }
      return splits > 0;
    });

    // Bridges: interior edges between two walls (the rungs of a strip one triangle wide). Splitting
    // them gives the strip a middle row: at the apex of a sharp wedge, a one-row strip always leaves
    // a base vertex of the apex triangle with two triangles on a straight segment (90 + 90).
    auto on_wall = [](const Mesh& m, VertexHandle vh) {
      for (auto heh : m.voh_range(vh))
        if (is_constrained(m, m.edge_handle(heh))) return true;
      return false;
    };
    std::vector<std::array<VertexHandle, 2>> bridges, near_bridges;
    for (auto eh : sub0.edges()) {
      if (sub0.status(eh).deleted() || sub0.is_boundary(eh) || is_constrained(sub0, eh) || sub0.data(eh).frozen) continue;
      const auto heh = sub0.halfedge_handle(eh, 0);
      const VertexHandle from = sub0.from_vertex_handle(heh), to = sub0.to_vertex_handle(heh);
      if (!on_wall(sub0, from) || !on_wall(sub0, to)) continue;
      bridges.push_back({from, to});
      bool near = false;
      for (auto w : v)
        for (auto x : sub0.vv_range(w)) near = near || x == from || x == to || w == from || w == to;
      if (near) near_bridges.push_back({from, to});
    }
    auto split_all = [&](Mesh& sub, const std::vector<std::array<VertexHandle, 2>>& edges) {
      int splits = 0;
      for (const auto& ends : edges) {
        const auto heh = sub.find_halfedge(ends[0], ends[1]);
        if (!heh.is_valid()) continue;
        splits += split_edge(sub, sub.edge_handle(heh), 0.5 * (point2(sub, ends[0]) + point2(sub, ends[1]))).is_valid();
      }
      return splits > 0;
    };
    if (!near_bridges.empty()) attempt(kNearBridges, [&](Mesh& sub) { return split_all(sub, near_bridges); });
    if (bridges.size() > near_bridges.size()) attempt(kAllBridges, [&](Mesh& sub) { return split_all(sub, bridges); });

    // Removals: collapse the edge opposite the smallest angle, or remove a corner of the worst face.
    const VertexHandle vb2 = v[(kmin + 1) % 3], vc2 = v[(kmin + 2) % 3];
    for (auto [from, to] : {std::pair{vb2, vc2}, std::pair{vc2, vb2}})
      attempt(kCollapse, [&, from = from, to = to](Mesh& sub) {
        const auto heh = sub.find_halfedge(from, to);
        if (!heh.is_valid() || can_collapse(sub, heh) != OpVerdict::Ok) return false;
        collapse(sub, heh);
        return true;
      });
    for (auto vh : v)
      attempt(kRemoveCorner, [&, vh](Mesh& sub) { return !is_input(sub, vh) && remove_vertex(sub, vh); });
    // Interior vertices of degree <= 4 always make an angle of at least 90 degrees. The ones
    // nearest the worst face are candidates of their own; any further ones go together (one
    // candidate per vertex made a poor region's search cost most of the repair's time).
    constexpr std::size_t kLowDegreeSingles = 8;
    std::vector<std::pair<double, VertexHandle>> low_degree;
    const Point2 worst_centre = (p[0] + p[1] + p[2]) / 3.0;
    for (auto vh : sub0.vertices())
      if (!is_input(sub0, vh) && !sub0.is_boundary(vh) && sub0.valence(vh) <= 4)
        low_degree.emplace_back((point2(sub0, vh) - worst_centre).squaredNorm(), vh);
    std::sort(low_degree.begin(), low_degree.end());
    for (std::size_t k = 0; k < std::min(low_degree.size(), kLowDegreeSingles); ++k)
      attempt(kRemoveLowDegree, [&, vh = low_degree[k].second](Mesh& sub) { return remove_vertex(sub, vh); });
    if (low_degree.size() > kLowDegreeSingles)
      attempt(kRemoveLowDegreeRest, [&](Mesh& sub) {
        bool removed = false;
        for (std::size_t k = kLowDegreeSingles; k < low_degree.size(); ++k) {
          const VertexHandle vh = low_degree[k].second;
          if (!sub.status(vh).deleted() && sub.valence(vh) <= 4) removed = remove_vertex(sub, vh) || removed;
        }
        return removed;
      });

    // A sharp corner of the worst face rebuilt as a graded two-row strip (see rebuild_wedge).
    joint_first = true;
    std::vector<VertexHandle> apexes;  // of the worst face, or next to it (the apex triangle's neighbour)
    for (auto vh : v) {
      apexes.push_back(vh);
      for (auto w : sub0.vv_range(vh)) apexes.push_back(w);
    }
    std::sort(apexes.begin(), apexes.end());
    apexes.erase(std::unique(apexes.begin(), apexes.end()), apexes.end());
    for (auto vh : apexes)
      if (detail::has_narrow_sector(sub0, vh))
      {
        for (int rings : {3, 5}) attempt(kWedge, [&, vh, rings](Mesh& sub) { return detail::rebuild_wedge(sub, vh, rings); });
        for (int rings : {3, 5}) attempt(kHub, [&, vh, rings](Mesh& sub) { return detail::rebuild_hub(sub, vh, rings); });
      }
    constexpr double kPi = 3.14159265358979323846;
    // Strips (sectors below the min bound, at forced corners) get isosceles apex triangles; so do
    // sectors below twice the min bound, which hold one triangle whose base angles stay below the
    // max bound only while its walls' first radii nearly agree (a 32.7-degree sector of a CG:SHOP
    // instance: radii 2.40 and 2.85 gave a right angle no single move could undo). The strips-only
    // candidate is queued only where it differs from the other (a corner with both kinds).
    const double strip_below = bounds_.min_deg * kPi / 180, one_triangle_below = 2 * strip_below;
    for (auto vh : apexes) {
      if (!is_input(sub0, vh)) continue;
      bool strip = false, one_triangle = false;
      for (const SegmentSector& sector : segment_sectors(sub0, vh)) {
        strip = strip || sector.radians < strip_below;
        one_triangle = one_triangle || (sector.radians >= strip_below && sector.radians < one_triangle_below);
      }
      const bool forced_strip = strip && static_cast<std::size_t>(vh.idx()) < forced.size() && forced[static_cast<std::size_t>(vh.idx())];
      if (forced_strip && one_triangle)
        attempt(kEqualiseApexes, [&, vh](Mesh& sub) { return detail::equalise_strip_apexes(sub, vh, strip_below); });
      if (strip || one_triangle)
        attempt(kEqualiseApexes, [&, vh](Mesh& sub) { return detail::equalise_strip_apexes(sub, vh, one_triangle_below); });
      // Or the nearer wall vertex moved out: moved in, the farther one may keep too few triangles
      // beside the apex triangle (two on its straight side: a right angle smoothing cannot open).
      if (one_triangle)
        attempt(kEqualiseApexes, [&, vh](Mesh& sub) { return detail::equalise_strip_apexes(sub, vh, one_triangle_below, /*outward=*/true); });
      // Or either, and a point beyond the apex triangle that gives its base vertices a third triangle.
      if (one_triangle)
        for (bool outward : {false, true})
          attempt(kApexMiddle, [&, vh, outward](Mesh& sub) { return detail::apex_with_middle_point(sub, vh, strip_below, one_triangle_below, outward); });
    }
    joint_first = false;

    // A cluster that has resisted every single operation: the region re-sampled from scratch at
    // the local spacing and finer, down to half of it (fresh random darts each time). Half: the
    // end of a strip one triangle wide between two right-angled input corners needs a second row
    // there (a CG:SHOP ortho instance at a coarsened size kept one right triangle at 0.65).
    if (remesh) {
      const double h = detail::movable_edge_median(sub0);
      joint_first = true;
      for (double scale : {1.0, 0.8, 0.65, 0.5})
        attempt(kRemesh, [&, scale, h](Mesh& sub) { return detail::remesh_region(sub, scale * h, ++remesh_seed_); });
      joint_first = false;
    }
    // (The queued operations run here: what they capture by reference must live at function scope.)
    std::stable_sort(pending.begin(), pending.end(), [&](const Pending& x, const Pending& y) { return wins_[x.kind] > wins_[y.kind]; });
    for (const Pending& c : pending) run(c.kind, c.joint_first, c.operation);
  }

  Mesh& mesh_;
  std::size_t deleted_vertices_ = 0, deleted_faces_ = 0;  ///< left in mesh_ by the last iteration
  std::vector<double> face_margin_;                       ///< the global phase's, by face index
  RepairParams params_;
  AngleBounds bounds_;
  std::vector<bool> forced_;
  std::vector<EdgeHandle> queue_;
  std::vector<char> seen_;  // grow()'s marks, all 0 between calls
  std::vector<VertexHandle> sub_touched_;  // smooth_sub's work lists, kept between calls
  std::vector<char> sub_settled_;
  int candidate_ = 0;
  int best_candidate_ = 0;
  int best_kind_ = -1;
  std::array<int, kCandidateKinds> wins_{};  ///< clusters each kind of candidate solved, this run
  double paranoid_area_ = 0;
  std::chrono::steady_clock::time_point t0_;
  int stuck_ = 0;
  bool kick_ = false;    ///< this iteration, a cluster no candidate improves takes its best worse one
  bool kicked_ = false;  ///< the current cluster's search returned such a one
  std::uint32_t remesh_seed_ = 0;
  bool trace_ = std::getenv("ACUTE_TRACE") != nullptr;
  bool paranoid_ = std::getenv("ACUTE_PARANOID") != nullptr;
  RepairResult result_;
};

}  // namespace

RepairResult repair_acute(Mesh& mesh, const RepairParams& params) { return Repairer(mesh, params).run(); }

}  // namespace acute
