#include <acute/io/cgshop_solution.h>

#include "io/atomic_file.h"

#include <acute/core/errors.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
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

CgshopSolution make_cgshop_solution(const Mesh& mesh, const Domain& domain) {
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
  for (const auto& p : solution.steiner_points) {
    xs.push_back(coordinate(p.x()));
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

void write_cgshop_solution(const Mesh& mesh, const Domain& domain, const std::string& path) {
  write_cgshop_solution(make_cgshop_solution(mesh, domain), path);
}

}  // namespace acute::io
