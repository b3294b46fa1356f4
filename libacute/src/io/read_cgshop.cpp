// CG:SHOP 2025 instance JSON.
#include "io/io_detail.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>

namespace acute::io {

namespace {

// Minimal unsigned big integer (little-endian 32-bit limbs) for correctly rounded p/q.
struct BigUint {
  std::vector<std::uint32_t> limbs;

  void trim() {
    while (!limbs.empty() && limbs.back() == 0) limbs.pop_back();
  }
  bool is_zero() const { return limbs.empty(); }
  int bit_length() const {
    if (limbs.empty()) return 0;
    int bits = 32 * static_cast<int>(limbs.size() - 1);
    for (std::uint32_t top = limbs.back(); top; top >>= 1) ++bits;
    return bits;
  }
  void mul_add(std::uint32_t m, std::uint32_t a) {
    std::uint64_t carry = a;
    for (auto& l : limbs) {
      const std::uint64_t t = std::uint64_t(l) * m + carry;
      l = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    if (carry) limbs.push_back(static_cast<std::uint32_t>(carry));
  }
  BigUint shifted_left(int bits) const {
    BigUint r;
    r.limbs.assign(static_cast<std::size_t>(bits / 32), 0);
    const int s = bits % 32;
    std::uint32_t carry = 0;
    for (auto l : limbs) {
      r.limbs.push_back(s ? (l << s) | carry : l);
      carry = s ? l >> (32 - s) : 0;
    }
    if (carry) r.limbs.push_back(carry);
    r.trim();
    return r;
  }
  static int compare(const BigUint& a, const BigUint& b) {
    if (a.limbs.size() != b.limbs.size()) return a.limbs.size() < b.limbs.size() ? -1 : 1;
    for (std::size_t i = a.limbs.size(); i-- > 0;)
      if (a.limbs[i] != b.limbs[i]) return a.limbs[i] < b.limbs[i] ? -1 : 1;
    return 0;
  }
  void subtract(const BigUint& b) {  // requires *this >= b
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < limbs.size(); ++i) {
      std::int64_t t = std::int64_t(limbs[i]) - borrow - (i < b.limbs.size() ? std::int64_t(b.limbs[i]) : 0);
      borrow = t < 0;
      if (t < 0) t += std::int64_t(1) << 32;
      limbs[i] = static_cast<std::uint32_t>(t);
    }
    trim();
  }
};

bool parse_big(std::string_view s, BigUint& out) {
  if (s.empty()) return false;
  out.limbs.clear();
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    out.mul_add(10, static_cast<std::uint32_t>(c - '0'));
  }
  out.trim();
  return true;
}

// The double nearest to p/q (ties to even), q > 0.
double nearest_quotient(const BigUint& p, const BigUint& q) {
  if (p.is_zero()) return 0.0;
  // Scale so that the quotient has 55 or 56 bits: 53 kept, then a round bit, plus a sticky rest.
  const int shift = 55 + q.bit_length() - p.bit_length();
  BigUint num = shift > 0 ? p.shifted_left(shift) : p;
  const BigUint den = shift < 0 ? q.shifted_left(-shift) : q;
  std::uint64_t quotient = 0;
  for (int bit = 57; bit >= 0; --bit) {
    const BigUint d = den.shifted_left(bit);
    if (BigUint::compare(num, d) >= 0) {
      num.subtract(d);
      quotient |= std::uint64_t(1) << bit;
    }
  }
  bool sticky = !num.is_zero();
  int exponent = -shift;
  while (quotient >= (std::uint64_t(1) << 54)) {  // keep 54 bits: 53 + round bit
    sticky = sticky || (quotient & 1);
    quotient >>= 1;
    ++exponent;
  }
  const bool round = quotient & 1;
  quotient >>= 1;
  ++exponent;
  if (round && (sticky || (quotient & 1))) ++quotient;  // may carry to 2^53: still exact in a double
  return std::ldexp(static_cast<double>(quotient), exponent);
}

// A coordinate: a JSON number, or a string holding an integer, a decimal, or a fraction "p/q".
bool coordinate_of(const nlohmann::json& j, double& value) {
  if (j.is_number()) {
    value = j.get<double>();
    return true;
  }
  if (!j.is_string()) return false;
  std::string_view s = j.get_ref<const std::string&>();
  bool negative = false;
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  const auto slash = s.find('/');
  BigUint p, q;
  if (slash == std::string_view::npos) {
    if (!parse_big(s, p)) return detail::parse_double(j.get_ref<const std::string&>(), value);
    q.limbs = {1};
  } else if (!parse_big(s.substr(0, slash), p) || !parse_big(s.substr(slash + 1), q) || q.is_zero()) {
    return false;
  }
  value = nearest_quotient(p, q);
  if (negative) value = -value;
  return true;
}

}  // namespace

