#include <acute/cvt/cvt.h>

#include "cvt/in_place.h"
#include "cvt/settled_cells.h"

#include <acute/core/errors.h>
#include <acute/delaunay/cdt.h>
#include <acute/mesh/segments.h>
#include <acute/ops/delaunay_flips.h>
#include <acute/ops/relocate.h>

#include <LBFGSpp/BFGSMat.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

namespace acute {
namespace {

/// A vertex the optimiser moves: not deleted, not an input vertex, in a face.
bool is_mover(const Mesh& mesh, VertexHandle vh) {
  return !mesh.status(vh).deleted() && mesh.data(vh).kind != VertexKind::Input && !mesh.is_isolated(vh);
}

/// The moving vertices, their coordinates (2 per free vertex, the arc length along the segment
/// for a vertex on a segment), the cells, and the move/flip machinery.
class Optimizer {
 public:
  Optimizer(Mesh& mesh, const SizeField& field, const CvtOptimizeParams& params) : mesh_(mesh), field_(field) {
    std::vector<char> taken(mesh.n_vertices(), 0);
    auto add = [&](VertexHandle vh) {
      if (!vh.is_valid() || !is_mover(mesh, vh) || taken[static_cast<std::size_t>(vh.idx())]) return;
      const auto& d = mesh.data(vh);
      taken[static_cast<std::size_t>(vh.idx())] = 1;
      Mover m;
      m.vh = vh;
      m.offset = num_vars_;
      if (d.kind == VertexKind::OnSegment) {
        if (d.segment < 0 || static_cast<std::size_t>(d.segment) >= segment_table(mesh).size())
          throw InvalidInput("cvt: vertex " + std::to_string(vh.idx()) + " is on a segment missing from the segment table");
        const auto& [a, b] = segment_endpoints(mesh, d.segment);
        m.segment = d.segment;
        m.origin = a;
        m.dir = (b - a).normalized();
        num_vars_ += 1;
      } else {
        num_vars_ += 2;
      }
      movers_.push_back(m);
    };
    local_ = !params.subset.empty();
    if (local_) {
      for (VertexHandle vh : params.subset) add(vh);
      std::sort(movers_.begin(), movers_.end(), [](const Mover& a, const Mover& b) { return a.vh.idx() < b.vh.idx(); });
      int off = 0;
      for (auto& m : movers_) m.offset = off, off += m.segment >= 0 ? 1 : 2;
    } else {
      for (auto vh : mesh.vertices()) add(vh);
    }
    face_stamp_.assign(mesh.n_faces(), 0);
  }

  int num_vars() const { return num_vars_; }
  std::size_t num_movers() const { return movers_.size(); }

  /// The movers whose last evaluated move |v - c_v| / h(v) exceeds `threshold`.
  std::vector<VertexHandle> moving(double threshold) const {
    std::vector<VertexHandle> out;
    for (std::size_t k = 0; k < movers_.size(); ++k)
      if (move_[k] > threshold) out.push_back(movers_[k].vh);
    return out;
  }

  /// The rms move is taken as over `count` movers, the others still (an active set's complement).
  void count_still_movers(std::size_t count) { rms_count_ = std::max(count, movers_.size()); }
  /// Added to the energy reported (the frozen cells' part, for an active set).
  void set_energy_offset(double offset) {
    energy_ += offset - energy_offset_;
    energy_offset_ = offset;
  }

  /// Cells at the current positions: energy, gradient, max |v - c| / h.
  void evaluate() {
    if (local_) {
      faces_.clear();
      ++stamp_;
      for (const auto& m : movers_)
        for (auto fh : mesh_.vf_range(m.vh))
          if (face_stamp_[static_cast<std::size_t>(fh.idx())] != stamp_) {
            face_stamp_[static_cast<std::size_t>(fh.idx())] = stamp_;
            faces_.push_back(fh);
          }
      std::sort(faces_.begin(), faces_.end());
    }
    compute_cells(mesh_, field_, cells_, ws_, local_ ? &faces_ : nullptr);
    energy_ = cells_.energy + energy_offset_;
    grad_.resize(num_vars_);
    move_.resize(movers_.size());
    max_move_ = 0;
    double sum2 = 0;
    for (std::size_t k = 0; k < movers_.size(); ++k) {
      const Mover& m = movers_[k];
      const auto i = static_cast<std::size_t>(m.vh.idx());
      const double mass = cells_.mass[i];
      const Point2 g = -2.0 * cells_.shift[i];  // dF/dv = 2 m (v - c) (the cell boundary terms cancel)
      const double h = std::pow(ws_.vertex_rho[i], -0.25);
      if (m.segment >= 0) {
        grad_[m.offset] = g.dot(m.dir);
        const double r = (mass > 0 ? std::abs(grad_[m.offset]) / (2.0 * mass * h) : 0.0);
        max_move_ = std::max(max_move_, r);
        sum2 += r * r;
        move_[k] = r;
      } else {
        grad_[m.offset] = g.x();
        grad_[m.offset + 1] = g.y();
        const double r = (mass > 0 ? g.norm() / (2.0 * mass * h) : 0.0);
        max_move_ = std::max(max_move_, r);
        sum2 += r * r;
        move_[k] = r;
      }
    }
    const std::size_t count = std::max(rms_count_, movers_.size());
    rms_move_ = count == 0 ? 0.0 : std::sqrt(sum2 / static_cast<double>(count));
  }

