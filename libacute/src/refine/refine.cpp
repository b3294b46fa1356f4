#include <acute/refine/refine.h>

#include <acute/mesh/geometry.h>
#include <acute/mesh/segments.h>
#include <acute/ops/delaunay_flips.h>
#include <acute/ops/insert.h>
#include <acute/ops/remove.h>
#include <acute/predicates/predicates.h>

#include <cmath>
#include <deque>
#include <vector>

namespace acute {
namespace {

constexpr double kPi = 3.14159265358979323846;

class Refiner {
 public:
  Refiner(Mesh& mesh, const RefineParams& params)
      : mesh_(mesh), params_(params), cos_min_(std::cos(params.min_angle_deg * kPi / 180.0)),
        max_radius2_(params.max_edge > 0 ? params.max_edge * params.max_edge / 3.0 : 0.0),
        off_constant_(0.475 / std::tan(0.5 * params.min_angle_deg * kPi / 180.0)) {}

  RefineResult run() {
    // Faces re-created by a rollback are not queued: sweep the whole mesh until a sweep finds
    // nothing to do (or nothing changed).
    for (std::size_t sweep = 0;; ++sweep) {
      const std::size_t before = result_.inserted + result_.segment_splits;
      for (auto fh : mesh_.faces())
        if (is_bad(fh)) faces_.push_back(fh);
      for (auto eh : mesh_.edges())
        if (is_constrained(mesh_, eh) && is_encroached(eh)) segments_.push_back(eh);
      if (faces_.empty() && segments_.empty()) break;
      process_queues();
      if (result_.status == RefineStatus::BudgetExhausted || result_.inserted + result_.segment_splits == before) break;
    }
    mesh_.garbage_collection();
    return result_;
  }

 private:
  void process_queues() {
    while (true) {
      if (mesh_.n_vertices() >= params_.max_vertices) {
        result_.status = RefineStatus::BudgetExhausted;
        break;
      }
      if (!segments_.empty()) {
        const EdgeHandle eh = segments_.back();
        segments_.pop_back();
        if (!mesh_.status(eh).deleted() && is_constrained(mesh_, eh) && is_encroached(eh)) split_segment(eh);
        continue;
      }
      if (faces_.empty()) break;
      const FaceHandle fh = faces_.front();
      faces_.pop_front();
      if (!mesh_.status(fh).deleted() && is_bad(fh)) split_triangle(fh);
    }
  }

  bool is_encroached(EdgeHandle eh) const {
    for (int side = 0; side < 2; ++side) {
      const auto heh = mesh_.halfedge_handle(eh, side);
      if (mesh_.is_boundary(heh)) continue;
      const Point2 a = point2(mesh_, mesh_.from_vertex_handle(heh)), b = point2(mesh_, mesh_.to_vertex_handle(heh));
      const Point2 apex = point2(mesh_, mesh_.to_vertex_handle(mesh_.next_halfedge_handle(heh)));
      if (predicates::in_diametral_circle(a, b, apex) == Sign::Positive) return true;
    }
    return false;
  }

  /// Input vertex where two segments meet at less than 60 degrees? Such corners get concentric shells.
  bool is_sharp_corner(VertexHandle vh) const {
    if (!is_input(mesh_, vh)) return false;
    std::vector<Point2> dirs;
    const Point2 p = point2(mesh_, vh);
    for (auto heh : mesh_.voh_range(vh))
      if (is_constrained(mesh_, mesh_.edge_handle(heh))) dirs.push_back((point2(mesh_, mesh_.to_vertex_handle(heh)) - p).normalized());
    for (std::size_t i = 0; i < dirs.size(); ++i)
      for (std::size_t j = i + 1; j < dirs.size(); ++j)
        if (dirs[i].dot(dirs[j]) > 0.5) return true;
    return false;
  }

