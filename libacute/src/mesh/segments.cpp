#include <acute/mesh/segments.h>

#include <acute/predicates/predicates.h>

#include "mesh/modular_search.h"

#include <OpenMesh/Core/Utils/Property.hh>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <numeric>
#include <optional>
#include <vector>
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
constexpr int kMaxWindow = 4096;
constexpr double kAcceptable = 0x1p-36;

// Held by shared pointer: a mesh copy (the repair copies regions and candidates many times) shares
// the table instead of copying every segment. The table is never changed in place.
using SharedTable = std::shared_ptr<const SegmentTable>;

OpenMesh::MPropHandleT<SharedTable> table_handle(const Mesh& mesh) {
  OpenMesh::MPropHandleT<SharedTable> mph;
  mesh.get_property_handle(mph, kSegmentTableName);
  return mph;
}

bool strictly_between(double v, double lo, double hi) { return lo < hi ? (lo < v && v < hi) : (hi < v && v < lo); }
bool weakly_between(double v, double lo, double hi) { return lo <= hi ? (lo <= v && v <= hi) : (hi <= v && v <= lo); }

bool in_bracket(const std::array<Point2, 2>& ends, const Point2& p, const Point2* lo, const Point2* hi) {
  return lo == nullptr || hi == nullptr || strictly_between_along(ends, *lo, p, *hi);
}

#ifdef __SIZEOF_INT128__
__extension__ typedef __int128 i128;

/// The unit in the last place of x (x finite, nonzero).
double ulp_of(double x) { return std::nextafter(std::fabs(x), std::numeric_limits<double>::infinity()) - std::fabs(x); }

/// x / u as an integer when x is a multiple of u that fits comfortably in 62 bits.
bool grid_index(double x, double u, std::int64_t& out) {
  const double t = x / u;  // u is a power of two: exact
  if (!(std::fabs(t) < 0x1p62) || t != std::floor(t)) return false;
  out = static_cast<std::int64_t>(t);
  return true;
}

