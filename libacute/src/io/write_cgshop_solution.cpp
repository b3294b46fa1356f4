#include <acute/io/cgshop_solution.h>

#include "io/atomic_file.h"

#include <acute/core/errors.h>
#include <acute/mesh/segments.h>
#include <acute/predicates/predicates.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <utility>

namespace acute::io {

namespace {

/// Decimal text of m * 2^k (m, k >= 0) with base-1e9 limbs, least significant first.
std::string shifted_decimal(std::uint64_t m, int k) {
  constexpr std::uint64_t kBase = 1'000'000'000;
  std::vector<std::uint64_t> limbs;
  for (std::uint64_t v = m; v > 0; v /= kBase) limbs.push_back(v % kBase);
  if (limbs.empty()) return "0";
  while (k > 0) {
    const int step = std::min(k, 29);  // limb * 2^29 + carry fits in 64 bits
    std::uint64_t carry = 0;
    for (auto& limb : limbs) {
      const std::uint64_t v = (limb << step) + carry;
      limb = v % kBase;
      carry = v / kBase;
    }
    while (carry > 0) {
      limbs.push_back(carry % kBase);
      carry /= kBase;
    }
    k -= step;
  }
  std::string out = std::to_string(limbs.back());
  for (std::size_t i = limbs.size() - 1; i-- > 0;) {
    const std::string part = std::to_string(limbs[i]);
    out += std::string(9 - part.size(), '0') + part;
  }
  return out;
}

/// Exact dyadic number mantissa * 2^exponent, the mantissa a sign-magnitude big integer (32-bit
/// limbs, little-endian). Just enough for a + t (b - a) on doubles.
struct Dyadic {
  bool negative = false;
  std::vector<std::uint32_t> mag;
  int exponent = 0;

