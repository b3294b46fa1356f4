#include <acute/mesh/segments.h>

#include <acute/predicates/predicates.h>

#include <OpenMesh/Core/Utils/Property.hh>

#include <cmath>
#include <limits>

namespace acute {
namespace {
const char* const kSegmentTableName = "acute:segment_table";

// Deviation (distance over length) accepted without searching: 2^-42 ~ 2.3e-13, far below the
// 1e-10 a referee allows and above the rounding of a point of any segment not tiny for its place.
constexpr double kGoodEnough = 0x1p-42;
// Columns (ulps along the segment's dominant axis) tried on each side of the rounded projection:
// kWindow at first, up to kMaxWindow while the best is worse than kAcceptable (2^-36 ~ 1.5e-11).
// The nearest double of a column is off by a uniform fraction of an ulp, so n columns bring the
// best near ulp / (2 n).
constexpr int kWindow = 128;
constexpr int kMaxWindow = 2048;
constexpr double kAcceptable = 0x1p-36;

OpenMesh::MPropHandleT<SegmentTable> table_handle(const Mesh& mesh) {
  OpenMesh::MPropHandleT<SegmentTable> mph;
  mesh.get_property_handle(mph, kSegmentTableName);
  return mph;
}

bool strictly_between(double v, double lo, double hi) { return lo < hi ? (lo < v && v < hi) : (hi < v && v < lo); }

bool in_bracket(const std::array<Point2, 2>& ends, const Point2& p, const Point2* lo, const Point2* hi) {
  return lo == nullptr || hi == nullptr || strictly_between_along(ends, *lo, p, *hi);
}
}  // namespace

void set_segment_table(Mesh& mesh, SegmentTable table) {
  auto mph = table_handle(mesh);
  if (!mph.is_valid()) mesh.add_property(mph, kSegmentTableName);
  mesh.property(mph) = std::move(table);
}

const SegmentTable& segment_table(const Mesh& mesh) {
  static const SegmentTable empty;
  const auto mph = table_handle(mesh);
  return mph.is_valid() ? mesh.property(mph) : empty;
}

const std::array<Point2, 2>& segment_endpoints(const Mesh& mesh, int id) { return segment_table(mesh).at(static_cast<std::size_t>(id)); }

Point2 project_on_segment(const Mesh& mesh, int id, const Point2& p) { return project_on_line(segment_endpoints(mesh, id), p); }

Point2 project_on_line(const std::array<Point2, 2>& ends, const Point2& p, const Point2* lo, const Point2* hi) {
  const auto& [a, b] = ends;
  const Point2 d = b - a;
  const double t = (p - a).dot(d) / d.squaredNorm();
  // Interpolate from the nearer endpoint: keeps points near an end accurate.
  const Point2 q = t <= 0.5 ? Point2(a + t * d) : Point2(b - (1.0 - t) * d);
  return snap_to_line(ends, q, lo, hi);
}

bool strictly_between_along(const std::array<Point2, 2>& ends, const Point2& lo, const Point2& p, const Point2& hi) {
  for (int i = 0; i < 2; ++i)
    if (ends[0][i] != ends[1][i] && !strictly_between(p[i], lo[i], hi[i])) return false;
  return true;
}

double line_deviation(const std::array<Point2, 2>& ends, const Point2& p) {
  const auto& [a, b] = ends;
  return std::fabs(predicates::orient2d_value(a, b, p)) / (b - a).squaredNorm();
}

Point2 snap_to_line(const std::array<Point2, 2>& ends, const Point2& q, const Point2* lo, const Point2* hi) {
  const auto& [a, b] = ends;
  const Point2 d = b - a;
  if (!(d.squaredNorm() > 0) || !std::isfinite(q.x()) || !std::isfinite(q.y())) return q;
  constexpr double inf = std::numeric_limits<double>::infinity();
  Point2 best = q;
  double best_dev = in_bracket(ends, q, lo, hi) ? line_deviation(ends, q) : inf;
  if (best_dev <= kGoodEnough) return q;
  // Walk the dominant axis ulp by ulp; in each column the doubles nearest the exact line are the
  // rounded line ordinate and its two neighbours (the ordinate is computed to about an ulp).
  const int k = std::fabs(d.x()) >= std::fabs(d.y()) ? 0 : 1, j = 1 - k;
  const double slope = d[j] / d[k];
  double up = q[k], down = q[k];
  for (int step = 0; step < kMaxWindow && !(step >= kWindow && best_dev <= kAcceptable); ++step) {
    up = std::nextafter(up, inf);
    down = std::nextafter(down, -inf);
    for (const double xk : {up, down}) {
      const double yj = a[j] + (xk - a[k]) * slope;
      for (const double y : {std::nextafter(yj, -inf), yj, std::nextafter(yj, inf)}) {
        Point2 c;
        c[k] = xk;
        c[j] = y;
        if (!in_bracket(ends, c, lo, hi)) continue;
        const double dev = line_deviation(ends, c);
        if (dev < best_dev) {
          best = c;
          best_dev = dev;
          if (dev <= kGoodEnough) return best;
        }
      }
    }
  }
  return best;
}

}  // namespace acute