/// When both ends lie in one binade per axis, every double between them is a lattice point
/// a + (m u_k, n u_j); its distance from the line is |m D_j - n D_k| u_k u_j / |ab| for the ends'
/// integer offsets D. The lattice points with residue r = m D_j' - n D_k' (D' = D / gcd) recur
/// every |D_k'| columns, so the nearest to the line inside the bracket are found by residue,
/// within 1/64 of the segment from q: nice slopes (exactly 1/2 on the grid) have exact points,
/// others the best there. `most_exact_in_reach` is set when the point is what the walk of
/// snap_to_line would find at best (its columns searched exactly), so the walk can be skipped.
/// Returns false when the method does not apply or nothing within kMaxSegmentDeviation fits.
bool lattice_snap(const std::array<Point2, 2>& ends, const Point2& q, int k, const Point2* lo, const Point2* hi, Point2& out,
                  bool* most_exact_in_reach) {
  if (most_exact_in_reach) *most_exact_in_reach = false;
  const auto& [a, b] = ends;
  const int j = 1 - k;
  if (a[k] == 0 || b[k] == 0 || a[j] == 0 || b[j] == 0) return false;
  const double uk = ulp_of(a[k]), uj = ulp_of(a[j]);
  if (ulp_of(b[k]) != uk || ulp_of(b[j]) != uj || (a[k] < 0) != (b[k] < 0) || (a[j] < 0) != (b[j] < 0)) return false;
  std::int64_t ak, bk, aj, bj, qk;
  if (!grid_index(a[k], uk, ak) || !grid_index(b[k], uk, bk) || !grid_index(a[j], uj, aj) || !grid_index(b[j], uj, bj)) return false;
  if (!grid_index(std::round((q[k] - a[k]) / uk) * uk, uk, qk)) return false;  // target column offset
  std::int64_t dk = bk - ak, dj = bj - aj;
  if (dk == 0) return false;
  std::int64_t g = std::gcd(dk < 0 ? -dk : dk, dj < 0 ? -dj : dj);
  const std::int64_t dk1 = dk / g, dj1 = dj / g, period = dk1 < 0 ? -dk1 : dk1;
  const double len2 = (b - a).squaredNorm();
  // Largest |r| whose deviation g |r| uk uj / len2 stays within kMaxSegmentDeviation.
  const double r_cap = std::floor(kMaxSegmentDeviation * len2 / (uk * uj * static_cast<double>(g)));
  // Stay near q: within 1/64 of the segment (or kWindow columns), as the window search does.
  const i128 reach = std::max<i128>(kWindow, static_cast<i128>(dk < 0 ? -dk : dk) / 64);
  // Columns in reach, and strictly inside the bracket where it lies on the same grid (a split
  // near a corner: most columns in reach are outside the edge being split).
  i128 m_lo_bracket = -(static_cast<i128>(1) << 100), m_hi_bracket = static_cast<i128>(1) << 100;
  std::int64_t il = 0, ih = 0;
  if (lo != nullptr && hi != nullptr && grid_index((*lo)[k], uk, il) && grid_index((*hi)[k], uk, ih)) {
    if (il > ih) std::swap(il, ih);
    m_lo_bracket = static_cast<i128>(il) - ak + 1;
    m_hi_bracket = static_cast<i128>(ih) - ak - 1;
  }
  const i128 m_lo = std::max<i128>(qk - reach, m_lo_bracket), m_hi = std::min<i128>(qk + reach, m_hi_bracket);
  if (m_lo > m_hi) return false;
  // The lattice point of column offset m (from a) whose line offset is res, if it qualifies.
  auto accept = [&](i128 m, std::int64_t res) {
    if (m < m_lo || m > m_hi) return false;
    const i128 num = m * dj1 - res;  // == n dk1
    if (num % dk1 != 0) return false;  // cannot happen; guards the arithmetic
    const i128 n = num / dk1;
    const i128 ck = static_cast<i128>(ak) + m, cj = static_cast<i128>(aj) + n;
    if (ck > (static_cast<i128>(1) << 62) || ck < -(static_cast<i128>(1) << 62) || cj > (static_cast<i128>(1) << 62) || cj < -(static_cast<i128>(1) << 62)) return false;
    Point2 c;
    c[k] = static_cast<double>(static_cast<std::int64_t>(ck)) * uk;  // an integer below 2^53 in practice: exact
    c[j] = static_cast<double>(static_cast<std::int64_t>(cj)) * uj;
    if (ulp_of(c[k]) != uk || ulp_of(c[j]) != uj) return false;  // left the binade: not the lattice point
    if (!in_bracket(ends, c, lo, hi) || line_deviation(ends, c) > kMaxSegmentDeviation) return false;
    out = c;
    return true;
  };
  // The lattice points of columns [from, to] whose line offset is at most r_limit: the most exact
  // first, then the nearest to q. The offsets step by dj1 from column to column (modulo period).
  auto try_columns = [&](i128 from, i128 to, std::int64_t r_limit) {
    using Column = std::pair<std::int64_t, std::int64_t>;  // (rank of |res|, m)
    const auto before = [&](const Column& x, const Column& y) {
      if (x.first != y.first) return x.first < y.first;
      const std::int64_t dx = x.second > qk ? x.second - qk : qk - x.second, dy = y.second > qk ? y.second - qk : qk - y.second;
      return dx != dy ? dx < dy : x.second < y.second;
    };
    const std::int64_t step = period == 1 ? 0 : static_cast<std::int64_t>(((static_cast<i128>(dj1) % period) + period) % period);
    const std::int64_t res_from = period == 1 ? 0 : static_cast<std::int64_t>(((from * dj1) % period + period) % period);  // in [0, period)
    auto for_each_column = [&](auto&& visit) {
      std::int64_t res0 = res_from;
      for (auto m = static_cast<std::int64_t>(from); m <= static_cast<std::int64_t>(to); ++m) {
        const std::int64_t res = 2 * res0 > period ? res0 - period : res0;
        const std::int64_t mag = res < 0 ? -res : res;
        if (mag <= r_limit) visit(Column{2 * mag + (res < 0), m});  // as the offset loop: r before -r
        res0 += step;
        if (res0 >= period) res0 -= period;
      }
    };
    auto accept_column = [&](const Column& c) { return accept(c.second, (c.first & 1) ? -(c.first / 2) : c.first / 2); };
    // The first in that order is accepted nearly always: found in one pass, without sorting. (Far
    // from the origin, a short segment at 1e6 where no double lies within kGoodEnough of it, every
    // snap searches: sorting the 257 columns each time made such a domain ten times slower to
    // repair than the same one at the origin.)
    std::optional<Column> first;
    for_each_column([&](const Column& c) {
      if (!first || before(c, *first)) first = c;
    });
    if (!first) return false;
    if (accept_column(*first)) return true;
    thread_local std::vector<Column> columns;
    columns.clear();
    for_each_column([&](const Column& c) { columns.push_back(c); });
    std::sort(columns.begin(), columns.end(), before);
    for (const Column& c : columns)
      if (c != *first && accept_column(c)) return true;
    return false;
  };
  // Near q first: within kWindow columns, a point within kAcceptable (as the window walk would
  // find). The most exact point of the whole reach can be 1/64 of the segment away: a split there
  // once landed back on the vertex it replaced (a strip's apex triangle never made isosceles).
  const double r_ok = std::floor(kAcceptable * len2 / (uk * uj * static_cast<double>(g)));
  if (try_columns(std::max<i128>(m_lo, static_cast<i128>(qk) - kWindow), std::min<i128>(m_hi, static_cast<i128>(qk) + kWindow),
                               static_cast<std::int64_t>(std::min(r_ok, 0x1p62))))
    return true;
  // Beyond the first window, as the walk in snap_to_line would go but exactly: the column nearest
  // q within kMaxWindow whose point is within kAcceptable, else the most exact of those columns,
  // else the most exact of the whole reach (anything within kMaxSegmentDeviation), each nearest q
  // among equals. Column m's line offset is (m dj1) mod period, centred; the columns with
  // |offset| <= t, read from a start column outwards, are the first hits of two intervals
  // (detail::first_hit), so the least t a span attains takes a binary search of O(log) steps. (A scan of
  // offsets 0, 1, 2, ... gave up at 65,536 and left it to the walk: on a slope near a small
  // fraction, 13 / 8 at (1e6, -3e6), the offsets drift by a few every 8 columns, the near ones lie
  // millions of columns away, and every such snap walked 4,096 columns.)
  const i128 P = period, A = ((static_cast<i128>(dj1) % P) + P) % P;
  auto offset0 = [&](i128 m) { return (((m % P) + P) % P) * A % P; };  // in [0, P)
  // Columns from `start` on (or back) to the first with |offset| <= t: their count, -1 for none.
  auto distance_to_hit = [&](i128 start, bool forward, i128 t) -> i128 {
    if (2 * t + 1 >= P) return 0;
    const auto p = static_cast<std::int64_t>(P), tt = static_cast<std::int64_t>(t);
    const auto step = static_cast<std::int64_t>(forward ? A : (P - A) % P), b0 = static_cast<std::int64_t>(offset0(start));
    i128 x = detail::first_hit(step, b0, p, 0, tt);
    if (t > 0) {
      const i128 y = detail::first_hit(step, b0, p, p - tt, p - 1);
      if (y >= 0 && (x < 0 || y < x)) x = y;
    }
    return x;
  };
  auto attains = [&](i128 c_lo, i128 c_hi, i128 t) {
    const i128 x = distance_to_hit(c_lo, true, t);
    return x >= 0 && x <= c_hi - c_lo;
  };
  const i128 t_cap = std::min<i128>(P / 2, static_cast<i128>(std::min(r_cap, 0x1p62)));
  // The least t <= t_cap some column of [c_lo, c_hi] attains; -1 for none.
  auto least_offset = [&](i128 c_lo, i128 c_hi) -> i128 {
    if (c_lo > c_hi || !attains(c_lo, c_hi, t_cap)) return -1;
    i128 t_lo = -1, t_hi = t_cap;  // attains(t_lo) false, attains(t_hi) true
    while (t_hi - t_lo > 1) {
      const i128 mid = t_lo + (t_hi - t_lo) / 2;
      (attains(c_lo, c_hi, mid) ? t_hi : t_lo) = mid;
    }
    return t_hi;
  };
  // The columns of [c_lo, c_hi] nearest q on either side with |offset| <= t, the nearer first
  // (ties: the left), offered to accept.
  auto nearest_within = [&](i128 c_lo, i128 c_hi, i128 t) {
    if (t < 0 || c_lo > c_hi) return false;
    const i128 from_right = std::max<i128>(qk, c_lo), from_left = std::min<i128>(qk, c_hi);
    const i128 xr = distance_to_hit(from_right, true, t), xl = distance_to_hit(from_left, false, t);
    i128 columns[2];
    int n = 0;
    if (xl >= 0 && from_left - xl >= c_lo) columns[n++] = from_left - xl;
    if (xr >= 0 && from_right + xr <= c_hi) columns[n++] = from_right + xr;
    if (n == 2 && columns[1] - qk < qk - columns[0]) std::swap(columns[0], columns[1]);
    for (int c = 0; c < n; ++c) {
      const i128 r0 = offset0(columns[c]);
      if (accept(columns[c], static_cast<std::int64_t>(2 * r0 > P ? r0 - P : r0))) return true;
    }
    return false;
  };
  // The walk's columns: kMaxWindow on either side of q, strictly inside the bracket and the segment.
  const i128 w_lo = std::max<i128>({qk - kMaxWindow, m_lo_bracket, std::min<i128>(0, dk) + 1});
  const i128 w_hi = std::min<i128>({qk + kMaxWindow, m_hi_bracket, std::max<i128>(0, dk) - 1});
  const auto t_ok = static_cast<i128>(std::min(r_ok, 0x1p62));
  if (nearest_within(w_lo, w_hi, std::min(t_ok, t_cap)) || nearest_within(w_lo, w_hi, least_offset(w_lo, w_hi)) ||
      nearest_within(m_lo, m_hi, least_offset(m_lo, m_hi))) {
    if (most_exact_in_reach) *most_exact_in_reach = true;
    return true;
  }
  return false;
}
#endif
}  // namespace

