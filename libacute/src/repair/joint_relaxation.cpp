#include <acute/repair/joint_relaxation.h>

#include <acute/mesh/geometry.h>
#include <acute/mesh/segments.h>
#include <acute/ops/relocate.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace acute {

namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

/// The triangles the relaxation looks at, with the local index of each corner (-1: fixed).
struct Patch {
  std::vector<VertexHandle> movable;
  std::vector<Point2> axis;  ///< unit direction of the segment for OnSegment vertices, (0, 0) when free
  std::vector<std::array<Point2, 2>> ends;  ///< that segment's endpoints
  std::vector<std::array<VertexHandle, 3>> faces;
  std::vector<std::array<int, 3>> local;
  std::vector<std::array<bool, 3>> exempt;  ///< min bound dropped at that corner (forced, narrow sector)
};

Patch make_patch(const Mesh& mesh, const std::vector<VertexHandle>& vertices, const std::vector<bool>& forced, double min_deg, bool movable_only) {
  Patch patch;
  std::unordered_map<int, int> index;
  for (auto vh : vertices) {
    if (mesh.status(vh).deleted() || index.count(vh.idx())) continue;
    const auto& d = mesh.data(vh);
    Point2 axis(0, 0);
    std::array<Point2, 2> ends{};
    if (closes_strip_apex(mesh, vh, forced, min_deg)) continue;  // fixed: see angle_bounds.h
    if (d.kind == VertexKind::Input) {
      if (movable_only) continue;
    } else if (d.kind == VertexKind::OnSegment) {
      if (d.segment < 0 || static_cast<std::size_t>(d.segment) >= segment_table(mesh).size()) {
        if (movable_only) continue;
      } else {
        ends = segment_endpoints(mesh, d.segment);
        axis = (ends[1] - ends[0]).normalized();
      }
    } else if (movable_only) {
      // A free vertex on the border would move the domain's boundary (as can_relocate refuses).
      bool border = false;
      for (auto heh : mesh.voh_range(vh)) border = border || mesh.is_boundary(heh);
      if (border) continue;
    }
    index.emplace(vh.idx(), static_cast<int>(patch.movable.size()));
    patch.movable.push_back(vh);
    patch.axis.push_back(axis);
    patch.ends.push_back(ends);
  }
  std::vector<FaceHandle> faces;
  for (auto vh : patch.movable)
    for (auto fh : mesh.vf_range(vh)) faces.push_back(fh);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  for (auto fh : faces) {
    std::array<VertexHandle, 3> v;
    std::array<int, 3> l;
    std::array<bool, 3> exempt{};
    int k = 0;
    for (auto vh : mesh.fv_range(fh)) {
      v[k] = vh;
      const auto it = index.find(vh.idx());
      l[k] = it == index.end() ? -1 : it->second;
      exempt[k] = min_exempt_corner(mesh, vh, fh, min_deg, forced);
      ++k;
    }
    patch.faces.push_back(v);
    patch.local.push_back(l);
    patch.exempt.push_back(exempt);
  }
  return patch;
}

/// Energy of the patch's triangles at the current positions; adds dE/dx to grad when given.
double patch_energy(const Mesh& mesh, const Patch& patch, const AngleBounds& bounds, double tau, std::vector<Point2>* grad) {
  if (grad) std::fill(grad->begin(), grad->end(), Point2(0, 0));
  double energy = 0;
  // exp((min - theta) / tau) = exp((min - max) / tau) / exp((theta - max) / tau): one exponential an
  // angle (theta - max lies in [-180, 0] degrees, so neither factor under- or overflows).
  const double lo_over_hi = std::exp((bounds.min_deg - bounds.max_deg) / tau);
  for (std::size_t f = 0; f < patch.faces.size(); ++f) {
    const auto& v = patch.faces[f];
    const Point2 p[3] = {point2(mesh, v[0]), point2(mesh, v[1]), point2(mesh, v[2])};
    for (int k = 0; k < 3; ++k) {
      const Point2& a = p[k];
      const Point2 u = p[(k + 1) % 3] - a, w = p[(k + 2) % 3] - a;
      const double theta = approx_angle_deg(a, p[(k + 1) % 3], p[(k + 2) % 3]);
      const double hi = std::exp((theta - bounds.max_deg) / tau);
      const double lo = patch.exempt[f][static_cast<std::size_t>(k)] ? 0.0
                        : lo_over_hi > 1e-200 && hi > 1e-200 ? lo_over_hi / hi  // (a tiny tau: both exponentials)
                                                             : std::exp((bounds.min_deg - theta) / tau);
      energy += hi + lo;
      if (!grad) continue;
      const double de = (hi - lo) / tau * kDeg;  // dE / dtheta (theta in radians)
      const double uu = u.squaredNorm(), ww = w.squaredNorm();
      if (!(uu > 0) || !(ww > 0)) continue;
      // For a counter-clockwise triangle theta = arg(w) - arg(u).
      const Point2 d_b(u.y() / uu, -u.x() / uu), d_c(-w.y() / ww, w.x() / ww);
      const int lb = patch.local[f][(k + 1) % 3], lc = patch.local[f][(k + 2) % 3], la = patch.local[f][k];
      if (lb >= 0) (*grad)[static_cast<std::size_t>(lb)] += de * d_b;
      if (lc >= 0) (*grad)[static_cast<std::size_t>(lc)] += de * d_c;
      if (la >= 0) (*grad)[static_cast<std::size_t>(la)] -= de * (d_b + d_c);
    }
  }
  return energy;
}

