#include <acute/repair/repair.h>

#include <acute/mesh/geometry.h>
#include <acute/mesh/segments.h>
#include <acute/ops/delaunay_flips.h>
#include <acute/ops/insert.h>
#include <acute/ops/remove.h>
#include <acute/repair/clusters.h>
#include <acute/repair/relocation.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace acute {

std::vector<FaceHandle> bad_triangles(const Mesh& mesh, const AngleBounds& bounds) {
  const auto forced = forced_corner_vertices(mesh, bounds.min_deg);
  std::vector<FaceHandle> bad;
  for (auto fh : mesh.faces())
    if (is_bad_triangle(mesh, fh, bounds, forced)) bad.push_back(fh);
  return bad;
}

namespace {

class Repairer {
 public:
  Repairer(Mesh& mesh, const RepairParams& params) : mesh_(mesh), params_(params), bounds_(params.bounds) {}

  RepairResult run() {
    const auto t0 = std::chrono::steady_clock::now();
    refresh_forced();
    std::size_t best_bad = SIZE_MAX;
    Mesh best;
    int stagnation = 0;
    for (int it = 0;; ++it) {
      const auto clusters = find_clusters(mesh_, bounds_, forced_);
      std::size_t bad = 0;
      for (const auto& c : clusters) bad += c.bad.size();
      if (it == 0) result_.bad_before = bad;
      result_.iterations = it;
      const bool global = it < params_.global_iterations;
      if (params_.observer) params_.observer(RepairProgress{it, bad, global});
      if (bad < best_bad) {
        best_bad = bad;
        stagnation = 0;
        if (bad > 0) best = mesh_;
      } else {
        ++stagnation;
      }
      if (bad == 0) {
        result_.status = RepairStatus::Converged;
        break;
      }
      if (it >= params_.max_iterations || stagnation > 40) {
        result_.status = RepairStatus::IterationLimit;
        break;
      }
      if (params_.time_limit_s > 0 &&
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > params_.time_limit_s) {
        result_.status = RepairStatus::TimeLimit;
        break;
      }
      if (params_.cancel && params_.cancel()) {
        result_.status = RepairStatus::Cancelled;
        break;
      }
      if (mesh_.n_vertices() >= params_.max_vertices) {
        result_.status = RepairStatus::VertexBudget;
        break;
      }
      iterate(clusters, global, it);
      mesh_.garbage_collection();
      refresh_forced();
    }
    if (result_.status != RepairStatus::Converged && best_bad < SIZE_MAX && best.n_faces() > 0) mesh_ = std::move(best);
    mesh_.garbage_collection();
    result_.bad_after = bad_triangles(mesh_, bounds_).size();
    return result_;
  }

 private:
  void refresh_forced() { forced_ = forced_corner_vertices(mesh_, bounds_.min_deg); }

  bool forced(VertexHandle vh) const {
    const auto i = static_cast<std::size_t>(vh.idx());
    return i < forced_.size() && forced_[i];
  }

  void restore_around(VertexHandle vh) {
    queue_.clear();
    push_star_edges(mesh_, vh, queue_);
    restore_delaunay(mesh_, queue_);
  }

