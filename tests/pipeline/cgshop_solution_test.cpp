// io::exact_rational and the CG:SHOP 2025 solution writer: exact values, indices, round trip.
#include <acute/core/errors.h>
#include <acute/io/cgshop_solution.h>
#include <acute/io/io.h>
#include <acute/mesher.h>

#include "support/paths.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>
#include <limits>
#include <set>
#include <string>

namespace acute {
namespace {

/// Parses an exact_rational text back to the double it denotes (q a power of two).
double parse_dyadic(const nlohmann::json& v) {
  if (v.is_number_integer()) return static_cast<double>(v.get<std::int64_t>());
  const std::string s = v.get<std::string>();
  const auto slash = s.find('/');
  if (slash == std::string::npos) return std::stod(s);
  const double p = std::stod(s.substr(0, slash));  // <= 2^53 in magnitude: exact
  const std::string q = s.substr(slash + 1);
  // q = 2^k: count the halvings of its decimal text
  std::string digits = q;
  int k = 0;
  while (digits != "1") {
    std::string half;
    int carry = 0;
    for (char c : digits) {
      const int d = carry * 10 + (c - '0');
      if (!half.empty() || d / 2 > 0) half += static_cast<char>('0' + d / 2);
      carry = d % 2;
    }
    EXPECT_EQ(carry, 0) << q << " is not a power of two";
    digits = half;
    ++k;
  }
  return std::ldexp(p, -k);
}

TEST(ExactRational, small_values_are_exact_fractions_in_lowest_terms) {
  EXPECT_EQ(io::exact_rational(0.0), "0");
  EXPECT_EQ(io::exact_rational(3.0), "3");
  EXPECT_EQ(io::exact_rational(-12.0), "-12");
  EXPECT_EQ(io::exact_rational(0.5), "1/2");
  EXPECT_EQ(io::exact_rational(-0.75), "-3/4");
  EXPECT_EQ(io::exact_rational(0.1), "3602879701896397/36028797018963968");
  EXPECT_EQ(io::exact_rational(std::ldexp(1.0, 70)), "1180591620717411303424");
  EXPECT_THROW(io::exact_rational(std::nan("")), InvalidInput);
}

TEST(ExactRational, random_doubles_round_trip) {
  std::uint64_t state = 12345;
  for (int i = 0; i < 2000; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double x = std::ldexp(static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5, static_cast<int>(state % 80) - 40);
    EXPECT_EQ(parse_dyadic(io::exact_rational(x)), x) << io::exact_rational(x);
  }
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(parse_dyadic(io::exact_rational(tiny)), tiny) << "denorm_min";
}

TEST(CgshopSolution, written_solution_reads_back_to_the_mesh) {
  // a square with an interior point, meshed by the CDT, plus one Steiner point at a dyadic position
  Domain d;
  d.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  d.instance_uid = "unit_square_test";
  Mesh m = build_domain_cdt(d);
  // split an interior edge at its midpoint: a Steiner point (x, y) not at an input point
  EdgeHandle split;
  for (auto eh : m.edges())
    if (!m.is_boundary(eh)) split = eh;
  const auto h = m.halfedge_handle(split, 0);
  const Point2 mid = 0.5 * (point2(m, m.from_vertex_handle(h)) + point2(m, m.to_vertex_handle(h)));
  const auto vh = m.add_vertex(Mesh::Point(mid.x() + 0.1, mid.y(), 0));  // 0.1: not a dyadic with a short form
  m.split(split, vh);

  const auto path = (std::filesystem::path(acute::test::test_output_dir()) / "unit_square_test.solution.json").string();
  io::write_cgshop_solution(m, d, path);
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["content_type"], "CG_SHOP_2025_Solution") << path;
  EXPECT_EQ(j["instance_uid"], "unit_square_test") << path;
  ASSERT_EQ(j["steiner_points_x"].size(), 1u) << path;
  ASSERT_EQ(j["steiner_points_y"].size(), 1u) << path;
  EXPECT_EQ(parse_dyadic(j["steiner_points_x"][0]), mid.x() + 0.1) << j["steiner_points_x"][0];
  EXPECT_EQ(parse_dyadic(j["steiner_points_y"][0]), mid.y()) << j["steiner_points_y"][0];
  EXPECT_EQ(j["edges"].size(), m.n_edges()) << path;
  std::set<std::pair<int, int>> edges;
  for (const auto& e : j["edges"]) {
    const int a = e[0], b = e[1];
    EXPECT_TRUE(a >= 0 && a < 6 && b >= 0 && b < 6 && a != b) << e;
    edges.insert({std::min(a, b), std::max(a, b)});
  }
  EXPECT_EQ(edges.size(), m.n_edges()) << "no repeated edge";
  for (auto [a, b] : {std::pair{0, 1}, {1, 2}, {2, 3}, {0, 3}}) EXPECT_TRUE(edges.count({a, b})) << "boundary edge " << a << "-" << b;
}

__extension__ typedef __int128 Int128;

/// "P/Q" or "P" as (P, Q); P and Q must fit 64 bits.
std::pair<Int128, Int128> fraction(const std::string& s) {
  const auto slash = s.find('/');
  if (slash == std::string::npos) return {std::stoll(s), 1};
  return {std::stoll(s.substr(0, slash)), static_cast<Int128>(std::stoull(s.substr(slash + 1)))};
}

TEST(CgshopSolution, exact_coordinates_put_segment_vertices_exactly_on_slanted_segments) {
  Domain d;
  d.points = {{0, 0}, {3, 1}, {0, 5}};
  d.segments = {{0, 1}, {1, 2}, {2, 0}};
  Mesh m = build_domain_cdt(d);
  // a vertex on segment 0 at a rounded position (0.1 * (3, 1) is not exactly on the line)
  EdgeHandle seg0;
  for (auto eh : m.edges())
    if (m.data(eh).segment == 0) seg0 = eh;
  ASSERT_TRUE(seg0.is_valid());
  const auto vh = m.add_vertex(Mesh::Point(0.3 * 1.0000000000000002, 0.1, 0));
  m.split(seg0, vh);
  m.data(vh).kind = VertexKind::OnSegment;
  m.data(vh).segment = 0;
  for (auto e : m.ve_range(vh))
    if (m.is_boundary(e)) m.data(e).segment = 0;
  const auto xy = io::exact_coordinates(m, vh);
  const auto [px, qx] = fraction(xy[0]);
  const auto [py, qy] = fraction(xy[1]);
  // on the line y = x / 3 exactly: 3 * py / qy == px / qx
  EXPECT_TRUE(3 * py * qx == px * qy) << xy[0] << ", " << xy[1];
  EXPECT_NEAR(static_cast<double>(px) / static_cast<double>(qx), 0.3, 1e-12) << xy[0];
  // a vertex not on a segment is written as its double
  EXPECT_EQ(io::exact_coordinates(m, VertexHandle(1))[0], "3") << "input vertex";
  const auto path = (std::filesystem::path(acute::test::test_output_dir()) / "slanted_exact.off").string();
  io::write_off_exact(m, path);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find(xy[0] + " " + xy[1]), std::string::npos) << path;
}

TEST(CgshopSolution, missing_input_point_is_an_error) {
  Domain d;
  d.points = {{0, 0}, {1, 0}, {0, 1}};
  d.segments = {{0, 1}, {1, 2}, {2, 0}};
  Mesh m = build_domain_cdt(d);
  d.points.push_back({5, 5});
  try {
    io::make_cgshop_solution(m, d);
    ADD_FAILURE() << "point 3 is not in the mesh";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("point 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace acute