  bool split_segment(EdgeHandle eh) {
    const auto heh = mesh_.halfedge_handle(eh, 0);
    const VertexHandle va = mesh_.from_vertex_handle(heh), vb = mesh_.to_vertex_handle(heh);
    const Point2 a = point2(mesh_, va), b = point2(mesh_, vb);
    double t = 0.5;
    const bool sharp_a = is_sharp_corner(va), sharp_b = is_sharp_corner(vb);
    if (sharp_a != sharp_b) {
      // Concentric shells: split at a power-of-two distance from the sharp corner.
      const double len = (b - a).norm();
      const double shell = std::exp2(std::round(std::log2(0.5 * len)));
      double s = std::clamp(shell / len, 1.0 / 3.0, 2.0 / 3.0);
      t = sharp_a ? s : 1.0 - s;
    }
    const VertexHandle vh = split_edge(mesh_, eh, a + t * (b - a));
    if (!vh.is_valid()) return false;
    ++result_.segment_splits;
    after_insertion(vh);
    return true;
  }

  bool is_bad(FaceHandle fh) const {
    const auto p = face_points(mesh_, fh);
    if (max_radius2_ > 0 && (circumcenter(p[0], p[1], p[2]) - p[0]).squaredNorm() > max_radius2_) return true;
    const auto c = angle_cosines(p[0], p[1], p[2]);
    const int k = smallest_angle(c);
    if (c[k] <= cos_min_) return false;
    return !is_protected(fh, k);
  }

  static int smallest_angle(const std::array<double, 3>& c) { return c[0] >= c[1] && c[0] >= c[2] ? 0 : (c[1] >= c[2] ? 1 : 2); }

  /// A skinny triangle at a small input angle cannot be fixed: its apex is a sharp corner, or its
  /// shortest edge joins two different segments that meet at a sharp corner (concentric shells).
  bool is_protected(FaceHandle fh, int k) const {
    const auto v = face_vertices(mesh_, fh);
    if (is_input(mesh_, v[k]) && corner_sector_deg(fh, v[k]) < params_.min_angle_deg) return true;
    const VertexHandle p = v[(k + 1) % 3], q = v[(k + 2) % 3];
    const auto& dp = mesh_.data(p);
    const auto& dq = mesh_.data(q);
    if (dp.kind != VertexKind::OnSegment || dq.kind != VertexKind::OnSegment || dp.segment == dq.segment) return false;
    const auto& table = segment_table(mesh_);
    if (table.empty()) return false;
    const auto& s1 = table[static_cast<std::size_t>(dp.segment)];
    const auto& s2 = table[static_cast<std::size_t>(dq.segment)];
    for (const auto& e1 : s1)
      for (const auto& e2 : s2)
        if (e1 == e2) {
          const Point2 d1 = (s1[0] == e1 ? s1[1] : s1[0]) - e1, d2 = (s2[0] == e2 ? s2[1] : s2[0]) - e2;
          if (d1.normalized().dot(d2.normalized()) > cos_min_) return true;
        }
    return false;
  }

  /// Angle of the sector around vh that contains face fh and is bounded by segments (360 if none).
  double corner_sector_deg(FaceHandle fh, VertexHandle vh) const {
    HalfedgeHandle start;  // the outgoing halfedge of vh in fh
    for (auto heh : mesh_.fh_range(fh))
      if (mesh_.from_vertex_handle(heh) == vh) start = heh;
    auto angle_at = [&](HalfedgeHandle out) {
      const Point2 p = point2(mesh_, vh), a = point2(mesh_, mesh_.to_vertex_handle(out));
      const Point2 b = point2(mesh_, mesh_.from_vertex_handle(mesh_.prev_halfedge_handle(out)));
      return std::atan2(std::abs(signed_area2(p, a, b)), (a - p).dot(b - p)) * 180.0 / kPi;
    };
    double total = angle_at(start);
    // Counter-clockwise from start, then clockwise, stopping at constrained or boundary edges.
    for (HalfedgeHandle h = start;;) {
      const HalfedgeHandle in = mesh_.prev_halfedge_handle(h);
      if (is_constrained(mesh_, mesh_.edge_handle(in)) || mesh_.is_boundary(mesh_.edge_handle(in))) break;
      h = mesh_.opposite_halfedge_handle(in);
      if (h == start) return 360.0;
      total += angle_at(h);
    }
    for (HalfedgeHandle h = start;;) {
      if (is_constrained(mesh_, mesh_.edge_handle(h)) || mesh_.is_boundary(mesh_.edge_handle(h))) break;
      h = mesh_.next_halfedge_handle(mesh_.opposite_halfedge_handle(h));
      total += angle_at(h);
    }
    return total;
  }