bool patch_valid(const Mesh& mesh, const Patch& patch) {
  for (const auto& v : patch.faces)
    if (predicates::orient2d(point2(mesh, v[0]), point2(mesh, v[1]), point2(mesh, v[2])) != Sign::Positive) return false;
  // Segment chains stay monotone and near their lines (else they no longer read back as the segment).
  for (std::size_t i = 0; i < patch.movable.size(); ++i)
    if (patch.axis[i] != Point2(0, 0) && (!keeps_segment_order(mesh, patch.movable[i], point2(mesh, patch.movable[i])) ||
                                          !close_enough_to_line(patch.ends[i], point2(mesh, patch.movable[i]))))
      return false;
  return true;
}

}  // namespace

double joint_energy(const Mesh& mesh, const std::vector<VertexHandle>& vertices, const AngleBounds& bounds,
                    const std::vector<bool>& forced, double tau_deg) {
  const Patch patch = make_patch(mesh, vertices, forced, bounds.min_deg, false);
  return patch_energy(mesh, patch, bounds, tau_deg, nullptr);
}

bool relax_jointly(Mesh& mesh, const std::vector<VertexHandle>& vertices, const AngleBounds& bounds,
                   const std::vector<bool>& forced, const JointRelaxParams& params) {
  Patch patch = make_patch(mesh, vertices, forced, bounds.min_deg, true);
  const std::size_t n = patch.movable.size();
  if (n == 0) return false;
  // Length scale: the shortest edge at a movable vertex bounds the first step.
  double scale = INFINITY;
  for (auto vh : patch.movable)
    for (auto heh : mesh.voh_range(vh)) scale = std::min(scale, (point2(mesh, mesh.to_vertex_handle(heh)) - point2(mesh, vh)).norm());
  if (!(scale > 0) || !std::isfinite(scale)) return false;

  std::vector<Point2> grad(n), trial_grad(n), start(n), trial(n);
  for (std::size_t i = 0; i < n; ++i) start[i] = point2(mesh, patch.movable[i]);
  std::vector<Point2> current = start;
  double energy = patch_energy(mesh, patch, bounds, params.tau_deg, &grad);
  double step = 0.05 * scale;  // largest displacement of a trial step
  bool moved = false;
  for (int it = 0; it < params.iterations && step > 1e-7 * scale; ++it) {
    double gmax = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (patch.axis[i] != Point2(0, 0)) grad[i] = grad[i].dot(patch.axis[i]) * patch.axis[i];
      gmax = std::max(gmax, grad[i].norm());
    }
    if (!(gmax > 0) || !std::isfinite(gmax)) break;
    bool accepted = false;
    while (step > 1e-7 * scale) {
      for (std::size_t i = 0; i < n; ++i) {
        Point2 q = current[i] - (step / gmax) * grad[i];
        if (patch.axis[i] != Point2(0, 0)) q = project_on_line(patch.ends[i], q);
        trial[i] = q;
        set_point2(mesh, patch.movable[i], q);
      }
      // With its gradient: an accepted trial needs it next, and most trials are accepted.
      const double e = patch_valid(mesh, patch) ? patch_energy(mesh, patch, bounds, params.tau_deg, &trial_grad) : INFINITY;
      if (e < energy * (1 - 1e-12)) {
        current.swap(trial);
        grad.swap(trial_grad);
        energy = e;
        step *= 1.5;
        accepted = moved = true;
        break;
      }
      for (std::size_t i = 0; i < n; ++i) set_point2(mesh, patch.movable[i], current[i]);
      step *= 0.5;
    }
    if (!accepted) break;
  }
  for (std::size_t i = 0; i < n; ++i) set_point2(mesh, patch.movable[i], current[i]);
  return moved;
}

}  // namespace acute
