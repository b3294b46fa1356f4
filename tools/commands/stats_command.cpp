// `acute stats`: angle statistics of a mesh, with meshcheck's definitions and JSON key names.
#include "commands/commands.h"

#include <acute/io/io.h>
#include <acute/mesh/check.h>
#include <acute/mesh/quality.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace acute::cli {

namespace {

struct StatsArgs {
  std::string mesh_path;
  std::string domain_path;
  bool json = false;
  bool histogram = false;
  std::optional<double> min_angle, max_angle;
};

/// A number, or null when absent (angle figures of an empty mesh).
nlohmann::json num(bool present, double v) { return present ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json to_json(const StatsArgs& a, const QualityReport& q, const Domain* domain, const CheckReport& check,
                       std::size_t viol_min, std::size_t viol_max) {
  using nlohmann::json;
  const bool any = q.n_triangles > 0;
  json j;
  j["mesh"] = a.mesh_path;
  j["domain"] = a.domain_path.empty() ? json(nullptr) : json(a.domain_path);
  j["n_vertices"] = q.n_vertices;
  j["n_triangles"] = q.n_triangles;
  j["n_steiner"] = q.n_steiner ? json(*q.n_steiner) : json(nullptr);
  j["min_angle"] = num(any, q.min_angle);
  j["max_angle"] = num(any, q.max_angle);
  j["min_angle_bound"] = q.min_angle_bound;
  j["max_angle_bound"] = q.max_angle_bound;
  j["bounds_given"] = {{"min", a.min_angle.has_value()}, {"max", a.max_angle.has_value()}};
  j["n_below_min"] = q.n_below_min;
  j["pct_below_min"] = q.pct(q.n_below_min);
  j["n_above_max"] = q.n_above_max;
  j["pct_above_max"] = q.pct(q.n_above_max);
  j["n_at_max"] = q.n_at_max;
  j["n_right"] = q.n_right;
  j["pct_right"] = q.pct(q.n_right);
  j["n_obtuse"] = q.n_obtuse;
  j["pct_obtuse"] = q.pct(q.n_obtuse);
  j["mean_min_angle"] = num(any, q.mean_min_angle);
  j["std_min_angle"] = num(any, q.std_min_angle);
  j["mean_max_angle"] = num(any, q.mean_max_angle);
  j["std_max_angle"] = num(any, q.std_max_angle);
  j["q_min"] = num(any, q.q_min);
  j["q_mean"] = num(any, q.q_mean);
  j["n_forced_corners"] = q.forced_corners.size();
  json fc = json::array();
  for (std::size_t i = 0; i < q.forced_corners.size() && i < 5; ++i) {
    const Point2& p = domain->points[q.forced_corners[i].point];
    fc.push_back({{"point", {p.x(), p.y()}}, {"angle", q.forced_corners[i].angle_deg}});
  }
  j["forced_corners"] = fc;
  j["free_min_angle"] = q.free_min_angle ? json(*q.free_min_angle) : json(nullptr);
  j["n_free_triangles"] = q.n_free_triangles;
  j["n_below_min_free"] = q.n_below_min_free;
  j["n_max_violations"] = q.n_max_violations;
  j["violations"] = {{"min", viol_min}, {"max", viol_max}};
  if (q.has_histogram && any) {
    json edges = json::array();
    for (int e = 0; e <= 180; e += 10) edges.push_back(e);
    j["histogram"] = {{"bin_edges_deg", edges}, {"counts", q.histogram}, {"right", q.histogram_right}};
  } else {
    j["histogram"] = nullptr;
  }
  j["valid"] = check.ok();
  j["check"] = check.summary();
  return j;
}

std::string fmt(double v, int digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

void print_text(const StatsArgs& a, const QualityReport& q, const Domain* domain, const CheckReport& check,
                std::size_t viol_min, std::size_t viol_max) {
  auto& o = std::cout;
  o << "mesh    " << a.mesh_path << "\n";
  o << "domain  " << (a.domain_path.empty() ? std::string("none (no Steiner count, no forced corners)") : a.domain_path)
    << "\n";
  o << "valid   " << (check.ok() ? "yes" : "NO: " + check.summary(3)) << "\n";
  o << "vertices " << q.n_vertices << "   triangles " << q.n_triangles << "   Steiner points "
    << (q.n_steiner ? std::to_string(*q.n_steiner) : std::string("n/a")) << "\n";
  if (q.n_triangles) {
    char line[512];
    o << "min angle " << fmt(q.min_angle, 10) << "   max angle " << fmt(q.max_angle, 10) << "   (degrees)\n";
    std::snprintf(line, sizeof line,
                  "below %s: %zu (%.2f%%)   above %s: %zu (%.2f%%)   right (90): %zu (%.2f%%)   obtuse: %zu (%.2f%%)\n",
                  fmt(q.min_angle_bound).c_str(), q.n_below_min, q.pct(q.n_below_min), fmt(q.max_angle_bound).c_str(),
                  q.n_above_max, q.pct(q.n_above_max), q.n_right, q.pct(q.n_right), q.n_obtuse, q.pct(q.n_obtuse));
    o << line;
    o << "per-triangle min angle: mean " << fmt(q.mean_min_angle) << ", std " << fmt(q.std_min_angle)
      << ";  max angle: mean " << fmt(q.mean_max_angle) << ", std " << fmt(q.std_max_angle) << "\n";
    o << "quality Q = 2*sqrt(3)*S/(p*h): min " << fmt(q.q_min) << ", mean " << fmt(q.q_mean) << "\n";
  }
  if (domain) {
    o << "forced corners (below " << fmt(q.min_angle_bound) << " degrees): " << q.forced_corners.size()
      << ";  free min angle " << (q.free_min_angle ? fmt(*q.free_min_angle, 10) : std::string("n/a")) << " (over "
      << q.n_free_triangles << " triangles not incident on them)\n";
    for (std::size_t i = 0; i < q.forced_corners.size() && i < 5; ++i) {
      const Point2& p = domain->points[q.forced_corners[i].point];
      o << "    - corner at (" << fmt(p.x(), 17) << ", " << fmt(p.y(), 17) << "): " << fmt(q.forced_corners[i].angle_deg)
        << " degrees\n";
    }
  }
  if (q.has_histogram && q.n_triangles) {
    std::size_t total = q.histogram_right;
    for (auto n : q.histogram) total += n;
    o << "angle histogram (all " << total << " angles; within 1e-09 of a multiple of 10 counted at it):\n";
    char line[64];
    for (int i = 0; i < 18; ++i) {
      if (i == 9) {
        std::snprintf(line, sizeof line, "   %-11s %10zu\n", "= 90 right", q.histogram_right);
        o << line;
      }
      const std::string label = i == 9    ? "(90,100)"
                                : i == 17 ? "[170,180]"
                                          : "[" + std::to_string(10 * i) + "," + std::to_string(10 * i + 10) + ")";
      std::snprintf(line, sizeof line, "   %-11s %10zu\n", label.c_str(), q.histogram[i]);
      o << line;
    }
  }
  if (a.min_angle || a.max_angle) {
    o << "bounds:";
    if (a.min_angle)
      o << " " << viol_min << " triangle(s) not incident on a forced corner have an angle below " << fmt(*a.min_angle)
        << (a.max_angle ? ";" : "");
    if (a.max_angle) o << " " << viol_max << " triangle(s) have an angle not strictly below " << fmt(*a.max_angle);
    o << "\n";
  }
}

int run_stats(const StatsArgs& a) {
  const Mesh mesh = io::read_mesh(a.mesh_path);
  std::unique_ptr<Domain> domain;
  if (!a.domain_path.empty()) {
    domain = std::make_unique<Domain>(io::read_domain(a.domain_path));
    if (io::is_mesh_path(a.domain_path)) {
      // Repair case: every vertex of the domain mesh is an input point for the Steiner count
      // (as meshcheck counts it); extra points without segments do not change forced corners.
      const Mesh dm = io::read_mesh(a.domain_path);
      for (auto vh : dm.vertices()) domain->points.push_back(point2(dm, vh));
    }
  }
  QualityOptions opt;
  opt.min_angle_deg = a.min_angle.value_or(30.0);
  opt.max_angle_deg = a.max_angle.value_or(90.0);
  opt.histogram = a.histogram;
  const QualityReport q = measure_quality(mesh, opt, domain.get());
  const CheckReport check = check_mesh(mesh, CheckLevel::Geometry);
  const std::size_t viol_min = a.min_angle ? q.n_below_min_free : 0;
  const std::size_t viol_max = a.max_angle ? q.n_max_violations : 0;
  if (a.json)
    std::cout << to_json(a, q, domain.get(), check, viol_min, viol_max).dump(1) << "\n";
  else
    print_text(a, q, domain.get(), check, viol_min, viol_max);
  return (viol_min || viol_max) ? BoundsNotMet : Ok;
}

}  // namespace

void add_stats_command(CLI::App& app, const GlobalOptions&, int& exit_code) {
  auto args = std::make_shared<StatsArgs>();
  CLI::App* sub = app.add_subcommand("stats", "Angle statistics of a triangle mesh (meshcheck's definitions)");
  sub->footer(
      "Angles are atan2(|cross|, dot) in degrees; angles within 1e-9 of a bound count as equal to it.\n"
      "With --domain: Steiner points (vertices not at an input point) and forced corners (domain\n"
      "corners narrower than the min bound, exempt from it). --json prints one object whose keys are\n"
      "those of meshcheck's \"quality\" object, plus mesh, domain, valid and check.\n"
      "Exit: 0, or 1 when a bound given with --min-angle/--max-angle is violated; 2 bad input, 3 I/O.\n\n"
      "Example:\n"
      "  acute stats out.off --domain in.poly --min-angle 30 --max-angle 90 --histogram\n"
      "  acute stats out.off --json > stats.json\n");
  sub->add_option("mesh", args->mesh_path, "Triangle mesh (.off .obj .ply .node/.ele)")->type_name("MESH")->required();
  sub->add_option("--domain", args->domain_path, "Input domain (.poly, CG:SHOP .json, or a mesh)")->type_name("DOMAIN");
  sub->add_flag("--json", args->json, "Print one JSON object");
  sub->add_flag("--histogram", args->histogram, "Add a 10-degree histogram of all angles (as a picture: acute render --histogram)");
  sub->add_option("--min-angle", args->min_angle, "Minimum angle bound in degrees (default 30; checked if given)")
      ->check(CLI::Range(0.0, 180.0));
  sub->add_option("--max-angle", args->max_angle, "Maximum angle bound in degrees, exclusive (default 90; checked if given)")
      ->check(CLI::Range(0.0, 180.0));
  sub->callback([args, &exit_code] { exit_code = run_guarded([&] { return run_stats(*args); }); });
}

}  // namespace acute::cli
