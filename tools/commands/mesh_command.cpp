// `acute mesh`: mesh a domain (.poly, CG:SHOP .json, or a mesh whose region is the domain).
#include "commands/commands.h"
#include "commands/pictures.h"
#include "commands/progress.h"
#include "commands/report.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>
#include <acute/mesh/dual.h>
#include <acute/mesh/quality.h>
#include <acute/mesher.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace acute::cli {

namespace {

struct MeshArgs {
  std::string input, output, method = "acute", dual, pictures;
  MeshOptions options;
  bool convex_hull = false, split_crossings = false, json = false;
};

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::exists(b, ec) && std::filesystem::equivalent(a, b, ec);
}

int run_mesh(const MeshArgs& args, const GlobalOptions& global) {
  const auto t0 = std::chrono::steady_clock::now();
  if (same_file(args.input, args.output)) throw IoError(args.output + ": refusing to overwrite the input file");
  if (!io::is_mesh_output_path(args.output)) throw InvalidInput(args.output + ": unknown output format (use .off .obj .ply .node .ele .vtk .vtu .msh .svg)");
  if (!args.dual.empty() && !io::is_dual_output_path(args.dual))
    throw InvalidInput(args.dual + ": unknown dual format (use .off .obj .ply .vtk .vtu .svg)");
  io::WarningSink warn = [&](const std::string& w) {
    if (!global.quiet) std::cerr << "acute: warning: " << w << "\n";
  };
  io::ReadOptions read_options;
  read_options.allow_crossing_segments = args.split_crossings;  // the CDT splits them
  Domain domain = io::read_domain(args.input, warn, read_options);
  domain.convex_hull = domain.convex_hull || args.convex_hull;
  MeshOptions options = args.options;
  options.method = parse_method(args.method);
  options.cdt.crossing = args.split_crossings ? CrossingSegments::Split : CrossingSegments::Error;
  if (!args.pictures.empty()) check_picture_prefix(args.pictures, {args.output, args.dual});
  ProgressLine progress(global, t0);
  if (progress.wanted())
    options.observer = [&progress](const MeshProgress& p) {
      if (p.phase == "cvt")
        progress.update_cvt(p.iteration, p.step, p.energy, p.gradient_norm);
      else
        progress.update(p.phase, p.iteration, p.bad);
    };
  if (!global.quiet) options.on_note = [&progress](const std::string& note) { progress.print("acute: note: " + note + "\n"); };
  // Initialised from the call, not assigned: an OpenMesh mesh has no move, so an assignment
  // copies it whole (tens of milliseconds per million triangles).
  MeshResult result = [&] {
    try {
      return generate_mesh(domain, options);
    } catch (const InvalidInput& e) {
      throw InvalidInput(args.input + ": " + e.what());
    }
  }();
  progress.finish();
  for (const auto& note : result.notes) warn(note);

  io::WriteOptions write_options;
  write_options.min_angle_deg = options.min_angle_deg;
  write_options.max_angle_deg = options.max_angle_deg;
  write_options.title = domain.name;
  io::write_mesh(result.mesh, args.output, write_options);
  std::optional<DualCheck> dual_check;
  if (!args.dual.empty()) {
    dual_check = check_well_centered(result.mesh);
    io::write_dual(circumcentric_dual(result.mesh), args.dual, &result.mesh, write_options);
    if (!dual_check->well_centered() && !global.quiet)
      std::cerr << "acute: the dual is not well-centred: " << dual_check->n_right << " right and " << dual_check->n_obtuse
                << " obtuse triangles\n";
  }

  RunReport report;
  if (!args.pictures.empty()) {
    const Mesh before = build_domain_cdt(domain, options.cdt);
    report.pictures = write_pictures(args.pictures, before, result.mesh, write_options);
  }

  QualityOptions qopt;
  qopt.min_angle_deg = options.min_angle_deg;
  qopt.max_angle_deg = options.max_angle_deg;
  // Only a summary line or a JSON report reads the figures (0.25 s per million triangles).
  const QualityReport q = global.quiet && !args.json ? QualityReport{} : measure_quality(result.mesh, qopt, &domain);
  report.label = args.method;
  report.input = args.input;
  report.status = result.status == MeshStatus::Ok ? "ok" : (result.status == MeshStatus::BoundsNotMet ? "bounds_not_met" : "n/a");
  report.bounds_not_met = result.status == MeshStatus::BoundsNotMet;
  report.bad_summary = std::to_string(result.remaining.size()) + (result.remaining.size() >= 100 ? "+" : "") + " bad triangle(s)";
  report.remaining = result.remaining;
  report.n_vertices = q.n_vertices;
  report.n_triangles = q.n_triangles;
  report.n_steiner = q.n_steiner;
  report.min_angle = q.min_angle;
  report.max_angle = q.max_angle;
  char figures[96];
  std::snprintf(figures, sizeof figures, "%zu obtuse, %zu below %.4g", q.n_obtuse, q.n_below_min, options.min_angle_deg);
  report.figures = figures;
  report.iterations = result.iterations;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  report.outputs = {args.output};
  if (!args.dual.empty()) report.outputs.push_back(args.dual);
  nlohmann::json& j = report.extra;
  j["output"] = args.output;
  j["method"] = args.method;
  j["free_min_angle"] = q.free_min_angle ? nlohmann::json(*q.free_min_angle) : nlohmann::json(nullptr);
  j["n_obtuse"] = q.n_obtuse;
  j["n_right"] = q.n_right;
  j["n_below_min"] = q.n_below_min;
  j["merged_duplicates"] = result.cdt.merged_duplicates;
  if (result.cvt_vertices > 0) j["n_vertices_cvt"] = result.cvt_vertices;
  if (result.start_vertices > 0) j["n_vertices_start"] = result.start_vertices;
  if (dual_check)
    j["dual"] = {{"well_centered", dual_check->well_centered()}, {"n_right", dual_check->n_right}, {"n_obtuse", dual_check->n_obtuse}};
  print_report(report, args.json, global);
  return report.bounds_not_met ? BoundsNotMet : Ok;
}


}  // namespace

