#include "cvt/lattice.h"

#include <acute/mesh/geometry.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace acute::detail {
namespace {

constexpr double kRowHeight = 0.86602540378443864676;  // sqrt(3) / 2
constexpr double kSqrt2 = 1.41421356237309504880;

/// Twice the signed area of abc in floating point: a sampling choice, not a topological decision.
double orient_value(const Point2& a, const Point2& b, const Point2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/// Separating-axis test of two triangles (either orientation); touching counts as overlapping.
bool overlaps(const Point2 (&p)[3], const Point2 (&q)[3]) {
  auto separated_by_edges_of = [](const Point2 (&s)[3], const Point2 (&t)[3]) {
    for (int e = 0; e < 3; ++e) {
      const Point2 d = s[(e + 1) % 3] - s[e];
      const Point2 n(-d.y(), d.x());
      double smin = n.dot(s[0]), smax = smin, tmin = n.dot(t[0]), tmax = tmin;
      for (int k = 1; k < 3; ++k) {
        smin = std::min(smin, n.dot(s[k])), smax = std::max(smax, n.dot(s[k]));
        tmin = std::min(tmin, n.dot(t[k])), tmax = std::max(tmax, n.dot(t[k]));
      }
      if (smax < tmin || tmax < smin) return true;
    }
    return false;
  };
  return !separated_by_edges_of(p, q) && !separated_by_edges_of(q, p);
}

/// The point of triangle p nearest to c (c itself when inside). A cell that overlaps the triangle
/// near a small feature may have its centroid outside the domain, where the size field holds no
/// meaning (a clamped walk gives some far triangle's value): a tiny notch on a long wall then never
/// got its fine cells. Inside the domain the field is graded, so the nearest point speaks for the cell.
Point2 nearest_in_triangle(const Point2 (&p)[3], const Point2& c) {
  const double s0 = orient_value(p[0], p[1], c), s1 = orient_value(p[1], p[2], c), s2 = orient_value(p[2], p[0], c);
  const bool ccw = orient_value(p[0], p[1], p[2]) >= 0;
  if (ccw ? (s0 >= 0 && s1 >= 0 && s2 >= 0) : (s0 <= 0 && s1 <= 0 && s2 <= 0)) return c;
  Point2 best = nearest_on_segment(c, p[0], p[1]);
  for (int e = 1; e < 3; ++e) {
    const Point2 q = nearest_on_segment(c, p[e], p[(e + 1) % 3]);
    if ((q - c).squaredNorm() < (best - c).squaredNorm()) best = q;
  }
  return best;
}

}  // namespace

NestedLattice::NestedLattice(const SizeField& field, const Point2& lo, const Point2& hi, unsigned seed) : field_(field) {
  const double hmax = field.max_value(), hmin = std::max(field.min_value(), hmax * 1e-9);
  const Point2 extent = hi - lo;
  // Top level: at most about 4096 cells over the box.
  int up = 0;
  double top = hmax;
  while (up < 40 && extent.x() * extent.y() / (top * top * kRowHeight) > 2048.0) top *= 2, ++up;
  // Finest level: within sqrt(2) of the smallest h; at most 2^44 units across the box.
  int down = 0;
  fine_ = hmax;
  while (down < 40 && fine_ > hmin * kSqrt2 && up + down < 44) fine_ *= 0.5, ++down;
  top_ = up + down;
  // Off the box by a random part of a cell, so that lattice rows do not run along the domain's
  // own axis-parallel edges.
  std::mt19937 rng(seed);
  const double fx = (static_cast<double>(rng()) + 0.5) / 4294967296.0, fy = (static_cast<double>(rng()) + 0.5) / 4294967296.0;
  origin_ = lo - Point2(top, top) + fine_ * Point2(fx, fy * kRowHeight);
}

void NestedLattice::sort_unique_keys() {
  // Every lattice point comes once per leaf triangle around it (up to six times): sorted and
  // deduplicated in lexicographic order. Where the keys span less than 2^32 in each coordinate
  // (always but for absurd gradings) they are packed in 64-bit words, in the same order; many keys
  // then go through a radix sort, 16 bits a pass, skipping the passes whose digit never varies:
  // several times faster than std::sort.
  if (keys_.empty()) return;
  Key lo = keys_.front(), hi = lo;
  for (const Key& k : keys_)
    for (int c = 0; c < 2; ++c) lo[c] = std::min(lo[c], k[c]), hi[c] = std::max(hi[c], k[c]);
  constexpr std::int64_t kSpan = std::int64_t{1} << 32;
  // Each radix pass clears and sums 2^16 counters: worth it for large triangles only (a domain's
  // CDT has thousands of small ones, each with a handful of keys).
  constexpr std::size_t kRadixFrom = std::size_t{1} << 15;
  if (hi[0] - lo[0] >= kSpan || hi[1] - lo[1] >= kSpan) {
    std::sort(keys_.begin(), keys_.end());
    keys_.erase(std::unique(keys_.begin(), keys_.end()), keys_.end());
    return;
  }
  packed_.resize(keys_.size());
  for (std::size_t i = 0; i < keys_.size(); ++i)
    packed_[i] = (static_cast<std::uint64_t>(keys_[i][0] - lo[0]) << 32) | static_cast<std::uint64_t>(keys_[i][1] - lo[1]);
  if (keys_.size() < kRadixFrom) {
    std::sort(packed_.begin(), packed_.end());  // one word a key: cheaper to compare than two
  } else {
    radix_sort_packed();
  }
  packed_.erase(std::unique(packed_.begin(), packed_.end()), packed_.end());
  keys_.resize(packed_.size());
  for (std::size_t i = 0; i < packed_.size(); ++i)
    keys_[i] = {lo[0] + static_cast<std::int64_t>(packed_[i] >> 32), lo[1] + static_cast<std::int64_t>(packed_[i] & 0xFFFFFFFFu)};
}

void NestedLattice::radix_sort_packed() {
  std::uint64_t varying = 0;
  for (std::uint64_t w : packed_) varying |= w ^ packed_.front();
  scratch_.resize(packed_.size());
  counts_.resize(std::size_t{1} << 16);
  for (int shift = 0; shift < 64; shift += 16) {
    if (((varying >> shift) & 0xFFFF) == 0) continue;
    std::fill(counts_.begin(), counts_.end(), 0);
    for (std::uint64_t w : packed_) ++counts_[(w >> shift) & 0xFFFF];
    std::size_t sum = 0;
    for (auto& c : counts_) {
      const std::size_t n = c;
      c = sum;
      sum += n;
    }
    for (std::uint64_t w : packed_) scratch_[counts_[(w >> shift) & 0xFFFF]++] = w;
    packed_.swap(scratch_);
  }
}

Point2 NestedLattice::at(const Key& k) const {
  return origin_ + fine_ * Point2(static_cast<double>(k[0]) + 0.5 * static_cast<double>(k[1]), static_cast<double>(k[1]) * kRowHeight);
}

void NestedLattice::points_in_triangle(const Point2& a, const Point2& b, const Point2& c, int& hint, std::vector<Point2>& out) {
  const Point2 tri[3] = {a, b, c};
  const std::int64_t unit = std::int64_t{1} << top_;
  const double top = fine_ * static_cast<double>(unit), row = top * kRowHeight;
  stack_.clear();
  keys_.clear();
  // The top cells meeting the triangle, row by row: the triangle's x-range within each band.
  const double ymin = std::min({a.y(), b.y(), c.y()}), ymax = std::max({a.y(), b.y(), c.y()});
  const auto j0 = static_cast<std::int64_t>(std::floor((ymin - origin_.y()) / row));
  const auto j1 = static_cast<std::int64_t>(std::floor((ymax - origin_.y()) / row));
  for (std::int64_t j = j0; j <= j1; ++j) {
    const double y0 = origin_.y() + static_cast<double>(j) * row, y1 = y0 + row;
    double xmin = INFINITY, xmax = -INFINITY;
    for (int e = 0; e < 3; ++e) {
      const Point2& p = tri[e];
      const Point2& q = tri[(e + 1) % 3];
      if (p.y() >= y0 && p.y() <= y1) xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
      for (double y : {y0, y1})
        if ((p.y() - y) * (q.y() - y) < 0) {
          const double x = p.x() + (y - p.y()) / (q.y() - p.y()) * (q.x() - p.x());
          xmin = std::min(xmin, x), xmax = std::max(xmax, x);
        }
    }
    if (!(xmin <= xmax)) continue;
    const double shift = 0.5 * static_cast<double>(j);
    const auto i0 = static_cast<std::int64_t>(std::floor((xmin - origin_.x()) / top - shift)) - 1;
    const auto i1 = static_cast<std::int64_t>(std::floor((xmax - origin_.x()) / top - shift)) + 1;
    for (std::int64_t i = i0; i <= i1; ++i) {
      const Key p00{i * unit, j * unit}, p10{(i + 1) * unit, j * unit}, p01{i * unit, (j + 1) * unit}, p11{(i + 1) * unit, (j + 1) * unit};
      stack_.push_back({{p00, p10, p01}, top_});
      stack_.push_back({{p10, p11, p01}, top_});
    }
  }
  auto mid = [](const Key& p, const Key& q) { return Key{(p[0] + q[0]) / 2, (p[1] + q[1]) / 2}; };
  while (!stack_.empty()) {
    const Cell cell = stack_.back();
    stack_.pop_back();
    const Point2 q[3] = {at(cell.v[0]), at(cell.v[1]), at(cell.v[2])};
    if (!overlaps(tri, q)) continue;
    if (cell.level > 0) {
      const double spacing = fine_ * static_cast<double>(std::int64_t{1} << cell.level);
      if (field_.eval(nearest_in_triangle(tri, (q[0] + q[1] + q[2]) / 3.0), hint) < spacing / kSqrt2) {
        const Key m01 = mid(cell.v[0], cell.v[1]), m12 = mid(cell.v[1], cell.v[2]), m20 = mid(cell.v[2], cell.v[0]);
        const int l = cell.level - 1;
        stack_.push_back({{cell.v[0], m01, m20}, l});
        stack_.push_back({{m01, cell.v[1], m12}, l});
        stack_.push_back({{m20, m12, cell.v[2]}, l});
        stack_.push_back({{m01, m12, m20}, l});
        continue;
      }
    }
    for (int k = 0; k < 3; ++k)
      if (predicates::orient2d(a, b, q[k]) == Sign::Positive && predicates::orient2d(b, c, q[k]) == Sign::Positive &&
          predicates::orient2d(c, a, q[k]) == Sign::Positive)
        keys_.push_back(cell.v[k]);
  }
  sort_unique_keys();
  for (const Key& k : keys_) out.push_back(at(k));
}

}  // namespace acute::detail