  void get_x(Eigen::VectorXd& x) const {
    x.resize(num_vars_);
    for (const auto& m : movers_) {
      const Point2 v = point2(mesh_, m.vh);
      if (m.segment >= 0) {
        x[m.offset] = (v - m.origin).dot(m.dir);
      } else {
        x[m.offset] = v.x();
        x[m.offset + 1] = v.y();
      }
    }
  }

  /// Lloyd targets: the centroids (projected on the segment line for vertices on segments).
  void lloyd_targets(Eigen::VectorXd& x) const {
    x.resize(num_vars_);
    for (const auto& m : movers_) {
      const auto i = static_cast<std::size_t>(m.vh.idx());
      const double mass = cells_.mass[i];
      const Point2 c = point2(mesh_, m.vh) + (mass > 0 ? Point2(cells_.shift[i] / mass) : Point2(0, 0));
      if (m.segment >= 0) {
        x[m.offset] = (c - m.origin).dot(m.dir);
      } else {
        x[m.offset] = c.x();
        x[m.offset + 1] = c.y();
      }
    }
  }

  /// Diagonal scaling 1/sqrt(2 m) per coordinate (a unit step along -scaled gradient is Lloyd's).
  void scaling(Eigen::VectorXd& s) const {
    s.resize(num_vars_);
    for (const auto& m : movers_) {
      const double mass = cells_.mass[static_cast<std::size_t>(m.vh.idx())];
      const double si = mass > 0 ? 1.0 / std::sqrt(2.0 * mass) : 0.0;
      s[m.offset] = si;
      if (m.segment < 0) s[m.offset + 1] = si;
    }
  }

  /// Moves every vertex towards its target (halving a move that would invert a triangle or leave
  /// the segment interval, up to 8 times), then restores the constrained Delaunay property.
  void apply(const Eigen::VectorXd& x) {
    queue_.clear();
    blocked_ = 0;
    for (const auto& m : movers_) {
      const Point2 v = point2(mesh_, m.vh);
      Point2 target = m.segment >= 0 ? Point2(m.origin + x[m.offset] * m.dir) : Point2(x[m.offset], x[m.offset + 1]);
      if (m.segment >= 0) target = project_on_segment(mesh_, m.segment, target);
      if (target == v) continue;
      bool moved = false;
      const double h = std::pow(ws_.vertex_rho[static_cast<std::size_t>(m.vh.idx())], -0.25);
      for (int k = 0; k <= 8; ++k) {
        if (keeps_clear_of_constraints(m.vh, v, target, h) && can_relocate(mesh_, m.vh, target) == OpVerdict::Ok) {
          relocate(mesh_, m.vh, target);
          moved = true;
          if (k > 0) ++blocked_;
          break;
        }
        target = 0.5 * (v + target);
        if (m.segment >= 0) target = project_on_segment(mesh_, m.segment, target);
      }
      if (!moved) ++blocked_;
      if (moved) moved_.push_back(m.vh);
    }
    // Many moves: every edge once is cheaper than the stars (each edge would come up ~4 times).
    if (moved_.size() * 4 > mesh_.n_vertices()) {
      for (auto eh : mesh_.edges()) queue_.push_back(eh);
    } else {
      for (VertexHandle vh : moved_) push_star_edges(mesh_, vh, queue_);
    }
    moved_.clear();
    flips_ = restore_delaunay(mesh_, queue_);
  }