  Point2 steiner_point(FaceHandle fh) const {
    const auto p = face_points(mesh_, fh);
    const Point2 cc = circumcenter(p[0], p[1], p[2]);
    if (!params_.off_centers) return cc;
    // Shortest edge (a, b): the off-centre lies on its bisector, towards the circumcentre.
    int k = 0;
    double best = INFINITY;
    for (int i = 0; i < 3; ++i) {
      const double len = (p[(i + 1) % 3] - p[i]).squaredNorm();
      if (len < best) best = len, k = i;
    }
    const Point2 a = p[k], b = p[(k + 1) % 3];
    const Point2 mid = 0.5 * (a + b);
    const double dc = (cc - mid).norm(), doff = off_constant_ * std::sqrt(best);
    return doff < dc ? Point2(mid + (cc - mid) * (doff / dc)) : cc;
  }

  void split_triangle(FaceHandle fh) {
    const Point2 c = steiner_point(fh);
    EdgeHandle blocked;
    const Location loc = locate(mesh_, c, fh);
    if (loc.kind == LocationKind::Blocked) {
      if (split_segment(loc.edge)) faces_.push_back(fh);
      return;
    }
    if (loc.kind == LocationKind::OnVertex) return;
    const VertexHandle vh = insert_point(mesh_, c, loc.face, &blocked);
    if (!vh.is_valid()) return;
    // A new point that encroaches a subsegment is taken back; the subsegment is split instead.
    // (Edges are remembered by their ends: the removal may re-create them.)
    std::vector<std::array<VertexHandle, 2>> encroached;
    for (auto heh : mesh_.voh_range(vh)) {
      if (mesh_.is_boundary(heh)) continue;
      const auto link = mesh_.next_halfedge_handle(heh);
      if (is_constrained(mesh_, mesh_.edge_handle(link)) && is_encroached(mesh_.edge_handle(link)))
        encroached.push_back({mesh_.from_vertex_handle(link), mesh_.to_vertex_handle(link)});
    }
    if (!encroached.empty() && remove_vertex(mesh_, vh)) {
      bool split_any = false;
      for (const auto& ends : encroached) {
        const auto heh = mesh_.find_halfedge(ends[0], ends[1]);
        if (heh.is_valid() && is_constrained(mesh_, mesh_.edge_handle(heh))) split_any |= split_segment(mesh_.edge_handle(heh));
      }
      if (split_any) faces_.push_back(fh);
      return;
    }
    ++result_.inserted;
    after_insertion(vh);
  }

  void after_insertion(VertexHandle vh) {
    for (auto fh : mesh_.vf_range(vh)) faces_.push_back(fh);
    for (auto heh : mesh_.voh_range(vh)) {
      const EdgeHandle eh = mesh_.edge_handle(heh);
      if (is_constrained(mesh_, eh)) segments_.push_back(eh);
      if (!mesh_.is_boundary(heh)) {
        const EdgeHandle link = mesh_.edge_handle(mesh_.next_halfedge_handle(heh));
        if (is_constrained(mesh_, link)) segments_.push_back(link);
      }
    }
  }

  Mesh& mesh_;
  RefineParams params_;
  double cos_min_, max_radius2_, off_constant_;
  std::vector<EdgeHandle> segments_;
  std::deque<FaceHandle> faces_;
  RefineResult result_;
};

}  // namespace

RefineResult refine(Mesh& mesh, const RefineParams& params) { return Refiner(mesh, params).run(); }

}  // namespace acute
