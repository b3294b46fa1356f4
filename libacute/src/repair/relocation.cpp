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

/// The star of a vertex as the descent sees it. Only the vertex moves, so each face, its
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

  /// Reads which corners the min bound applies to: an exempt corner's input sector is narrower
  /// than the min, and that does not change as the vertex moves. Before energy().
  void load_min_exemptions(const Mesh& mesh, double min_deg, const std::vector<bool>& forced) {
    for (int i = 0; i < n_; ++i) {
      Face& f = face(i);
      const bool forced_corner[3] = {forced0_, f.forced1, f.forced2};
      const VertexHandle corner[3] = {vh_, f.v1, f.v2};
      for (int k = 0; k < 3; ++k) f.min_applies[k] = !(forced_corner[k] && min_exempt_corner(mesh, corner[k], f.fh, min_deg, forced));
    }
  }

  /// The soft minimum of the star's angle margins with the vertex at p: every angle near or beyond
  /// a bound pushes, the worst most. (A plain max-min stalls when the worst angle cannot change,
  /// e.g. at a fixed input corner.) With `gradient`, also its gradient with respect to p.
  double energy(const Point2& p, const AngleBounds& bounds, Point2* gradient = nullptr) const {
    constexpr double kTau = 2.0;  // degrees
    constexpr double kDeg = 57.29577951308232;
    double energy = 0;
    Point2 grad(0, 0);
    for (int i = 0; i < n_; ++i) {
      const Face& f = face(i);
      // The angles at p1 and p2; the one at p is what is left of 180 degrees.
      const double a1 = approx_angle_deg(f.p1, f.p2, p), a2 = approx_angle_deg(f.p2, p, f.p1);
      const double angles[3] = {180.0 - a1 - a2, a1, a2};
      double slope[3];  // d energy / d angle
      for (int k = 0; k < 3; ++k) {
        const double to_max = bounds.max_deg - angles[k];
        const bool min_binds = f.min_applies[k] && angles[k] - bounds.min_deg < to_max;
        const double e = std::exp(-(min_binds ? angles[k] - bounds.min_deg : to_max) / kTau);
        energy += e;
        slope[k] = min_binds ? -e / kTau : e / kTau;
      }
      if (!gradient) continue;
      // In a counter-clockwise triangle (p, p1, p2) the angle at p1 is arg(p - p1) - arg(p2 - p1) and
      // the one at p2 is arg(p1 - p2) - arg(p - p2); the one at p is 180 degrees minus both.
      const Point2 w1 = p - f.p1, w2 = p - f.p2;
      const double n1 = w1.squaredNorm(), n2 = w2.squaredNorm();
      if (!(n1 > 0) || !(n2 > 0)) continue;
      const Point2 d1 = kDeg * Point2(-w1.y(), w1.x()) / n1, d2 = -kDeg * Point2(-w2.y(), w2.x()) / n2;
      grad += (slope[1] - slope[0]) * d1 + (slope[2] - slope[0]) * d2;
    }
    if (gradient) *gradient = grad;
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
      // keeps_segment_order's test.
      if (n_along_ < 2 || !in_chain_order(along_[1] - along_[0], along_[0], p, along_[1])) return false;
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
    bool min_applies[3];  ///< at the vertex, v1 and v2 (load_min_exemptions)
  };
  /// Stars up to kInline faces (all but rare hubs) live in the object: no allocation per move.
  static constexpr int kInline = 32;
  const Face& face(int i) const { return i < kInline ? faces_[i] : overflow_[static_cast<std::size_t>(i - kInline)]; }
  Face& face(int i) { return i < kInline ? faces_[i] : overflow_[static_cast<std::size_t>(i - kInline)]; }

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
  star.load_min_exemptions(mesh, bounds.min_deg, forced);
  return star.energy(point2(mesh, vh), bounds);
}

bool relocate_for_angles(Mesh& mesh, VertexHandle vh, const AngleBounds& bounds, const std::vector<bool>& forced) {
  const auto& data = mesh.data(vh);
  if (data.kind == VertexKind::Input || closes_strip_apex(mesh, vh, forced, bounds.min_deg)) return false;
  // A star whose every angle is this far inside the bounds has nothing to gain: its energy terms
  // are below exp(-6) each, and a move changes no angle outside the star. (Most of a CVT mesh is
  // such stars; the descent would spend a dozen evaluations on each.)
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

  Point2 gradient(0, 0), trial_gradient(0, 0);
  star.load_min_exemptions(mesh, bounds.min_deg, forced);
  const double base = star.energy(start, bounds, &gradient);
  double best = base;
  Point2 best_p = start;
  // Evaluates a candidate (exactly valid stars only) and keeps it, with its gradient, when better.
  auto consider = [&](const Point2& q) {
    const Point2 p = place(q);
    if (p == best_p || !star.can_move_to(mesh, p)) return false;
    set_point2(mesh, vh, p);
    const double m = star.energy(p, bounds, &trial_gradient);
    const bool better = m < best * (1 - 1e-12) && (!keep_good || star.margin(mesh, bounds) >= 0);
    set_point2(mesh, vh, best_p);
    if (better) {
      best = m;
      best_p = p;
      gradient = trial_gradient;
      set_point2(mesh, vh, p);
      return true;
    }
    return false;
  };

  if (!on_segment) consider(centroid);
  // Descent along the gradient (along the segment for a vertex on one): a refused step halves,
  // an accepted one grows by half. A tenth of the pattern search's evaluations for the same
  // resolution (it tried 8 directions a step).
  double step = 0.2 * mean_edge;
  const double min_step = 1e-3 * mean_edge;
  for (int it = 0; it < 40 && step > min_step; ++it) {
    const Point2 d = on_segment ? Point2(gradient.dot(axis) * axis) : gradient;
    const double norm = d.norm();
    if (!(norm > 0) || !std::isfinite(norm)) break;
    if (consider(best_p - (step / norm) * d))
      step = std::min(1.5 * step, 0.5 * mean_edge);
    else
      step *= 0.5;
  }
  set_point2(mesh, vh, best_p);
  return best_p != start;
}

}  // namespace acute