void add_mesh_command(CLI::App& app, const GlobalOptions& global, int& exit_code) {
  auto args = std::make_shared<MeshArgs>();
  auto* cmd = app.add_subcommand("mesh", "Mesh a domain (.poly, CG:SHOP .json, .off/.obj/.ply region)");
  cmd->footer(
      "Examples:\n"
      "  acute mesh meshes/A.poly -o A.off                    # acute mesh, every angle in [30, 90)\n"
      "  acute mesh meshes/A.poly -o A.vtu --vertices 20000 --dual A_dual.vtu\n"
      "  acute mesh meshes/A.poly -o A.off --method refine --min-angle 30 --size 0.05\n"
      "  acute mesh meshes/A.poly -o A.svg --method cdt\n"
      "  acute mesh meshes/A.poly -o A.off --pictures A        # A_before.svg (the CDT), A_after.svg,\n"
      "                                                         # A_before_histogram.svg, A_after_histogram.svg\n"
      "On a terminal, stderr shows one updating progress line (phase, iteration, bad triangles,\n"
      "elapsed time); never when stderr is a file or pipe, nor with -q.\n"
      "Exit codes: 0 ok, 1 bounds not met (best mesh still written), 2 invalid input, 3 I/O error.");
  cmd->add_option("domain", args->input, "Domain: .poly, CG:SHOP .json, or a mesh (.off .obj .ply .node/.ele) whose region is meshed")
      ->type_name("DOMAIN")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->output, "Output mesh, format from the extension: .off .obj .ply .node .ele .vtk .vtu .msh .svg")
      ->type_name("OUT")
      ->required();
  cmd->add_option("--method", args->method, "cdt | refine | cvt | acute")->type_name("METHOD")->capture_default_str();
  cmd->add_option("--min-angle", args->options.min_angle_deg, "Smallest allowed angle (degrees)")->capture_default_str();
  cmd->add_option("--max-angle", args->options.max_angle_deg, "Angles must be strictly below this (degrees)")->capture_default_str();
  auto* size = cmd->add_option("--size", args->options.size, "Largest edge length (finer where the domain's features need it; uniform with --method cvt or refine)");
  cmd->add_option("--vertices", args->options.target_vertices, "Target vertex count (small features that need more get more; under --time-limit T at most the larger of 16 times it and 1,000 T)")->excludes(size);
  cmd->add_option("--gradation", args->options.gradation, "Size gradation factor: how fast sizes may grow away from features (the acute method follows at most 1.5)")->capture_default_str();
  cmd->add_option("--max-size", args->options.max_size, "Largest edge length of the graded size field (default: a fraction of the domain's diameter)")
      ->excludes(size);
  cmd->add_option("--seed", args->options.seed, "Random seed (deterministic output)")->capture_default_str();
  cmd->add_option("--max-iterations", args->options.max_iterations, "Iteration cap (0: method default)");
  cmd->add_option("--restarts", args->options.restarts, "When the acute repair stalls with a few bad triangles, run again from another seed's start with a 5% finer size field each time, up to this many times")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  cmd->add_option("--max-vertices", args->options.max_vertices, "Vertex budget")->capture_default_str();
  cmd->add_option("--time-limit", args->options.time_limit_s, "Time limit in seconds for the meshing; a step that cannot be cut (about a second on 10^6 vertices) and writing the output come on top (0: none)");
  cmd->add_option("--dual", args->dual, "Also write the circumcentric dual (.off .obj .ply .vtk .vtu .svg)")->type_name("DUAL");
  cmd->add_option("--pictures", args->pictures,
                  "Also write PREFIX_before.svg (the CDT of the domain), PREFIX_after.svg and their angle histograms")
      ->type_name("PREFIX");
  cmd->add_flag("--convex-hull", args->convex_hull, "Mesh the convex hull of the points (Triangle -c)");
  cmd->add_flag("--split-crossings", args->split_crossings, "Split crossing segments instead of failing");
  cmd->add_flag("--json", args->json, "Print a JSON report on stdout");
  cmd->add_flag("-q,--quiet", const_cast<GlobalOptions&>(global).quiet, "No output but errors");
  cmd->add_flag("-v,--verbose", const_cast<GlobalOptions&>(global).verbose, "Log each phase on stderr (off a terminal also each CVT iteration with its energy and gradient norm, and each repair iteration)");
  cmd->callback([args, &global, &exit_code] { exit_code = run_guarded([&] { return run_mesh(*args, global); }); });
}

}  // namespace acute::cli