  /// A vertex whose centroid lies across a constrained edge of its link (an interior segment with
  /// the same region on both sides, whose cells are not cut by it) would creep onto that edge by
  /// ever shorter moves and leave a flat triangle: a move may not bring it closer to such an edge
  /// than a quarter of its size (or than it already is).
  bool keeps_clear_of_constraints(VertexHandle vh, const Point2& from, const Point2& to, double h) const {
    for (auto he : mesh_.voh_range(vh)) {
      if (!mesh_.face_handle(he).is_valid()) continue;
      const auto opposite = mesh_.next_halfedge_handle(he);
      if (!is_constrained(mesh_, mesh_.edge_handle(opposite))) continue;
      const Point2 a = point2(mesh_, mesh_.from_vertex_handle(opposite)), b = point2(mesh_, mesh_.to_vertex_handle(opposite));
      auto distance = [&](const Point2& p) {
        const Point2 ab = b - a;
        const double l2 = ab.squaredNorm();
        const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
        return (a + t * ab - p).norm();
      };
      if (distance(to) < std::min(distance(from), 0.25 * h)) return false;
    }
    return true;
  }

  double energy() const { return energy_; }
  const Eigen::VectorXd& gradient() const { return grad_; }
  double max_move() const { return max_move_; }
  double rms_move() const { return rms_move_; }
  std::size_t flips() const { return flips_; }
  std::size_t blocked() const { return blocked_; }

