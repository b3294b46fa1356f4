#include <acute/repair/relocation.h>

#include <acute/mesh/geometry.h>
#include <acute/mesh/segments.h>
#include <acute/ops/relocate.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace acute {

namespace {

/// The star of a vertex as the pattern search sees it. Only the vertex moves, so each face, its
/// other two corners, their positions and whether a corner is forced are read from the mesh once;
/// an evaluation then walks plain arrays. star_energy and star_margin are its energy and margin;
/// can_move_to gives can_relocate's verdict.
class CachedStar {
 public:
  void load(const Mesh& mesh, VertexHandle vh, const std::vector<bool>& forced) {
    auto is_forced = [&](VertexHandle v) {
      const auto i = static_cast<std::size_t>(v.idx());
      return i < forced.size() && forced[i];
    };
    vh_ = vh;
    n_ = 0;
    overflow_.clear();
    open_border_ = false;
    forced0_ = is_forced(vh);
    const auto& data = mesh.data(vh);
    const bool on_segment = data.kind == VertexKind::OnSegment;
    // keeps_segment_order's neighbours along the segment, and the segment's line.
    n_along_ = 0;
    has_line_ = false;
    if (on_segment) {
      for (auto heh : mesh.voh_range(vh))
        if (mesh.data(mesh.edge_handle(heh)).segment == data.segment && n_along_ < 2) along_[n_along_++] = point2(mesh, mesh.to_vertex_handle(heh));
      if (data.segment >= 0 && static_cast<std::size_t>(data.segment) < segment_table(mesh).size()) {
        has_line_ = true;
        line_ = segment_endpoints(mesh, data.segment);
      }
    }
    for (auto heh : mesh.voh_range(vh)) {
      if (mesh.is_boundary(heh)) {
        open_border_ = open_border_ || !on_segment;
        continue;
      }
      if (n_ >= kInline) overflow_.emplace_back();
      Face& f = n_ < kInline ? faces_[n_] : overflow_.back();
      ++n_;
      f.fh = mesh.face_handle(heh);
      f.v1 = mesh.to_vertex_handle(heh);
      f.v2 = mesh.to_vertex_handle(mesh.next_halfedge_handle(heh));
      f.p1 = point2(mesh, f.v1);
      f.p2 = point2(mesh, f.v2);
      f.forced1 = is_forced(f.v1);
      f.forced2 = is_forced(f.v2);
    }
  }

  /// The soft minimum of the star's angle margins with the vertex at p (where the mesh has it too:
  /// forced corners read their sector from it): every angle near or beyond a bound pushes, the
  /// worst most. (A plain max-min stalls when the worst angle cannot change, e.g. at a fixed input
  /// corner.)
  double energy(const Mesh& mesh, const Point2& p, const AngleBounds& bounds, const std::vector<bool>& forced) const {
    constexpr double kTau = 2.0;  // degrees
    double energy = 0;
    for (int i = 0; i < n_; ++i) {
      const Face& f = face(i);
      const double angles[3] = {approx_angle_deg(p, f.p1, f.p2), approx_angle_deg(f.p1, f.p2, p), approx_angle_deg(f.p2, p, f.p1)};
      const bool forced_corner[3] = {forced0_, f.forced1, f.forced2};
      const VertexHandle corner[3] = {vh_, f.v1, f.v2};
      for (int k = 0; k < 3; ++k) {
        double m = bounds.max_deg - angles[k];
        if (!(forced_corner[k] && min_exempt_corner(mesh, corner[k], f.fh, bounds.min_deg, forced))) m = std::min(m, angles[k] - bounds.min_deg);
        energy += std::exp(-m / kTau);
      }
    }
    return energy;
  }

  /// The smallest margin over the star's angles, at the mesh's position of the vertex.
  double margin(const Mesh& mesh, const AngleBounds& bounds) const {
    double margin = INFINITY;
    for (int i = 0; i < n_; ++i) {
      const Face& f = face(i);
      margin = std::min(margin, triangle_margin(mesh, f.fh, bounds, forced0_ || f.forced1 || f.forced2));
    }
    return margin;
  }

  /// can_relocate(mesh, vh, p) == OpVerdict::Ok.
  bool can_move_to(const Mesh& mesh, const Point2& p) const {
    const auto& data = mesh.data(vh_);
    if (data.kind == VertexKind::Input || open_border_) return false;
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return false;
    if (data.kind == VertexKind::OnSegment) {
      // keeps_segment_order: strictly between the neighbours where they differ, equal where they agree.
      if (n_along_ < 2) return false;
      for (int i = 0; i < 2; ++i) {
        const double lo = std::min(along_[0][i], along_[1][i]), hi = std::max(along_[0][i], along_[1][i]);
        if (lo == hi ? p[i] != lo : !(lo < p[i] && p[i] < hi)) return false;
      }
      if (has_line_ && !close_enough_to_line(line_, p)) return false;
    }
    for (int i = 0; i < n_; ++i)
      if (predicates::orient2d(p, face(i).p1, face(i).p2) != Sign::Positive) return false;
    return true;
  }