Domain read_cgshop(const std::string& path, const WarningSink& warn, const ReadOptions& options) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInput(path + ": not valid JSON: " + e.what());
  }
  auto fail = [&](const std::string& message) { throw InvalidInput(path + ": " + message); };
  if (!j.is_object()) fail("expected a JSON object (CG:SHOP 2025 instance)");
  for (const char* key : {"points_x", "points_y", "region_boundary"})
    if (!j.contains(key) || !j[key].is_array()) fail(std::string("missing array '") + key + "'");

  Domain d;
  d.source_path = path;
  d.instance_uid = j.value("instance_uid", std::string());
  d.name = d.instance_uid.empty() ? detail::stem_of(detail::stem_of(path)) : d.instance_uid;

  const auto& xs = j["points_x"];
  const auto& ys = j["points_y"];
  if (xs.size() != ys.size())
    fail("points_x has " + std::to_string(xs.size()) + " entries, points_y " + std::to_string(ys.size()));
  if (j.contains("num_points") && (!j["num_points"].is_number_integer() || j["num_points"].get<long long>() != static_cast<long long>(xs.size())))
    fail("num_points is " + j["num_points"].dump() + " but points_x has " + std::to_string(xs.size()) + " entries");
  const std::size_t n = xs.size();
  d.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    double x = 0, y = 0;
    if (!coordinate_of(xs[i], x)) fail("points_x[" + std::to_string(i) + "] = " + xs[i].dump() + " is not a number");
    if (!coordinate_of(ys[i], y)) fail("points_y[" + std::to_string(i) + "] = " + ys[i].dump() + " is not a number");
    d.points[i] = Point2(x, y);
  }
  d.point_markers.assign(n, 0);

  auto index_of = [&](const nlohmann::json& v, const std::string& where) {
    if (!v.is_number_integer()) fail(where + " = " + v.dump() + " is not an integer");
    const long long k = v.get<long long>();
    if (k < 0 || k >= static_cast<long long>(n))
      fail(where + " = " + std::to_string(k) + " is out of range (" + std::to_string(n) + " points)");
    return static_cast<int>(k);
  };
  const auto& region = j["region_boundary"];
  const std::size_t m = region.size();
  if (m < 3) fail("region_boundary has " + std::to_string(m) + " points, need at least 3");
  std::vector<int> loop(m);
  for (std::size_t i = 0; i < m; ++i) loop[i] = index_of(region[i], "region_boundary[" + std::to_string(i) + "]");
  for (std::size_t i = 0; i < m; ++i) {
    d.segments.push_back({loop[i], loop[(i + 1) % m]});
    d.segment_markers.push_back(1);  // boundary
  }
  if (j.contains("additional_constraints")) {
    const auto& cs = j["additional_constraints"];
    if (!cs.is_array()) fail("additional_constraints is not an array");
    for (std::size_t i = 0; i < cs.size(); ++i) {
      const std::string where = "additional_constraints[" + std::to_string(i) + "]";
      if (!cs[i].is_array() || cs[i].size() != 2) fail(where + " is not a pair of point indices");
      d.segments.push_back({index_of(cs[i][0], where + "[0]"), index_of(cs[i][1], where + "[1]")});
      d.segment_markers.push_back(0);
    }
    if (j.contains("num_constraints") && j["num_constraints"] != cs.size() && warn)
      warn(path + ": num_constraints is " + j["num_constraints"].dump() + " but additional_constraints has " +
           std::to_string(cs.size()) + " entries");
  }
  detail::remove_duplicate_segments(d, nullptr, warn);
  validate_domain(d, options.allow_crossing_segments);
  return d;
}

}  // namespace acute::io
