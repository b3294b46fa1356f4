// Delaunay refinement with corner lopping for small input angles.
//
// A sector narrower than 60 degrees between two segments at an input vertex A (a "corner") is cut
// off before refinement: every segment bounding such a sector at A is split at the same distance r
// from A, and the edge joining the two cut points of each sector (a "chord") becomes a temporary
// constraint. The fan triangles A-p-q inside the chords are never split, and every triangle outside
// them sees only angles of at least 90 degrees at the chord ends, so ordinary refinement applies
// there. When the apex subsegment [A, p] is encroached (from a wide sector at A) or a chord of a
// sector that is not narrower than the angle bound must be split, the corner shrinks: all its
// segments are cut again at r/2 and the chords move in. Chords of sectors narrower than the bound
// are split at their midpoints (their fan triangles all keep A as a corner, where a small angle is
// forced anyway). The chords lose their constraint status at the end; with every triangle meeting
// the bound they are locally Delaunay (a triangle beyond a chord would need an angle above 120).
#include <acute/refine/refine.h>

#include <acute/mesh/geometry.h>
#include <acute/mesh/segments.h>
#include <acute/ops/delaunay_flips.h>
#include <acute/ops/insert.h>
#include <acute/ops/remove.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace acute {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLopAngleDeg = 60.0;   // sectors narrower than this are lopped
constexpr double kAngleTolDeg = 1e-9;   // as meshcheck: a sector this close to the bound is not forced
constexpr int kMaxShrinks = 48;         // then the corner is frozen (its edges are never split)

struct Sector {
  int first = 0, second = 0;  // indices into Corner::cuts, counter-clockwise
  int chord = -1;             // segment id of the chord (-1: no chord)
  bool forced = false;        // narrower than the angle bound
};

struct Corner {
  VertexHandle apex;
  double radius = 0;
  int shrinks = 0;
  bool frozen = false;
  bool forced = false;  // some sector is narrower than the bound: every triangle at the apex is excused
  std::vector<VertexHandle> cuts;  // per lopped segment: far end of the apex subsegment
  std::vector<Sector> sectors;
};

enum class Role { Plain, ApexSub, Chord };