 private:
  struct Mover {
    VertexHandle vh;
    int offset = 0;
    int segment = -1;
    Point2 origin{0, 0}, dir{0, 0};
  };
  Mesh& mesh_;
  const SizeField& field_;
  bool local_ = false;
  std::vector<Mover> movers_;
  int num_vars_ = 0;
  CellIntegrals cells_;
  CellWorkspace ws_;
  std::vector<FaceHandle> faces_;
  std::vector<unsigned> face_stamp_;
  unsigned stamp_ = 0;
  std::vector<EdgeHandle> queue_;
  std::vector<VertexHandle> moved_;
  Eigen::VectorXd grad_;
  std::vector<double> move_;  ///< per mover, at the last evaluation
  std::size_t rms_count_ = 0;
  double energy_offset_ = 0;
  double energy_ = 0, max_move_ = 0, rms_move_ = 0;
  std::size_t flips_ = 0, blocked_ = 0;
};

}  // namespace

CvtOptimizeResult cvt_optimize(Mesh& mesh, const SizeField& field, const CvtOptimizeParams& params) {
  CvtOptimizeResult res;
  std::optional<Optimizer> whole, part;
  // The active set's optimiser: its rms counts the `count` movers of the mesh, the others still.
  auto start_part = [&](const CvtOptimizeParams& local, std::size_t count) {
    res.active = local.subset.size();
    part.emplace(mesh, field, local);
    part->count_still_movers(count);
    part->evaluate();
  };
  if (params.active_move > 0 && params.subset.empty() && params.predict_settled) {
    // Cells known to have settled stand in for a first evaluation of every cell.
    std::vector<double> h;
    const std::vector<double> spacing = detail::settled_cells(mesh, field, params.active_move, h);
    std::vector<VertexHandle> unsettled;
    std::size_t count = 0;
    for (auto vh : mesh.vertices()) {
      if (!is_mover(mesh, vh)) continue;
      ++count;
      if (spacing[static_cast<std::size_t>(vh.idx())] == 0) unsettled.push_back(vh);
    }
    CvtOptimizeParams local = params;
    std::vector<char> seen;
    local.subset = with_rings(mesh, std::move(unsettled), 2, seen);
    if (local.subset.size() * 2 <= count) {
      // The frozen part of the energy: a settled cell is six kites of equal energy, one in each of
      // its triangles; those in triangles of the active vertices are in the part's energy.
      for (VertexHandle vh : local.subset) seen[static_cast<std::size_t>(vh.idx())] = 1;
      double frozen = 0;
      for (auto vh : mesh.vertices()) {
        const auto i = static_cast<std::size_t>(vh.idx());
        if (spacing[i] == 0 || seen[i]) continue;
        int kites = 0;
        for (auto heh : mesh.voh_range(vh))
          kites += !seen[static_cast<std::size_t>(mesh.to_vertex_handle(heh).idx())] &&
                   !seen[static_cast<std::size_t>(mesh.to_vertex_handle(mesh.next_halfedge_handle(heh)).idx())];
        frozen += (kites / 6.0) * detail::settled_cell_energy(spacing[i], h[i]);
      }
      if (local.subset.empty()) {  // every cell has settled
        res.initial_energy = res.energy = frozen;
        res.converged = true;
        return res;
      }
      start_part(local, count);
      part->set_energy_offset(frozen);
      res.initial_energy = part->energy();
    }
  }
  if (!part) {
    whole.emplace(mesh, field, params);
    whole->evaluate();
    res.initial_energy = whole->energy();
  }
  if (!part && params.active_move > 0 && params.subset.empty()) {
    CvtOptimizeParams local = params;
    std::vector<char> seen;
    local.subset = with_rings(mesh, whole->moving(params.active_move), 2, seen);
    if (!local.subset.empty() && local.subset.size() * 2 <= whole->num_movers()) {
      const std::size_t count = whole->num_movers();
      const double total = whole->energy();
      whole.reset();
      start_part(local, count);
      part->set_energy_offset(total - part->energy());
    }
  }
  Optimizer& opt = part ? *part : *whole;
  res.energy = opt.energy();
  res.gradient_norm = opt.gradient().norm();
  res.max_move = opt.max_move();
  res.rms_move = opt.rms_move();
  if (opt.num_vars() == 0) {
    res.converged = true;
    return res;
  }
  int iteration = 0;
  auto report = [&](const char* phase, bool fallback) {
    res.energy = opt.energy();
    res.gradient_norm = opt.gradient().norm();
    res.max_move = opt.max_move();
    res.rms_move = opt.rms_move();
    if (params.observer) {
      CvtProgress p;
      p.phase = phase;
      p.iteration = iteration;
      p.energy = res.energy;
      p.gradient_norm = res.gradient_norm;
      p.max_move = res.max_move;
      p.rms_move = res.rms_move;
      p.flips = opt.flips();
      p.blocked = opt.blocked();
      p.fallback = fallback;
      params.observer(p);
    }
  };
  auto done = [&](double previous_energy) {
    if (opt.rms_move() < params.move_tolerance || opt.max_move() < params.max_move_tolerance) return true;
    return std::abs(previous_energy - opt.energy()) <= params.energy_tolerance * std::abs(opt.energy());
  };

  Eigen::VectorXd x, target;
  auto lloyd_step = [&]() {
    opt.lloyd_targets(target);
    opt.apply(target);
    opt.evaluate();
  };
  const auto start = std::chrono::steady_clock::now();
  auto out_of_time = [&] {
    return params.time_limit_s > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > params.time_limit_s;
  };
  for (int k = 0; k < params.lloyd_iterations && !out_of_time(); ++k) {
    const double before = opt.energy();
    lloyd_step();
    ++iteration;
    ++res.lloyd_iterations;
    report("lloyd", false);
    if (done(before)) {
      res.converged = true;
      return res;
    }
  }

  // L-BFGS in the scaled coordinates z = x / s (s = 1/sqrt(2 m) at the start of the phase).
  const int n = opt.num_vars();
  LBFGSpp::BFGSMat<double> bfgs;
  bfgs.reset(n, std::max(1, params.lbfgs_memory));
  Eigen::VectorXd s, gz, dz(n), x0, g0, zstep, y;
  opt.scaling(s);
  for (int k = 0; k < params.lbfgs_iterations && !out_of_time(); ++k) {
    opt.get_x(x0);
    g0 = opt.gradient();
    const double f0 = opt.energy();
    gz = s.cwiseProduct(g0);
    if (bfgs.num_corrections() > 0) {
      bfgs.apply_Hv(gz, -1.0, dz);
    } else {
      dz = -gz;
    }
    if (!(gz.dot(dz) < 0)) {
      bfgs.reset(n, std::max(1, params.lbfgs_memory));
      dz = -gz;
    }
    bool accepted = false;
    double step = 1.0;
    for (int ls = 0; ls < 5; ++ls, step *= 0.5) {
      target = x0 + step * s.cwiseProduct(dz);
      opt.apply(target);
      opt.evaluate();
      opt.get_x(x);
      zstep = (x - x0).cwiseQuotient(s.cwiseMax(std::numeric_limits<double>::min()));
      const double slope = std::min(0.0, gz.dot(zstep));
      if (opt.energy() <= f0 + 1e-4 * slope && opt.energy() < f0) {
        accepted = true;
        break;
      }
    }
    ++iteration;
    ++res.lbfgs_iterations;
    if (accepted) {
      y = s.cwiseProduct(opt.gradient() - g0);
      const double sy = zstep.dot(y);
      if (sy > 1e-10 * zstep.norm() * y.norm()) bfgs.add_correction(zstep, y);
    } else {
      bfgs.reset(n, std::max(1, params.lbfgs_memory));
      lloyd_step();
      ++res.fallbacks;
      if (opt.energy() > f0) {
        // Neither descends: the blocked moves near tiny features make further steps climb (stress
        // seed 132 went from 649 to 81,864 in 20 such steps). Back to the last accepted point.
        opt.apply(x0);
        opt.evaluate();
        report("lbfgs", true);
        break;
      }
    }
    report("lbfgs", !accepted);
    if (done(f0)) {
      res.converged = true;
      return res;
    }
  }
  return res;
}

CvtResult cvt_mesh(const Domain& domain, const CvtParams& params) {
  CvtResult out;
  detail::cvt_mesh_into(out.mesh, out, domain, params);
  return out;
}

void detail::cvt_mesh_into(Mesh& mesh, CvtResult& out, const Domain& domain, const CvtParams& params) {
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const Mesh cdt = build_cdt(domain);
  SizeFieldParams sp;
  sp.size = params.size;
  sp.target_vertices = params.target_vertices;
  sp.graded = params.graded;
  sp.gradation = params.gradation;
  sp.lfs_factor = params.lfs_factor;
  sp.hmax = params.hmax;
  sp.scale = params.size_scale;
  sp.max_vertices = params.max_vertices;
  sp.hold_count = params.hold_count;
  sp.held_count_at_least = params.held_count_at_least;
  if (params.time_limit_s > 0) {
    sp.time_limit_s = std::max(0.25 * params.time_limit_s - elapsed(), 1e-9);
    sp.abandon_after_s = std::max(params.time_limit_s - elapsed(), 1e-9);
  }
  bool size_field_abandoned = false;
  out.size_field = make_size_field(cdt, sp, &size_field_abandoned, &out.features_decide, &out.count_held);
  if (params.size_cap && !out.size_field.is_uniform()) {
    std::vector<double> values = out.size_field.background_values();
    const auto& points = out.size_field.background_points();
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double cap = params.size_cap(points[i]);
      if (cap > 0 && std::isfinite(cap)) values[i] = std::min(values[i], cap);
    }
    out.size_field = out.size_field.with_values(std::move(values));
  }
  if (size_field_abandoned || (params.time_limit_s > 0 && elapsed() > params.time_limit_s)) {
    out.out_of_time = out.abandoned = true;
    return;
  }
  SamplingParams samp;
  samp.seed = params.seed;
  samp.interior = params.interior;
  sample_domain_into(mesh, domain, cdt, out.size_field, samp, &out.sampling);
  // The count model is not exact (and --size has none): coarsen and resample while over budget.
  // Samples scale as 1 / h^2 away from the input points, which stay.
  for (int k = 0; k < 2 && params.max_vertices > 0 && mesh.n_vertices() > params.max_vertices; ++k) {
    if (params.time_limit_s > 0 && elapsed() > params.time_limit_s) break;
    const double inputs = static_cast<double>(domain.points.size());
    const double extra = static_cast<double>(mesh.n_vertices()) - inputs;
    const double room = static_cast<double>(params.max_vertices) - inputs;
    if (room <= 0) break;
    out.size_field.scale(1.05 * std::sqrt(extra / room));
    out.sampling = {};
    sample_domain_into(mesh, domain, cdt, out.size_field, samp, &out.sampling);
  }
  out.over_budget = params.max_vertices > 0 && mesh.n_vertices() > params.max_vertices;
  if (params.on_sampled) params.on_sampled(mesh.n_vertices(), out.features_decide);
  CvtOptimizeParams op;
  op.lloyd_iterations = params.lloyd_iterations;
  op.lbfgs_iterations = params.lloyd_only_where_features_decide && out.features_decide ? 0 : params.lbfgs_iterations;
  op.move_tolerance = params.move_tolerance;
  op.active_move = params.active_move;
  op.predict_settled = params.predict_settled;
  if (params.time_limit_s > 0) {
    const double left = params.time_limit_s - elapsed();
    if (left <= 0) {
      op.lloyd_iterations = op.lbfgs_iterations = 0;
      out.out_of_time = true;
    }
    op.time_limit_s = std::max(left, 1e-9);
  }
  op.observer = params.observer;
  out.optimization = cvt_optimize(mesh, out.size_field, op);
  out.iterations = out.optimization.lloyd_iterations + out.optimization.lbfgs_iterations;
  out.energy = out.optimization.energy;
  out.gradient_norm = out.optimization.gradient_norm;
  if (params.time_limit_s > 0 && !out.optimization.converged && elapsed() > params.time_limit_s) out.out_of_time = true;
}

}  // namespace acute