  static Dyadic of(double x) {
    Dyadic d;
    if (x == 0) return d;
    int e = 0;
    const double f = std::frexp(std::abs(x), &e);
    const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));
    d.negative = x < 0;
    d.mag = {static_cast<std::uint32_t>(m), static_cast<std::uint32_t>(m >> 32)};
    d.exponent = e - 53;
    d.trim();
    return d;
  }
  void trim() {
    while (!mag.empty() && mag.back() == 0) mag.pop_back();
    if (mag.empty()) negative = false, exponent = 0;
  }
  Dyadic shifted_mantissa(int bits) const {  // same value, exponent lowered by bits
    Dyadic r = *this;
    if (mag.empty() || bits == 0) return r;
    r.mag.assign(static_cast<std::size_t>(bits / 32), 0);
    std::uint32_t carry = 0;
    const int rem = bits % 32;
    for (std::uint32_t limb : mag) {
      r.mag.push_back(static_cast<std::uint32_t>((std::uint64_t{limb} << rem) | carry));
      carry = rem ? static_cast<std::uint32_t>(limb >> (32 - rem)) : 0;
    }
    r.mag.push_back(carry);
    r.exponent = exponent - bits;
    r.trim();
    return r;
  }
  static int compare_mag(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
    if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
    for (std::size_t i = a.size(); i-- > 0;)
      if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    return 0;
  }
  friend Dyadic operator+(const Dyadic& x, const Dyadic& y) {
    if (x.mag.empty()) return y;
    if (y.mag.empty()) return x;
    const int e = std::min(x.exponent, y.exponent);
    const Dyadic a = x.shifted_mantissa(x.exponent - e), b = y.shifted_mantissa(y.exponent - e);
    Dyadic r;
    r.exponent = e;
    if (a.negative == b.negative) {
      r.negative = a.negative;
      std::uint64_t carry = 0;
      for (std::size_t i = 0; i < std::max(a.mag.size(), b.mag.size()); ++i) {
        const std::uint64_t v = carry + (i < a.mag.size() ? a.mag[i] : 0) + (i < b.mag.size() ? b.mag[i] : 0);
        r.mag.push_back(static_cast<std::uint32_t>(v));
        carry = v >> 32;
      }
      r.mag.push_back(static_cast<std::uint32_t>(carry));
    } else {
      const bool a_big = compare_mag(a.mag, b.mag) >= 0;
      const Dyadic& big = a_big ? a : b;
      const Dyadic& small = a_big ? b : a;
      r.negative = big.negative;
      std::int64_t borrow = 0;
      for (std::size_t i = 0; i < big.mag.size(); ++i) {
        std::int64_t v = std::int64_t{big.mag[i]} - borrow - (i < small.mag.size() ? std::int64_t{small.mag[i]} : 0);
        borrow = v < 0;
        if (v < 0) v += std::int64_t{1} << 32;
        r.mag.push_back(static_cast<std::uint32_t>(v));
      }
    }
    r.trim();
    return r;
  }
  friend Dyadic operator*(const Dyadic& x, const Dyadic& y) {
    Dyadic r;
    if (x.mag.empty() || y.mag.empty()) return r;
    std::vector<std::uint64_t> acc(x.mag.size() + y.mag.size() + 1, 0);
    for (std::size_t i = 0; i < x.mag.size(); ++i) {
      std::uint64_t carry = 0;
      for (std::size_t j = 0; j < y.mag.size(); ++j) {
        const std::uint64_t v = acc[i + j] + std::uint64_t{x.mag[i]} * y.mag[j] + carry;
        acc[i + j] = v & 0xffffffffu;
        carry = v >> 32;
      }
      acc[i + y.mag.size()] += carry;
    }
    for (auto v : acc) r.mag.push_back(static_cast<std::uint32_t>(v));
    r.negative = x.negative != y.negative;
    r.exponent = x.exponent + y.exponent;
    r.trim();
    return r;
  }
  Dyadic negated() const {
    Dyadic r = *this;
    r.negative = !mag.empty() && !negative;
    return r;
  }
  /// "m" or "m/2^k" in lowest terms, in decimal.
  std::string text() const {
    if (mag.empty()) return "0";
    std::vector<std::uint32_t> m = mag;
    int e = exponent;
    while (e < 0 && (m[0] & 1) == 0) {  // strip factors of two
      for (std::size_t i = 0; i < m.size(); ++i) m[i] = (m[i] >> 1) | (i + 1 < m.size() ? m[i + 1] << 31 : 0);
      ++e;
    }
    std::string digits;  // decimal of m by repeated division by 10^9
    while (!(m.size() == 1 && m[0] == 0) && !m.empty()) {
      std::uint64_t rem = 0;
      for (std::size_t i = m.size(); i-- > 0;) {
        const std::uint64_t cur = (rem << 32) | m[i];
        m[i] = static_cast<std::uint32_t>(cur / 1'000'000'000);
        rem = cur % 1'000'000'000;
      }
      while (m.size() > 1 && m.back() == 0) m.pop_back();
      std::string part = std::to_string(rem);
      const bool last = m.size() == 1 && m[0] == 0;
      if (!last) part = std::string(9 - part.size(), '0') + part;
      digits = part + digits;
    }
    std::string out = negative ? "-" : "";
    if (e >= 0) {
      if (e == 0) return out + digits;
      return out + shifted_decimal_big(digits, e);
    }
    return out + digits + "/" + shifted_decimal(1, -e);
  }
  static std::string shifted_decimal_big(std::string digits, int e) {  // decimal digits * 2^e
    for (; e > 0; --e) {
      int carry = 0;
      for (std::size_t i = digits.size(); i-- > 0;) {
        const int v = (digits[i] - '0') * 2 + carry;
        digits[i] = static_cast<char>('0' + v % 10);
        carry = v / 10;
      }
      if (carry) digits.insert(digits.begin(), static_cast<char>('0' + carry));
    }
    return digits;
  }
};

bool is_json_integer(double x) { return std::floor(x) == x && std::abs(x) < 9007199254740992.0; }

nlohmann::ordered_json coordinate(double x) {
  if (is_json_integer(x)) return static_cast<std::int64_t>(x);
  return exact_rational(x);
}

}  // namespace

std::string exact_rational(double x) {
  if (!std::isfinite(x)) throw InvalidInput("cannot write a non-finite coordinate as a rational");
  if (x == 0) return "0";
  const bool negative = x < 0;
  int e = 0;
  const double f = std::frexp(std::abs(x), &e);  // |x| = f * 2^e, f in [0.5, 1)
  auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));  // exact: 53-bit significand
  e -= 53;
  while ((m & 1) == 0 && e < 0) {
    m >>= 1;
    ++e;
  }
  std::string text = negative ? "-" : "";
  if (e >= 0) return text + shifted_decimal(m, e);
  return text + shifted_decimal(m, 0) + "/" + shifted_decimal(1, -e);
}

std::array<std::string, 2> exact_coordinates(const Mesh& mesh, VertexHandle vh) {
  const Point2 p = point2(mesh, vh);
  const int seg = mesh.data(vh).segment;
  if (mesh.data(vh).kind == VertexKind::OnSegment && seg >= 0 && static_cast<std::size_t>(seg) < segment_table(mesh).size()) {
    const auto& [a, b] = segment_endpoints(mesh, seg);
    if (predicates::orient2d(a, b, p) != Sign::Zero) {
      const Point2 d = b - a;
      const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
      const Dyadic tt = Dyadic::of(t);
      const Dyadic x = Dyadic::of(a.x()) + tt * (Dyadic::of(b.x()) + Dyadic::of(a.x()).negated());
      const Dyadic y = Dyadic::of(a.y()) + tt * (Dyadic::of(b.y()) + Dyadic::of(a.y()).negated());
      return {x.text(), y.text()};
    }
  }
  return {exact_rational(p.x()), exact_rational(p.y())};
}