class Refiner {
 public:
  Refiner(Mesh& mesh, const RefineParams& params)
      : mesh_(mesh), params_(params), cos_min_(std::cos(params.min_angle_deg * kPi / 180.0)),
        max_radius2_(params.max_edge > 0 ? params.max_edge * params.max_edge / 3.0 : 0.0),
        off_constant_(0.475 / std::tan(0.5 * params.min_angle_deg * kPi / 180.0)),
        n_input_segments_(static_cast<int>(segment_table(mesh).size())),
        deadline_(params.time_limit_s > 0 ? std::chrono::steady_clock::now() +
                                                std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                    std::chrono::duration<double>(params.time_limit_s))
                                          : std::chrono::steady_clock::time_point::max()) {}

  RefineResult run() {
    lop_corners();
    // Faces re-created by a rollback are not queued: sweep the whole mesh until a sweep finds
    // nothing to do (or nothing changed).
    for (;;) {
      if (past_deadline()) {  // a sweep costs a pass over the whole mesh
        result_.status = RefineStatus::OutOfTime;
        break;
      }
      const std::size_t before = progress();
      for (auto fh : mesh_.faces())
        if (is_bad(fh)) faces_.push_back(fh);
      for (auto eh : mesh_.edges())
        if (is_constrained(mesh_, eh) && is_encroached(eh)) segments_.push_back(eh);
      if (faces_.empty() && segments_.empty()) break;
      process_queues();
      if (result_.status != RefineStatus::Converged || progress() == before) break;
    }
    release_chords();
    result_.corners = corners_.size();
    result_.shrinks = shrinks_;
    mesh_.garbage_collection();
    return result_;
  }

 private:
  std::size_t progress() const { return result_.inserted + result_.segment_splits + shrinks_; }
  bool past_deadline() const {
    return deadline_ != std::chrono::steady_clock::time_point::max() && std::chrono::steady_clock::now() > deadline_;
  }

  // ---------------------------------------------------------------- corners

  /// Angle at vh of the face left of its outgoing halfedge out.
  double angle_at(HalfedgeHandle out) const {
    const Point2 p = point2(mesh_, mesh_.from_vertex_handle(out)), a = point2(mesh_, mesh_.to_vertex_handle(out));
    const Point2 b = point2(mesh_, mesh_.to_vertex_handle(mesh_.next_halfedge_handle(out)));
    return std::atan2(std::abs(signed_area2(p, a, b)), (a - p).dot(b - p)) * 180.0 / kPi;
  }

  /// Distance from a to the nearest vertex or non-incident constrained edge, found by a walk over
  /// the faces whose edges come closer than the best distance so far.
  double feature_distance(VertexHandle apex) const {
    const Point2 a = point2(mesh_, apex);
    double best = std::numeric_limits<double>::infinity();
    std::vector<FaceHandle> stack;
    std::unordered_set<int> seen;
    for (auto fh : mesh_.vf_range(apex))
      if (seen.insert(fh.idx()).second) stack.push_back(fh);
    auto seg_dist = [&](const Point2& p, const Point2& q) {
      const Point2 d = q - p;
      const double t = std::clamp((a - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
      return (p + t * d - a).norm();
    };
    while (!stack.empty()) {
      const FaceHandle fh = stack.back();
      stack.pop_back();
      for (auto heh : mesh_.fh_range(fh)) {
        const VertexHandle u = mesh_.from_vertex_handle(heh), v = mesh_.to_vertex_handle(heh);
        if (u != apex) best = std::min(best, (point2(mesh_, u) - a).norm());
        const bool incident = u == apex || v == apex;
        const double d = incident ? 0.0 : seg_dist(point2(mesh_, u), point2(mesh_, v));
        if (!incident && is_constrained(mesh_, mesh_.edge_handle(heh))) best = std::min(best, d);
        const auto opp = mesh_.opposite_halfedge_handle(heh);
        if (mesh_.is_boundary(opp) || (!incident && d >= best)) continue;
        const FaceHandle next = mesh_.face_handle(opp);
        if (seen.insert(next.idx()).second) stack.push_back(next);
      }
    }
    return best;
  }

  void lop_corners() {
    if (n_input_segments_ == 0) return;
    // Find the corners and their radii on the unrefined CDT first, then cut.
    struct Plan {
      VertexHandle apex;
      std::vector<HalfedgeHandle> spokes;
      std::vector<Sector> sectors;
      double radius;
    };
    std::vector<Plan> plans;
    for (auto vh : mesh_.vertices()) {
      if (!is_input(mesh_, vh)) continue;
      Plan plan{vh, {}, {}, std::numeric_limits<double>::infinity()};
      auto spoke_index = [&](HalfedgeHandle h) {
        for (std::size_t i = 0; i < plan.spokes.size(); ++i)
          if (plan.spokes[i] == h) return static_cast<int>(i);
        plan.spokes.push_back(h);
        return static_cast<int>(plan.spokes.size()) - 1;
      };
      for (auto h : mesh_.voh_range(vh)) {
        if (mesh_.is_boundary(h) || !is_constrained(mesh_, mesh_.edge_handle(h))) continue;
        double angle = 0;
        HalfedgeHandle g = h, end;
        while (angle < kLopAngleDeg) {
          angle += angle_at(g);
          const HalfedgeHandle g2 = mesh_.opposite_halfedge_handle(mesh_.prev_halfedge_handle(g));
          if (is_constrained(mesh_, mesh_.edge_handle(g2))) {
            end = g2;
            break;
          }
          if (mesh_.is_boundary(g2)) break;  // an unconstrained border (convex hull): leave it
          g = g2;
        }
        if (!end.is_valid() || end == h || angle >= kLopAngleDeg) continue;
        Sector s;
        s.first = spoke_index(h);
        s.second = spoke_index(end);
        s.forced = angle < params_.min_angle_deg - kAngleTolDeg;
        plan.sectors.push_back(s);
      }
      if (plan.sectors.empty()) continue;
      for (auto h : plan.spokes)
        plan.radius = std::min(plan.radius, (point2(mesh_, mesh_.to_vertex_handle(h)) - point2(mesh_, vh)).norm() / 3.0);
      plan.radius = std::min(plan.radius, 0.4 * feature_distance(vh));
      if (params_.max_edge > 0) plan.radius = std::min(plan.radius, params_.max_edge);
      plans.push_back(std::move(plan));
    }
    SegmentTable table = segment_table(mesh_);
    for (auto& plan : plans) {
      Corner c;
      c.apex = plan.apex;
      c.radius = plan.radius;
      const Point2 a = point2(mesh_, plan.apex);
      bool ok = true;
      for (auto h : plan.spokes) {
        // The spoke is still an edge: cuts of other corners lie farther than 0.6 of its length.
        const Point2 b = point2(mesh_, mesh_.to_vertex_handle(h));
        const VertexHandle cut = split_edge(mesh_, mesh_.edge_handle(h), a + (b - a) * (plan.radius / (b - a).norm()));
        ok = ok && cut.is_valid();
        c.cuts.push_back(cut);
      }
      if (!ok) continue;  // (never expected) the corner is left to plain refinement
      const int index = static_cast<int>(corners_.size());
      for (auto s : plan.sectors) {
        const HalfedgeHandle chord = mesh_.find_halfedge(c.cuts[static_cast<std::size_t>(s.first)], c.cuts[static_cast<std::size_t>(s.second)]);
        if (!chord.is_valid() || is_constrained(mesh_, mesh_.edge_handle(chord))) continue;
        s.chord = static_cast<int>(table.size());
        table.push_back({point2(mesh_, mesh_.from_vertex_handle(chord)), point2(mesh_, mesh_.to_vertex_handle(chord))});
        mesh_.data(mesh_.edge_handle(chord)).segment = s.chord;
        chord_corner_.push_back(index);
        chord_sector_.push_back(static_cast<int>(c.sectors.size()));
        c.sectors.push_back(s);
      }
      if (c.sectors.empty()) continue;
      for (const auto& s : c.sectors) c.forced = c.forced || s.forced;
      corner_of_apex_[c.apex.idx()] = index;
      for (auto v : c.cuts) corner_of_cut_[v.idx()] = index;
      corners_.push_back(std::move(c));
    }
    set_segment_table(mesh_, std::move(table));
  }

  int chord_corner(int segment) const {
    const auto i = static_cast<std::size_t>(segment - n_input_segments_);
    return segment >= n_input_segments_ && i < chord_corner_.size() ? chord_corner_[i] : -1;
  }

  static int lookup(const std::unordered_map<int, int>& map, VertexHandle vh) {
    const auto it = map.find(vh.idx());
    return it == map.end() ? -1 : it->second;
  }

  /// Is vh the apex, a cut or a chord vertex of corner c (so it lies in or on c's fan)?
  bool in_fan(VertexHandle vh, int c) const {
    return vh == corners_[static_cast<std::size_t>(c)].apex || lookup(corner_of_cut_, vh) == c || chord_corner(mesh_.data(vh).segment) == c;
  }

  /// What a constrained edge is to the corners; `corner` receives the owning corner.
  Role role(EdgeHandle eh, int& corner) const {
    corner = chord_corner(mesh_.data(eh).segment);
    if (corner >= 0) return Role::Chord;
    const auto heh = mesh_.halfedge_handle(eh, 0);
    const VertexHandle u = mesh_.from_vertex_handle(heh), v = mesh_.to_vertex_handle(heh);
    for (auto [apex, cut] : {std::pair{u, v}, std::pair{v, u}}) {
      const int c = lookup(corner_of_apex_, apex);
      if (c >= 0 && lookup(corner_of_cut_, cut) == c) {
        corner = c;
        return Role::ApexSub;
      }
    }
    return Role::Plain;
  }

  /// Halves the radius of corner c: its segments are cut at r/2 and its chords move in.
  bool shrink(int c) {
    Corner& corner = corners_[static_cast<std::size_t>(c)];
    if (corner.frozen) return false;
    if (corner.shrinks >= kMaxShrinks) {
      corner.frozen = true;
      return false;
    }
    const Point2 a = point2(mesh_, corner.apex);
    std::vector<VertexHandle> cuts;
    for (auto old : corner.cuts) {
      const auto heh = mesh_.find_halfedge(corner.apex, old);
      const VertexHandle cut = heh.is_valid() ? split_edge(mesh_, mesh_.edge_handle(heh), a + 0.5 * (point2(mesh_, old) - a)) : VertexHandle();
      if (!cut.is_valid()) {
        corner.frozen = true;
        return false;
      }
      cuts.push_back(cut);
      after_insertion(cut);
    }
    std::vector<EdgeHandle> released;
    SegmentTable table = segment_table(mesh_);
    for (auto& s : corner.sectors) {
      if (s.chord < 0) continue;
      release_chord(corner.cuts[static_cast<std::size_t>(s.first)], corner.cuts[static_cast<std::size_t>(s.second)], s.chord, released);
      const auto chord = mesh_.find_halfedge(cuts[static_cast<std::size_t>(s.first)], cuts[static_cast<std::size_t>(s.second)]);
      if (!chord.is_valid() || is_constrained(mesh_, mesh_.edge_handle(chord))) {
        s.chord = -1;  // (never expected) the sector becomes plain
        continue;
      }
      mesh_.data(mesh_.edge_handle(chord)).segment = s.chord;
      table[static_cast<std::size_t>(s.chord)] = {point2(mesh_, mesh_.from_vertex_handle(chord)), point2(mesh_, mesh_.to_vertex_handle(chord))};
    }
    set_segment_table(mesh_, std::move(table));
    for (auto old : corner.cuts) corner_of_cut_.erase(old.idx());
    for (auto v : cuts) corner_of_cut_[v.idx()] = c;
    corner.cuts = std::move(cuts);
    corner.radius *= 0.5;
    ++corner.shrinks;
    ++shrinks_;
    std::vector<EdgeHandle> queue = released;
    restore_delaunay(mesh_, queue);
    for (auto eh : released)
      if (!mesh_.status(eh).deleted())
        for (int side = 0; side < 2; ++side) {
          const auto fh = mesh_.face_handle(mesh_.halfedge_handle(eh, side));
          if (fh.is_valid()) faces_.push_back(fh);
        }
    return true;
  }

  /// Unconstrains the chord chain from u to v (segment id `chord`); its inner vertices become free.
  void release_chord(VertexHandle u, VertexHandle v, int chord, std::vector<EdgeHandle>& released) {
    VertexHandle prev, cur = u;
    while (cur != v) {
      HalfedgeHandle step;
      for (auto heh : mesh_.voh_range(cur))
        if (mesh_.data(mesh_.edge_handle(heh)).segment == chord && mesh_.to_vertex_handle(heh) != prev) step = heh;
      if (!step.is_valid()) break;
      const EdgeHandle eh = mesh_.edge_handle(step);
      mesh_.data(eh).segment = -1;
      mesh_.data(eh).marker = 0;
      released.push_back(eh);
      if (cur != u) {
        mesh_.data(cur).kind = VertexKind::Free;
        mesh_.data(cur).segment = -1;
      }
      prev = cur;
      cur = mesh_.to_vertex_handle(step);
    }
  }

  void release_chords() {
    std::vector<EdgeHandle> released;
    for (const auto& corner : corners_)
      for (const auto& s : corner.sectors)
        if (s.chord >= 0) release_chord(corner.cuts[static_cast<std::size_t>(s.first)], corner.cuts[static_cast<std::size_t>(s.second)], s.chord, released);
    if (corners_.empty()) return;
    SegmentTable table = segment_table(mesh_);
    table.resize(static_cast<std::size_t>(n_input_segments_));
    set_segment_table(mesh_, std::move(table));
    restore_delaunay(mesh_, released);
  }

  /// A face with a corner at the apex of a forced corner (where meshcheck excuses any angle).
  bool at_forced_corner(FaceHandle fh) const {
    for (auto vh : mesh_.fv_range(fh)) {
      const int c = lookup(corner_of_apex_, vh);
      if (c >= 0 && corners_[static_cast<std::size_t>(c)].forced) return true;
    }
    return false;
  }

  /// A face inside a fan: the apex of a corner and two vertices of its fan.
  bool is_fan_face(FaceHandle fh) const {
    const auto v = face_vertices(mesh_, fh);
    for (int k = 0; k < 3; ++k) {
      const int c = lookup(corner_of_apex_, v[k]);
      if (c >= 0 && in_fan(v[(k + 1) % 3], c) && in_fan(v[(k + 2) % 3], c)) return true;
    }
    return false;
  }

  // ---------------------------------------------------------------- refinement

  void process_queues() {
    for (std::size_t step = 1;; ++step) {
      if (mesh_.n_vertices() >= params_.max_vertices) {
        result_.status = RefineStatus::BudgetExhausted;
        break;
      }
      if (step % 256 == 0 && past_deadline()) {
        result_.status = RefineStatus::OutOfTime;
        break;
      }
      if (!segments_.empty()) {
        const EdgeHandle eh = segments_.back();
        segments_.pop_back();
        if (!mesh_.status(eh).deleted() && is_constrained(mesh_, eh) && is_encroached(eh)) resolve(eh);
        continue;
      }
      if (faces_.empty()) break;
      const FaceHandle fh = faces_.front();
      faces_.pop_front();
      if (!mesh_.status(fh).deleted() && is_bad(fh)) split_triangle(fh);
    }
  }

  bool is_encroached(EdgeHandle eh) const {
    int c = -1;
    const Role r = role(eh, c);
    if (r != Role::Plain && corners_[static_cast<std::size_t>(c)].frozen) return false;
    // At a forced corner every triangle at the apex is excused, so a vertex seeing an apex
    // subsegment at an obtuse angle harms nothing (only a blocked Steiner point shrinks the corner).
    if (r == Role::ApexSub && corners_[static_cast<std::size_t>(c)].forced) return false;
    for (int side = 0; side < 2; ++side) {
      const auto heh = mesh_.halfedge_handle(eh, side);
      if (mesh_.is_boundary(heh)) continue;
      const VertexHandle apex = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(heh));
      if (r != Role::Plain && in_fan(apex, c)) continue;  // the fan side of a corner's edges
      const Point2 a = point2(mesh_, mesh_.from_vertex_handle(heh)), b = point2(mesh_, mesh_.to_vertex_handle(heh));
      if (predicates::in_diametral_circle(a, b, point2(mesh_, apex)) == Sign::Positive) return true;
    }
    return false;
  }

  /// Deals with an encroached (or blocking) constrained edge. False when nothing could be done.
  bool resolve(EdgeHandle eh) {
    int c = -1;
    switch (role(eh, c)) {
      case Role::Plain: return split_segment(eh);
      case Role::ApexSub: return shrink(c);
      case Role::Chord: {
        const auto& corner = corners_[static_cast<std::size_t>(c)];
        if (corner.frozen) return false;
        return corner.forced ? split_segment(eh) : shrink(c);
      }
    }
    return false;
  }

  bool split_segment(EdgeHandle eh) {
    const auto heh = mesh_.halfedge_handle(eh, 0);
    const Point2 a = point2(mesh_, mesh_.from_vertex_handle(heh)), b = point2(mesh_, mesh_.to_vertex_handle(heh));
    const VertexHandle vh = split_edge(mesh_, eh, 0.5 * (a + b));
    if (!vh.is_valid()) return false;
    ++result_.segment_splits;
    after_insertion(vh);
    return true;
  }

  bool is_bad(FaceHandle fh) const {
    if (is_fan_face(fh)) return false;
    const auto p = face_points(mesh_, fh);
    if (max_radius2_ > 0 && (circumcenter(p[0], p[1], p[2]) - p[0]).squaredNorm() > max_radius2_) return true;
    if (at_forced_corner(fh)) return false;
    const auto c = angle_cosines(p[0], p[1], p[2]);
    const int k = smallest_angle(c);
    if (c[k] <= cos_min_) return false;
    // A small angle at an input vertex between segments (a corner that could not be lopped).
    const auto v = face_vertices(mesh_, fh);
    return !(is_input(mesh_, v[k]) && corner_sector_deg(fh, v[k]) < params_.min_angle_deg);
  }

  static int smallest_angle(const std::array<double, 3>& c) { return c[0] >= c[1] && c[0] >= c[2] ? 0 : (c[1] >= c[2] ? 1 : 2); }

  /// Angle of the sector around vh that contains face fh and is bounded by segments (360 if none).
  double corner_sector_deg(FaceHandle fh, VertexHandle vh) const {
    HalfedgeHandle start;  // the outgoing halfedge of vh in fh
    for (auto heh : mesh_.fh_range(fh))
      if (mesh_.from_vertex_handle(heh) == vh) start = heh;
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
      // (An unconstrained border, e.g. a convex hull edge, is split like a segment.)
      if (is_constrained(mesh_, loc.edge) ? resolve(loc.edge) : split_segment(loc.edge)) faces_.push_back(fh);
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
      bool resolved = false;
      for (const auto& ends : encroached) {
        const auto heh = mesh_.find_halfedge(ends[0], ends[1]);
        if (heh.is_valid() && is_constrained(mesh_, mesh_.edge_handle(heh))) resolved |= resolve(mesh_.edge_handle(heh));
      }
      if (resolved) faces_.push_back(fh);
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
  int n_input_segments_;
  std::chrono::steady_clock::time_point deadline_;
  std::vector<Corner> corners_;
  std::vector<int> chord_corner_, chord_sector_;  // indexed by chord segment id - n_input_segments_
  std::unordered_map<int, int> corner_of_apex_, corner_of_cut_;
  std::size_t shrinks_ = 0;
  std::vector<EdgeHandle> segments_;
  std::deque<FaceHandle> faces_;
  RefineResult result_;
};

}  // namespace

RefineResult refine(Mesh& mesh, const RefineParams& params) { return Refiner(mesh, params).run(); }

}  // namespace acute