void set_segment_table(Mesh& mesh, SegmentTable table) {
  auto mph = table_handle(mesh);
  if (!mph.is_valid()) mesh.add_property(mph, kSegmentTableName);
  mesh.property(mph) = std::make_shared<const SegmentTable>(std::move(table));
}

void share_segment_table(Mesh& to, const Mesh& from) {
  const auto from_mph = table_handle(from);
  if (!from_mph.is_valid()) {
    set_segment_table(to, SegmentTable{});
    return;
  }
  auto mph = table_handle(to);
  if (!mph.is_valid()) to.add_property(mph, kSegmentTableName);
  to.property(mph) = from.property(from_mph);
}

const SegmentTable& segment_table(const Mesh& mesh) {
  static const SegmentTable empty;
  const auto mph = table_handle(mesh);
  return mph.is_valid() && mesh.property(mph) ? *mesh.property(mph) : empty;
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

bool advances_strictly(const Point2& direction, int axis) {
  if (direction[axis] == 0) return false;
  return axis == 0 || std::fabs(direction.y()) >= std::fabs(direction.x());
}

namespace {

/// The position of x in the order of the doubles (x finite): consecutive doubles differ by one.
std::int64_t double_ordinal(double x) {
  std::int64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
}

}  // namespace

std::uint64_t chain_capacity(const Point2& a, const Point2& b) {
  const Point2 d = b - a;
  std::uint64_t capacity = std::numeric_limits<std::uint64_t>::max();
  for (int i = 0; i < 2; ++i) {
    if (!advances_strictly(d, i)) continue;
    const std::int64_t oa = double_ordinal(a[i]), ob = double_ordinal(b[i]);
    const std::uint64_t between = (oa < ob ? static_cast<std::uint64_t>(ob) - static_cast<std::uint64_t>(oa)
                                           : static_cast<std::uint64_t>(oa) - static_cast<std::uint64_t>(ob)) - 1;
    capacity = std::min(capacity, between);
  }
  return capacity;
}

namespace {

/// Coordinate i of p between lo's and hi's in a chain of this direction's order.
bool coordinate_in_order(const Point2& direction, int i, const Point2& lo, const Point2& p, const Point2& hi) {
  return advances_strictly(direction, i) ? strictly_between(p[i], lo[i], hi[i]) : weakly_between(p[i], lo[i], hi[i]);
}

}  // namespace

bool in_chain_order(const Point2& direction, const Point2& lo, const Point2& p, const Point2& hi) {
  for (int i = 0; i < 2; ++i)
    if (lo[i] == hi[i] ? p[i] != lo[i] : !coordinate_in_order(direction, i, lo, p, hi)) return false;
  return true;
}

bool strictly_between_along(const std::array<Point2, 2>& ends, const Point2& lo, const Point2& p, const Point2& hi) {
  const Point2 d = ends[1] - ends[0];
  for (int i = 0; i < 2; ++i)
    if (d[i] != 0 && !coordinate_in_order(d, i, lo, p, hi)) return false;
  return true;
}

double line_deviation(const std::array<Point2, 2>& ends, const Point2& p) {
  const auto& [a, b] = ends;
  return std::fabs(predicates::orient2d_value(a, b, p)) / (b - a).squaredNorm();
}

namespace {

/// Whether line_deviation(ends, p) <= limit, decided from the filtered determinant alone (almost
/// always: a relocation asks this of every trial point on a segment); empty when its error bound
/// leaves it open, for the caller's exact test.
std::optional<bool> deviation_within(const std::array<Point2, 2>& ends, const Point2& p, double limit) {
  const auto& [a, b] = ends;
  double error = 0;
  const double value = std::fabs(predicates::orient2d_estimate(a, b, p, error));
  const double len2 = (b - a).squaredNorm();
  constexpr double kSlack = 1 + 0x1p-48;  // covers the roundings of the sums and quotients below
  if ((value + error) * kSlack / len2 <= limit) return true;
  if ((value - error) / (len2 * kSlack) > limit * kSlack) return false;
  return std::nullopt;
}

}  // namespace

bool close_enough_to_line(const std::array<Point2, 2>& ends, const Point2& p) {
  if (const auto decided = deviation_within(ends, p, kMaxSegmentDeviation)) return *decided;
  return line_deviation(ends, p) <= kMaxSegmentDeviation;
}

Point2 snap_to_line(const std::array<Point2, 2>& ends, const Point2& q, const Point2* lo, const Point2* hi) {
  const auto& [a, b] = ends;
  const Point2 d = b - a;
  if (!(d.squaredNorm() > 0) || !std::isfinite(q.x()) || !std::isfinite(q.y())) return q;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const bool q_in_bracket = in_bracket(ends, q, lo, hi);
  if (q_in_bracket && deviation_within(ends, q, kGoodEnough) == true) return q;  // else the exact test below
  Point2 best = q;
  double best_dev = q_in_bracket ? line_deviation(ends, q) : inf;
  if (best_dev <= kGoodEnough) return q;
  const int k = std::fabs(d.x()) >= std::fabs(d.y()) ? 0 : 1, j = 1 - k;
#ifdef __SIZEOF_INT128__
  Point2 lattice;
  bool most_exact = false;  // nothing in the walk's columns is nearer the line
  if (lattice_snap(ends, q, k, lo, hi, lattice, &most_exact)) {
    const double dev = line_deviation(ends, lattice);
    if (dev < best_dev) best = lattice, best_dev = dev;
    if (best_dev <= kAcceptable || most_exact) return best;
  }
#endif
  // Walk the dominant axis ulp by ulp; in each column the doubles nearest the exact line are the
  // rounded line ordinate and its two neighbours (the ordinate is computed to about an ulp).
  const double slope = d[j] / d[k];
  const double len2 = d.squaredNorm();
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
        // Most candidates are no nearer than the best: the filtered determinant shows it without
        // the exact one (the walk runs all 4,096 columns when no double is within kAcceptable,
        // as on a short segment far from the origin: most of A.poly's time at 1e6).
        double error = 0;
        const double estimate = std::fabs(predicates::orient2d_estimate(a, b, c, error));
        if (estimate - error > best_dev * len2 * (1 + 0x1p-48)) continue;
        const double dev = line_deviation(ends, c);
        if (dev < best_dev) {
          best = c;
          best_dev = dev;
          if (dev <= kGoodEnough) return best;
        }
      }
    }
  }
  if (best_dev <= kMaxSegmentDeviation || lo == nullptr || hi == nullptr) return best;
  // Nothing near the line's own doubles fits the bracket: on a wall a few doubles wide in its
  // minor coordinate (1e-15 out of plumb), the line's x near q is the bracket's, and the walk above
  // finds only x values the chain has used. Any x of the bracket is as near the line there (a few
  // doubles, far within kMaxSegmentDeviation of its length): q with each coordinate that must
  // advance moved into the bracket (its double next to the nearer end), so a chain's few points go
  // where they are needed.
  Point2 c = q;
  for (int i = 0; i < 2; ++i) {
    const double from = (*lo)[i], to = (*hi)[i];
    if (from == to) {
      c[i] = from;
    } else if (!strictly_between(c[i], from, to)) {
      // The bracket's double nearest q: next to the end q is beyond, else next to the start.
      const bool past_to = from < to ? c[i] >= to : c[i] <= to;
      c[i] = past_to ? std::nextafter(to, from) : std::nextafter(from, to);
    }
  }
  if (in_bracket(ends, c, lo, hi) && close_enough_to_line(ends, c)) return c;
  return best;
}

}  // namespace acute