  /// Relocates every vertex in `vertices` (a few sweeps), restoring Delaunay after each move.
  void smooth(std::vector<VertexHandle> vertices, int sweeps) {
    for (int s = 0; s < sweeps; ++s) {
      bool moved_any = false;
      for (auto vh : vertices) {
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
    std::vector<VertexHandle> out = seeds;
    std::vector<char> seen(mesh_.n_vertices(), 0);
    for (auto vh : seeds) seen[static_cast<std::size_t>(vh.idx())] = 1;
    std::size_t begin = 0;
    for (int r = 0; r < rings; ++r) {
      const std::size_t end = out.size();
      for (std::size_t i = begin; i < end; ++i)
        for (auto w : mesh_.vv_range(out[i]))
          if (!seen[static_cast<std::size_t>(w.idx())]) {
            seen[static_cast<std::size_t>(w.idx())] = 1;
            out.push_back(w);
          }
      begin = end;
    }
    return out;
  }

  void iterate(const std::vector<Cluster>& clusters, bool global, int it) {
    // 1. Smoothing: globally over every vertex near trouble, then only around the clusters.
    std::vector<VertexHandle> region;
    for (const auto& c : clusters) region.insert(region.end(), c.vertices.begin(), c.vertices.end());
    const int rings = global ? 2 : 1 + (it / 10) % 3;
    smooth(grow(region, rings), 3);

    // 2. Topology: interior vertices of degree <= 4 always make an angle >= 90; remove them.
    for (auto vh : grow(region, 1)) {
      if (mesh_.status(vh).deleted() || mesh_.data(vh).kind != VertexKind::Free || mesh_.is_boundary(vh)) continue;
      if (mesh_.valence(vh) <= 4 && remove_vertex(mesh_, vh)) ++result_.removed;
    }

    // 3. Still-bad triangles of the clusters: insert for large angles, collapse for small ones.
    std::vector<VertexHandle> touched;
    for (const auto& c : clusters) {
      for (auto fh : c.bad) {
        if (mesh_.status(fh).deleted() || !is_bad_triangle(mesh_, fh, bounds_, forced_)) continue;
        const VertexHandle vh = fix_triangle(fh);
        if (vh.is_valid()) touched.push_back(vh);
        break;  // one operation per cluster and iteration, then smooth again
      }
    }
    std::vector<VertexHandle> alive;
    for (auto vh : touched)
      if (!mesh_.status(vh).deleted()) alive.push_back(vh);
    smooth(grow(alive, 1), 2);
  }

  /// One operation on a bad triangle. Returns a vertex whose neighbourhood changed.
  VertexHandle fix_triangle(FaceHandle fh) {
    const auto v = face_vertices(mesh_, fh);
    const auto p = face_points(mesh_, fh);
    const auto a = angles_deg(p[0], p[1], p[2]);
    const int kmax = static_cast<int>(std::max_element(a.begin(), a.end()) - a.begin());
    const int kmin = static_cast<int>(std::min_element(a.begin(), a.end()) - a.begin());
    const bool exempt = forced(v[0]) || forced(v[1]) || forced(v[2]);
    if (a[kmax] >= bounds_.max_deg - bounds_.margin_deg) return fix_large_angle(fh, v, p, kmax);
    if (!exempt && a[kmin] < bounds_.min_deg + bounds_.margin_deg) return fix_small_angle(fh, v, p, kmin);
    return VertexHandle();
  }

  /// The edge opposite corner k of face fh.
  EdgeHandle opposite_edge(FaceHandle fh, const std::array<VertexHandle, 3>& v, int k) {
    return mesh_.edge_handle(mesh_.find_halfedge(v[(k + 1) % 3], v[(k + 2) % 3]));
  }

  VertexHandle fix_large_angle(FaceHandle fh, const std::array<VertexHandle, 3>& v, const std::array<Point2, 3>& p, int k) {
    const EdgeHandle ab = opposite_edge(fh, v, k);
    const Point2 a = p[(k + 1) % 3], b = p[(k + 2) % 3], c = p[k];
    if (is_constrained(mesh_, ab) || mesh_.is_boundary(ab)) {
      // Drop the altitude from the obtuse corner onto the segment.
      const Point2 d = b - a;
      const double t = std::clamp((c - a).dot(d) / d.squaredNorm(), 0.3, 0.7);
      const VertexHandle vh = split_edge(mesh_, ab, a + t * d);
      if (vh.is_valid()) ++result_.inserted;
      return vh;
    }
    // Interior edge: the circumcentre lies beyond it; insert it if reachable, else the midpoint.
    const Point2 cc = circumcenter(p[0], p[1], p[2]);
    EdgeHandle blocked;
    VertexHandle vh = insert_point(mesh_, cc, fh, &blocked);
    if (!vh.is_valid() && blocked.is_valid()) {
      const auto h = mesh_.halfedge_handle(blocked, 0);
      const Point2 s0 = point2(mesh_, mesh_.from_vertex_handle(h)), s1 = point2(mesh_, mesh_.to_vertex_handle(h));
      vh = split_edge(mesh_, blocked, 0.5 * (s0 + s1));
    }
    if (!vh.is_valid() || vh == v[0] || vh == v[1] || vh == v[2]) vh = split_edge(mesh_, ab, 0.5 * (a + b));
    if (vh.is_valid()) ++result_.inserted;
    return vh;
  }

  VertexHandle fix_small_angle(FaceHandle fh, const std::array<VertexHandle, 3>& v, const std::array<Point2, 3>& p, int k) {
    // The short edge opposite the small angle: merge its ends when one of them may go.
    const VertexHandle b = v[(k + 1) % 3], c = v[(k + 2) % 3];
    for (auto [from, to] : {std::pair{b, c}, std::pair{c, b}}) {
      const auto heh = mesh_.find_halfedge(from, to);
      if (heh.is_valid() && can_collapse(mesh_, heh) == OpVerdict::Ok) {
        collapse(mesh_, heh);
        ++result_.removed;
        return to;
      }
    }
    // Otherwise remove a free vertex of the triangle, or refine with the circumcentre.
    for (auto vh : v)
      if (!is_input(mesh_, vh) && remove_vertex(mesh_, vh)) {
        ++result_.removed;
        return v[k] == vh ? b : v[k];
      }
    const Point2 cc = circumcenter(p[0], p[1], p[2]);
    const VertexHandle vh = insert_point(mesh_, cc, fh);
    if (vh.is_valid()) ++result_.inserted;
    return vh;
  }

  Mesh& mesh_;
  RepairParams params_;
  AngleBounds bounds_;
  std::vector<bool> forced_;
  std::vector<EdgeHandle> queue_;
  RepairResult result_;
};

}  // namespace

RepairResult repair_acute(Mesh& mesh, const RepairParams& params) { return Repairer(mesh, params).run(); }

}  // namespace acute
