#include "repair/polygon_centre.h"

#include <algorithm>
#include <cmath>

namespace acute::exact {

namespace {

/// Keeps the part of a convex polygon where a*x + b*y >= c (Sutherland-Hodgman, one plane).
std::vector<XY> clip(const std::vector<XY>& poly, double a, double b, double c) {
  std::vector<XY> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const XY& p = poly[i];
    const XY& q = poly[(i + 1) % n];
    const double fp = a * p.first + b * p.second - c, fq = a * q.first + b * q.second - c;
    if (fp >= 0) out.push_back(p);
    if ((fp >= 0) != (fq >= 0)) {
      const double t = fp / (fp - fq);
      out.emplace_back(p.first + t * (q.first - p.first), p.second + t * (q.second - p.second));
    }
  }
  return out;
}

}  // namespace

std::vector<XY> polygon_centres(const std::vector<XY>& polygon, std::size_t max_points) {
  std::vector<XY> out;
  if (polygon.size() < 3) return out;
  double x0 = polygon[0].first, x1 = x0, y0 = polygon[0].second, y1 = y0;
  for (const auto& p : polygon) {
    x0 = std::min(x0, p.first), x1 = std::max(x1, p.first);
    y0 = std::min(y0, p.second), y1 = std::max(y1, p.second);
  }
  std::vector<XY> region = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n && !region.empty(); ++i) {
    const XY& p = polygon[i];
    const XY& q = polygon[(i + 1) % n];
    const double dx = q.first - p.first, dy = q.second - p.second;
    region = clip(region, -dy, dx, -dy * p.first + dx * p.second);      // left of pq
    region = clip(region, dx, dy, dx * p.first + dy * p.second);        // beyond the perpendicular at p
    region = clip(region, -dx, -dy, -dx * q.first - dy * q.second);     // before the perpendicular at q
  }
  if (region.size() < 3) return out;
  XY c{0, 0};
  for (const auto& v : region) c.first += v.first, c.second += v.second;
  c.first /= static_cast<double>(region.size());
  c.second /= static_cast<double>(region.size());
  std::vector<XY> samples = {c};
  for (double w : {0.5, 0.85})
    for (const auto& v : region) samples.emplace_back(c.first + w * (v.first - c.first), c.second + w * (v.second - c.second));
  for (const auto& x : samples) {
    bool ok = true;
    for (std::size_t i = 0; i < n && ok; ++i) {
      const XY& p = polygon[i];
      const XY& q = polygon[(i + 1) % n];
      // Angle at x at most 90: (p - x).(q - x) >= 0, with a margin for the rounding.
      const double d = (p.first - x.first) * (q.first - x.first) + (p.second - x.second) * (q.second - x.second);
      const double scale = std::hypot(q.first - p.first, q.second - p.second);
      ok = d > 1e-9 * scale * scale;
    }
    if (ok) out.push_back(x);
    if (out.size() >= max_points) break;
  }
  return out;
}

}  // namespace acute::exact