void write_off_exact(const Mesh& mesh, const std::string& path, const ExactCoordinates* exact_given) {
  std::vector<int> index(mesh.n_vertices(), -1);
  int n = 0;
  for (auto vh : mesh.vertices()) index[vh.idx()] = n++;
  detail::AtomicFile file(path);
  auto& out = file.stream();
  out << "OFF\n" << n << " " << mesh.n_faces() << " 0\n";
  char buf[64];
  for (auto vh : mesh.vertices()) {
    const Point2 p = point2(mesh, vh);
    const bool given = exact_given && static_cast<std::size_t>(vh.idx()) < exact_given->size();
    const auto exact = given ? (*exact_given)[static_cast<std::size_t>(vh.idx())] : exact_coordinates(mesh, vh);
    if (exact[0] == exact_rational(p.x()) && exact[1] == exact_rational(p.y())) {
      std::snprintf(buf, sizeof buf, "%.17g %.17g", p.x(), p.y());
      out << buf << " 0\n";
    } else {
      out << exact[0] << " " << exact[1] << " 0\n";
    }
  }
  for (auto fh : mesh.faces()) {
    out << "3";
    for (auto fv : mesh.fv_range(fh)) out << " " << index[fv.idx()];
    out << "\n";
  }
  file.commit();
}

CgshopSolution make_cgshop_solution(const Mesh& mesh, const Domain& domain, const ExactCoordinates* exact) {
  CgshopSolution s;
  s.instance_uid = domain.instance_uid.empty() ? domain.name : domain.instance_uid;
  s.n_points = domain.points.size();
  std::map<std::pair<double, double>, int> point_index;
  for (std::size_t i = 0; i < domain.points.size(); ++i)
    point_index.emplace(std::make_pair(domain.points[i].x(), domain.points[i].y()), static_cast<int>(i));
  std::vector<int> index(mesh.n_vertices(), -1);
  std::vector<char> present(domain.points.size(), 0);
  for (auto vh : mesh.vertices()) {
    if (mesh.is_isolated(vh)) continue;
    const Point2 p = point2(mesh, vh);
    const auto it = point_index.find({p.x(), p.y()});
    if (it != point_index.end()) {
      index[vh.idx()] = it->second;
      present[static_cast<std::size_t>(it->second)] = 1;
    } else {
      index[vh.idx()] = static_cast<int>(s.n_points + s.steiner_points.size());
      s.steiner_points.push_back(p);
      const bool given = exact && static_cast<std::size_t>(vh.idx()) < exact->size();
      s.steiner_exact.push_back(given ? (*exact)[static_cast<std::size_t>(vh.idx())] : exact_coordinates(mesh, vh));
    }
  }
  for (std::size_t i = 0; i < present.size(); ++i)
    if (!present[i])
      throw InvalidInput("point " + std::to_string(i) + " (" + std::to_string(domain.points[i].x()) + ", " +
                         std::to_string(domain.points[i].y()) + ") is not a vertex of the triangulation");
  s.edges.reserve(mesh.n_edges());
  for (auto eh : mesh.edges()) {
    const auto h = mesh.halfedge_handle(eh, 0);
    s.edges.push_back({index[mesh.from_vertex_handle(h).idx()], index[mesh.to_vertex_handle(h).idx()]});
  }
  return s;
}

void write_cgshop_solution(const CgshopSolution& solution, const std::string& path) {
  nlohmann::ordered_json j;
  j["content_type"] = "CG_SHOP_2025_Solution";
  j["instance_uid"] = solution.instance_uid;
  auto xs = nlohmann::ordered_json::array(), ys = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < solution.steiner_points.size(); ++i) {
    const Point2& p = solution.steiner_points[i];
    const bool exact = i < solution.steiner_exact.size();
    if (exact && solution.steiner_exact[i][0] != exact_rational(p.x()))
      xs.push_back(solution.steiner_exact[i][0]);
    else
      xs.push_back(coordinate(p.x()));
    if (exact && solution.steiner_exact[i][1] != exact_rational(p.y()))
      ys.push_back(solution.steiner_exact[i][1]);
    else
      ys.push_back(coordinate(p.y()));
  }
  j["steiner_points_x"] = std::move(xs);
  j["steiner_points_y"] = std::move(ys);
  auto edges = nlohmann::ordered_json::array();
  for (const auto& e : solution.edges) edges.push_back({e[0], e[1]});
  j["edges"] = std::move(edges);
  j["meta"] = {{"generator", "libacute"}};
  detail::AtomicFile file(path);
  file.stream() << j.dump() << "\n";
  file.commit();
}

void write_cgshop_solution(const Mesh& mesh, const Domain& domain, const std::string& path, const ExactCoordinates* exact) {
  write_cgshop_solution(make_cgshop_solution(mesh, domain, exact), path);
}

}  // namespace acute::io