 private:
  struct Face {
    FaceHandle fh;
    VertexHandle v1, v2;
    Point2 p1, p2;
    bool forced1, forced2;
  };
  /// Stars up to kInline faces (all but rare hubs) live in the object: no allocation per move.
  static constexpr int kInline = 32;
  const Face& face(int i) const { return i < kInline ? faces_[i] : overflow_[static_cast<std::size_t>(i - kInline)]; }

  VertexHandle vh_;
  int n_ = 0;
  bool forced0_ = false;
  bool open_border_ = false;  ///< a border spoke at a vertex on no segment: can_relocate refuses it
  int n_along_ = 0;           ///< neighbours along the vertex's segment (up to two)
  Point2 along_[2];
  bool has_line_ = false;
  std::array<Point2, 2> line_{};
  Face faces_[kInline];
  std::vector<Face> overflow_;
};

}  // namespace

double star_margin(const Mesh& mesh, VertexHandle vh, const AngleBounds& bounds, const std::vector<bool>& forced) {
  CachedStar star;
  star.load(mesh, vh, forced);
  return star.margin(mesh, bounds);
}

double star_energy(const Mesh& mesh, VertexHandle vh, const AngleBounds& bounds, const std::vector<bool>& forced) {
  CachedStar star;
  star.load(mesh, vh, forced);
  return star.energy(mesh, point2(mesh, vh), bounds, forced);
}

bool relocate_for_angles(Mesh& mesh, VertexHandle vh, const AngleBounds& bounds, const std::vector<bool>& forced) {
  const auto& data = mesh.data(vh);
  if (data.kind == VertexKind::Input || closes_strip_apex(mesh, vh, forced, bounds.min_deg)) return false;
  // A star whose every angle is this far inside the bounds has nothing to gain: its energy terms
  // are below exp(-6) each, and a move changes no angle outside the star. (Most of a CVT mesh is
  // such stars; the pattern search would spend up to 240 evaluations on each.)
  constexpr double kComfortableMarginDeg = 12.0;
  CachedStar star;
  star.load(mesh, vh, forced);
  const double margin0 = star.margin(mesh, bounds);
  if (margin0 >= kComfortableMarginDeg) return false;
  // The soft minimum trades a little of the worst angle for much of the others: in a star with no
  // bad triangle that trade must not make one (a graded hub patch lost its thin wall triangles so).
  const bool keep_good = margin0 >= 0;
  const Point2 start = point2(mesh, vh);
  double mean_edge = 0;
  int degree = 0;
  Point2 centroid(0, 0);
  for (auto heh : mesh.voh_range(vh)) {
    const Point2 w = point2(mesh, mesh.to_vertex_handle(heh));
    mean_edge += (w - start).norm();
    centroid += w;
    ++degree;
  }
  if (degree == 0) return false;
  mean_edge /= degree;
  centroid /= degree;

  const bool on_segment = data.kind == VertexKind::OnSegment && data.segment >= 0 &&
                          static_cast<std::size_t>(data.segment) < segment_table(mesh).size();
  if (data.kind == VertexKind::OnSegment && !on_segment) return false;
  Point2 axis(1, 0);
  std::array<Point2, 2> ends{};
  if (on_segment) {
    ends = segment_endpoints(mesh, data.segment);
    axis = (ends[1] - ends[0]).normalized();
  }
  auto place = [&](const Point2& p) { return on_segment ? project_on_line(ends, p) : p; };

  const double base = star.energy(mesh, start, bounds, forced);
  double best = base;
  Point2 best_p = start;
  // Evaluates a candidate (exactly valid stars only) and keeps it when better.
  auto consider = [&](const Point2& q) {
    const Point2 p = place(q);
    if (p == best_p || !star.can_move_to(mesh, p)) return false;
    set_point2(mesh, vh, p);
    const double m = star.energy(mesh, p, bounds, forced);
    const bool better = m < best * (1 - 1e-12) && (!keep_good || star.margin(mesh, bounds) >= 0);
    set_point2(mesh, vh, best_p);
    if (better) {
      best = m;
      best_p = p;
      set_point2(mesh, vh, p);
      return true;
    }
    return false;
  };

  if (!on_segment) consider(centroid);
  // Pattern search: 8 directions (2 along a segment), halving the step when nothing improves.
  static const double kDirs[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {0.7071067811865476, 0.7071067811865476},
                                     {-0.7071067811865476, 0.7071067811865476}, {0.7071067811865476, -0.7071067811865476},
                                     {-0.7071067811865476, -0.7071067811865476}};
  double step = 0.2 * mean_edge;
  const double min_step = 1e-3 * mean_edge;
  for (int it = 0; it < 30 && step > min_step; ++it) {
    bool improved = false;
    if (on_segment) {
      improved = consider(best_p + step * axis) || consider(best_p - step * axis);
    } else {
      for (const auto& d : kDirs) improved = consider(best_p + step * Point2(d[0], d[1])) || improved;
    }
    if (!improved) step *= 0.5;
  }
  set_point2(mesh, vh, best_p);
  return best_p != start;
}

}  // namespace acute
