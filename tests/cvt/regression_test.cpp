// Regressions of the CVT start on the shared classic domains (skipped when they are absent) and on
// small built-in domains: flat triangles on Constrained_Sweden, the lost enclosure on debug2, the
// local feature size across a narrow neck (guitar) or channel.
#include "cvt/cvt_domains.h"
#include "support/mesh_verify.h"
#include "support/paths.h"

#include <acute/cvt/cvt.h>
#include <acute/delaunay/cdt.h>
#include <acute/io/io.h>
#include <acute/mesh/check.h>
#include <acute/mesh/geometry.h>
#include <acute/mesh/quality.h>
#include <acute/mesh/segments.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace acute {
namespace {

namespace fs = std::filesystem;

/// Reads a classic shared domain; false when absent (the test then skips).
bool read_classic(const std::string& name, Domain& out) {
  const fs::path p = fs::path(acute::test::shared_dir()) / "domains" / "classic" / (name + ".poly");
  if (!fs::exists(p)) return false;
  out = io::read_domain(p.string());
  return true;
}

double max_angle_deg(const Mesh& mesh, FaceHandle fh) {
  const auto p = face_points(mesh, fh);
  const auto a = triangle_angles_deg(p[0], p[1], p[2]);
  return *std::max_element(a.begin(), a.end());
}

/// Every OnSegment vertex strictly inside its segment, on its line.
void expect_on_segments(const Mesh& mesh, const std::string& name) {
  for (auto vh : mesh.vertices()) {
    if (mesh.data(vh).kind != VertexKind::OnSegment) continue;
    const auto& [a, b] = segment_endpoints(mesh, mesh.data(vh).segment);
    const Point2 p = point2(mesh, vh);
    const double t = (p - a).dot(b - a) / (b - a).squaredNorm();
    EXPECT_GT(t, 0) << name << " vertex " << vh.idx();
    EXPECT_LT(t, 1) << name << " vertex " << vh.idx();
    const Point2 u = (b - a).normalized();
    EXPECT_LE(std::abs((p - a).x() * u.y() - (p - a).y() * u.x()), 1e-12 * (b - a).norm()) << name << " vertex " << vh.idx();
  }
}

TEST(CvtRegression, sweden_2000_has_no_flat_triangles_and_few_obtuse) {
  Domain d;
  if (!read_classic("Constrained_Sweden", d)) GTEST_SKIP() << "no shared domains at " << acute::test::shared_dir();
  CvtParams cp;
  cp.target_vertices = 2000;
  cp.graded = true;
  cp.lbfgs_iterations = 10;  // the flat triangles came from the field and the sampling, not the iteration count
  const CvtResult r = cvt_mesh(d, cp);
  EXPECT_TRUE(check_mesh(r.mesh, CheckLevel::Delaunay).ok()) << d.name << ": " << check_mesh(r.mesh, CheckLevel::Delaunay).summary();
  expect_on_segments(r.mesh, d.name);
  std::size_t obtuse = 0, flat = 0;
  for (auto fh : r.mesh.faces()) {
    const double m = max_angle_deg(r.mesh, fh);
    obtuse += m > 90 ? 1 : 0;
    // Three consecutive input points of the coast make a 170.5 degree corner: beyond that is new.
    if (m > 171) {
      ++flat;
      const auto p = face_points(r.mesh, fh);
      ADD_FAILURE() << d.name << ": near-flat triangle (" << m << " deg) at " << p[0].transpose();
    }
  }
  const double frac = static_cast<double>(obtuse) / static_cast<double>(r.mesh.n_faces());
  std::cout << "[cvt] " << d.name << " target 2000: " << r.mesh.n_vertices() << " vertices (the coast needs more), "
            << 100 * frac << "% obtuse\n";
  EXPECT_EQ(flat, 0u) << d.name;
  EXPECT_LT(frac, 0.10) << d.name;
  EXPECT_GT(r.mesh.n_vertices(), 2619u) << d.name << ": every input point is kept";
}

TEST(CvtRegression, debug2_sampling_keeps_the_enclosure) {
  Domain d;
  if (!read_classic("debug2", d)) GTEST_SKIP() << "no shared domains at " << acute::test::shared_dir();
  const Mesh cdt = build_cdt(d);
  for (std::size_t n : {2000u}) {
    SizeFieldParams sp;
    sp.target_vertices = n;
    sp.graded = true;
    sp.hold_count = true;  // ~32k samples: the features alone would decide ~2M
    const SizeField f = make_size_field(cdt, sp);
    SamplingStats stats;
    Mesh mesh;
    ASSERT_NO_THROW(mesh = sample_domain(d, cdt, f, {}, &stats)) << d.name << " target " << n;
    EXPECT_TRUE(check_mesh(mesh, CheckLevel::Delaunay).ok()) << d.name << ": " << check_mesh(mesh, CheckLevel::Delaunay).summary();
    EXPECT_EQ(test::verify_valid(mesh), "") << d.name;
    expect_on_segments(mesh, d.name);
    double area = 0;
    for (auto fh : mesh.faces()) {
      const auto p = face_points(mesh, fh);
      area += 0.5 * signed_area2(p[0], p[1], p[2]);
    }
    EXPECT_NEAR(area, measure_domain(cdt).area, 1e-9 * measure_domain(cdt).area) << d.name << " target " << n;
  }
}

TEST(CvtRegression, guitar_neck_size_is_the_width_of_the_neck) {
  Domain d;
  if (!read_classic("guitar", d)) GTEST_SKIP() << "no shared domains at " << acute::test::shared_dir();
  // Input vertices 83 and 90 (1-based in the file) are 0.215 apart across the neck.
  const Point2 a = d.points[82], b = d.points[89];
  ASSERT_NEAR((a - b).norm(), 0.2154, 1e-3) << d.name;
  const Mesh cdt = build_cdt(d);
  for (std::size_t n : {2000u, 20000u}) {
    SizeFieldParams sp;
    sp.target_vertices = n;
    sp.graded = true;
    sp.hold_count = true;  // ~32k samples: the features alone would decide ~2M
    const SizeField f = make_size_field(cdt, sp);
    EXPECT_LE(f(a), (a - b).norm() * (1 + 1e-9)) << d.name << " target " << n << ": h at vertex 83 above the width of the neck";
    EXPECT_LE(f(b), (a - b).norm() * (1 + 1e-9)) << d.name << " target " << n << ": h at vertex 90";
    EXPECT_LE(f(0.5 * (a + b)), 1.3 * (a - b).norm()) << d.name << " target " << n << ": h in the neck";
  }
}

TEST(LocalFeatureSize, sees_the_opposite_wall_of_a_long_channel) {
  // A 10 x 0.2 channel: four corners only, so no CDT vertex lies across from the middle of a wall.
  const Domain d = test::polygon_domain({{0, 0}, {10, 0}, {10, 0.2}, {0, 0.2}}, "channel");
  const Mesh cdt = build_cdt(d);
  const SizeField f = local_feature_size_field(cdt, {});
  for (double x : {0.5, 2.5, 5.0, 7.3, 9.5}) {
    EXPECT_LE(f({x, 0.0}), 0.2 * (1 + 1e-9)) << d.name << " at x = " << x;
    EXPECT_LE(f({x, 0.1}), 0.2 * 1.3 + 1e-9) << d.name << " mid-channel at x = " << x;
  }
  const LfsSamples s = local_feature_size_samples(cdt, 1.0);
  for (std::size_t i = 0; i < s.points.size(); ++i) EXPECT_NEAR(s.lfs[i], 0.2, 1e-12) << d.name << " sample " << s.points[i].transpose();
}

TEST(LocalFeatureSize, counts_features_that_are_not_cdt_neighbours) {
  // A triangular hole whose tip is 0.05 below the top wall, far from the wall's vertices.
  Domain c = test::polygon_domain({{0, 0}, {4, 0}, {4, 1}, {0, 1}}, "comb");
  const int b = static_cast<int>(c.points.size());
  c.points.insert(c.points.end(), {{1.9, 0.3}, {2.1, 0.3}, {2, 0.95}});
  for (int i = 0; i < 3; ++i) c.segments.push_back({b + i, b + (i + 1) % 3});
  c.holes.push_back({2, 0.5});
  const Mesh cdt = build_cdt(c);
  const SizeField f = local_feature_size_field(cdt, {});
  EXPECT_LE(f({2, 0.95}), 0.05 * (1 + 1e-9)) << c.name << ": the tip";
  EXPECT_LE(f({2, 1.0}), 0.05 * (1 + 1e-9)) << c.name << ": the top wall above the tip";
}

TEST(Sampling, segment_points_keep_a_count_at_least_the_boundary_need) {
  // A vertex count below what the boundary needs: the field stays at the lfs along the boundary.
  const Domain d = test::polygon_domain({{0, 0}, {10, 0}, {10, 0.2}, {0, 0.2}}, "channel");
  const Mesh cdt = build_cdt(d);
  SizeFieldParams sp;
  sp.target_vertices = 20;
  sp.graded = true;
  const SizeField f = make_size_field(cdt, sp);
  EXPECT_LE(f({5, 0}), 0.2 * (1 + 1e-9)) << d.name;
  const Mesh mesh = sample_domain(d, cdt, f, {});
  EXPECT_GE(mesh.n_vertices(), 90u) << d.name << ": about 2 x 50 points along the walls";
  for (auto fh : mesh.faces()) EXPECT_LT(max_angle_deg(mesh, fh), 150) << d.name << " face " << fh.idx();
}

}  // namespace
}  // namespace acute
