// `acute repair`: make an existing mesh acute (region and boundary kept), or keep every input
// vertex and remove the obtuse angles (--keep-vertices; CG:SHOP 2025 instances and solutions).
#include "commands/commands.h"
#include "commands/pictures.h"
#include "commands/progress.h"
#include "commands/report.h"

#include <acute/core/errors.h>
#include <acute/io/cgshop_solution.h>
#include <acute/io/io.h>
#include <acute/repair_mesh.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

namespace acute::cli {

namespace {

struct RepairArgs {
  std::string input, features, method = "acute", start = "auto", pictures;
  std::vector<std::string> outputs;
  RepairMeshOptions options;
  bool json = false, exact = false;
};

std::string extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::exists(b, ec) && std::filesystem::equivalent(a, b, ec);
}

/// Feature edges: one "a b" pair of 0-based vertex indices per line; '#' starts a comment.
std::vector<std::array<int, 2>> read_features(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open");
  std::vector<std::array<int, 2>> features;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream ls(line);
    long long a = 0, b = 0;
    if (!(ls >> a)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      throw InvalidInput(path + ":" + std::to_string(number) + ": expected two vertex indices");
    }
    std::string rest;
    if (!(ls >> b) || (ls >> rest) || a < 0 || b < 0 || a > 2147483647 || b > 2147483647 || a == b)
      throw InvalidInput(path + ":" + std::to_string(number) + ": expected two distinct non-negative vertex indices");
    features.push_back({static_cast<int>(a), static_cast<int>(b)});
  }
  return features;
}

/// Appends the edges the input file tags (OBJ polylines) to the features, each pair once; a tagged
/// pair that is not an edge of the mesh is refused naming its line.
void add_tagged_features(const std::string& path, const Mesh& mesh, std::vector<std::array<int, 2>>& features) {
  const std::vector<io::TaggedEdge> tagged = io::read_tagged_edges(path);
  std::set<std::pair<int, int>> have;
  for (const auto& f : features) have.insert(std::minmax(f[0], f[1]));
  for (const auto& t : tagged) {
    const auto [a, b] = t.vertices;
    if (static_cast<std::size_t>(std::max(a, b)) >= mesh.n_vertices() || !mesh.find_halfedge(VertexHandle(a), VertexHandle(b)).is_valid())
      throw InvalidInput(path + ":" + std::to_string(t.line) + ": polyline edge " + std::to_string(a + 1) + "-" + std::to_string(b + 1) +
                         " is not an edge of the mesh");
    if (have.insert(std::minmax(a, b)).second) features.push_back({a, b});
  }
}

int run_repair(RepairArgs args, const GlobalOptions& global) {
  const auto t0 = std::chrono::steady_clock::now();
  RepairMeshOptions& options = args.options;
  const std::string in_ext = extension(args.input);
  const bool domain_input = in_ext == ".json" || in_ext == ".poly";
  if (in_ext == ".json") options.keep_vertices = true;  // a CG:SHOP instance: its points are required
  if (domain_input && !options.keep_vertices)
    throw InvalidInput(args.input + ": a domain, not a mesh: use `acute mesh` (or --keep-vertices)");
  for (const auto& out : args.outputs) {
    if (same_file(args.input, out)) throw IoError(out + ": refusing to overwrite the input file");
    if (extension(out) == ".json") {
      if (!options.keep_vertices) throw InvalidInput(out + ": a CG:SHOP solution needs --keep-vertices");
    } else if (!io::is_mesh_output_path(out)) {
      throw InvalidInput(out + ": unknown output format (use .json .off .obj .ply .node .ele .vtk .vtu .msh .svg)");
    }
  }
  options.method = parse_method(args.method);
  if (args.start == "auto") options.start = RequiredStart::Auto;
  else if (args.start == "cdt") options.start = RequiredStart::Cdt;
  else if (args.start == "refine") options.start = RequiredStart::Refine;
  else if (args.start == "cvt") options.start = RequiredStart::Cvt;
  else throw InvalidInput("unknown --start '" + args.start + "' (expected auto, cdt, refine or cvt)");
  if (!args.features.empty()) {
    if (domain_input) throw InvalidInput("--features needs a mesh input (.off .obj .ply .node .ele)");
    options.features = read_features(args.features);
  }
  io::WarningSink warn = [&](const std::string& w) {
    if (!global.quiet) std::cerr << "acute: warning: " << w << "\n";
  };
  if (!args.pictures.empty()) check_picture_prefix(args.pictures, args.outputs);
  ProgressLine progress(global, t0);
  if (progress.wanted())
    options.progress = [&progress](const RepairMeshProgress& p) { progress.update(p.phase, p.iteration, p.bad); };

  RepairMeshResult result;
  Mesh before;  // for --pictures
  try {
    if (domain_input) {
      Domain domain = io::read_domain(args.input, warn);
      result = repair_required_points(domain, options);
      if (!args.pictures.empty()) before = build_domain_cdt(domain);
    } else {
      const Mesh mesh = io::read_mesh(args.input, warn);
      add_tagged_features(args.input, mesh, options.features);
      result = repair_mesh(mesh, options);
      if (!args.pictures.empty()) {
        before = mesh;
        mark_boundary_constrained(before);
      }
      result.domain.name = std::filesystem::path(args.input).stem().string();
    }
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    if (what.rfind(args.input, 0) == 0) throw;
    throw InvalidInput(args.input + ": " + what);
  }
  progress.finish();
  for (const auto& note : result.notes) warn(note);

  const double max_bound = options.keep_vertices ? (options.allow_right ? 90.000001 : 90.0) : options.max_angle_deg;
  const double min_bound = options.keep_vertices ? 0.0 : options.min_angle_deg;
  io::WriteOptions write_options;
  write_options.min_angle_deg = min_bound;
  write_options.max_angle_deg = max_bound;
  write_options.title = result.domain.name;
  for (const auto& out : args.outputs) {
    if (extension(out) == ".json")
      io::write_cgshop_solution(result.mesh, result.domain, out, &result.exact_coordinates);
    else if ((args.exact || !result.exact_coordinates.empty()) && extension(out) == ".off")
      io::write_off_exact(result.mesh, out, &result.exact_coordinates);
    else
      io::write_mesh(result.mesh, out, write_options);
  }

  RunReport report;
  if (!args.pictures.empty()) report.pictures = write_pictures(args.pictures, before, result.mesh, write_options);

  report.label = "repair";
  report.input = args.input;
  report.status = to_string(result.status);
  report.bounds_not_met = result.status == RepairMeshStatus::BoundsNotMet || result.status == RepairMeshStatus::Cancelled;
  report.bad_summary = std::to_string(result.n_bad) + " bad triangle(s)";
  if (options.keep_vertices) report.bad_summary += ", " + std::to_string(result.n_obtuse_exact) + " exactly obtuse";
  report.remaining = result.remaining;
  report.n_vertices = result.n_vertices;
  report.n_triangles = result.n_triangles;
  report.n_steiner = result.n_steiner;
  report.min_angle = result.min_angle_deg;
  report.max_angle = result.max_angle_deg;
  report.figures = std::to_string(result.n_bad) + " bad";
  report.iterations = result.iterations;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  report.outputs = args.outputs;
  nlohmann::json& j = report.extra;
  j["outputs"] = args.outputs;
  j["mode"] = options.keep_vertices ? "keep_vertices" : "remesh";
  j["min_angle_bound"] = min_bound;
  j["max_angle_bound"] = max_bound;
  j["n_input_vertices"] = result.n_input_vertices;
  j["n_domain_points"] = result.domain.points.size();
  j["n_bad"] = result.n_bad;
  j["n_obtuse_exact"] = result.n_obtuse_exact;
  j["n_right_exact"] = result.n_right_exact;
  if (!result.start.empty()) j["start"] = result.start;
  if (!result.domain.instance_uid.empty()) j["instance_uid"] = result.domain.instance_uid;
  print_report(report, args.json, global);
  return report.bounds_not_met ? BoundsNotMet : Ok;
}

}  // namespace

void add_repair_command(CLI::App& app, const GlobalOptions& global, int& exit_code) {
  auto args = std::make_shared<RepairArgs>();
  auto* cmd = app.add_subcommand("repair", "Make an existing mesh acute, or non-obtuse keeping every vertex");
  cmd->footer(
      "Modes:\n"
      "  default          remesh the region: boundary edges and vertices kept exactly, interior\n"
      "                   vertices may move, go or be added; every angle in [--min-angle, --max-angle)\n"
      "  --keep-vertices  every input vertex stays where it is; Steiner points are added until no\n"
      "                   angle is obtuse (>= 90, or > 90 with --allow-right). CG:SHOP 2025 instances\n"
      "                   (.json) are read in this mode; -o X.json writes a CG:SHOP 2025 solution.\n"
      "Examples:\n"
      "  acute repair ugly.off -o fixed.off\n"
      "  acute repair ugly.obj -o fixed.off --features creases.txt --feature-angle 1\n"
      "  acute repair inst.instance.json -o inst.solution.json -o inst.off --allow-right\n"
      "  acute repair ugly.off -o fixed.off --pictures fix    # fix_before.svg, fix_after.svg and\n"
      "                                                        # fix_before_histogram.svg, fix_after_histogram.svg\n"
      "On a terminal, stderr shows one updating progress line (phase, iteration, bad triangles,\n"
      "elapsed time); never when stderr is a file or pipe, nor with -q.\n"
      "Notes:\n"
      "  --feature-angle drops boundary vertices (and with a non-straight run changes the region):\n"
      "  the output then no longer keeps every boundary vertex, so `meshcheck OUT --domain IN`\n"
      "  reports those vertices as missing; check such output against your own domain.\n"
      "Exit codes: 0 ok, 1 bounds not met (best mesh still written), 2 invalid input, 3 I/O error.");
  cmd->add_option("input", args->input, "Input mesh (.off .obj .ply .node .ele), or with --keep-vertices a domain (.json .poly)")
      ->type_name("INPUT")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->outputs, "Output: a mesh (.off .obj .ply .vtk .vtu .msh .svg ...) or a CG:SHOP solution (.json); repeatable")
      ->type_name("OUT")
      ->required();
  auto* min = cmd->add_option("--min-angle", args->options.min_angle_deg, "Smallest allowed angle (degrees)")->capture_default_str();
  auto* max = cmd->add_option("--max-angle", args->options.max_angle_deg, "Angles must be strictly below this (degrees)")
                  ->capture_default_str();
  auto* feature = cmd->add_option("--feature-angle", args->options.feature_angle_deg,
                                  "Merge boundary runs straighter than this (degrees) into one segment");
  cmd->add_option("--features", args->features, "File of interior edges to keep (vertex index pairs, 0-based); OBJ polylines (l a b ...) in the input are kept too")
      ->type_name("FILE")
      ->check(CLI::ExistingFile);
  auto* keep = cmd->add_flag("--keep-vertices", args->options.keep_vertices, "Keep every input vertex; only remove obtuse angles");
  keep->excludes(min)->excludes(max)->excludes(feature);
  cmd->add_flag("--allow-right", args->options.allow_right, "With --keep-vertices (or .json input): right angles are fine");
  cmd->add_option("--start", args->start, "--keep-vertices start: auto | cdt | refine | cvt")->capture_default_str();
  cmd->add_option("--method", args->method, "Remesh method: cdt | refine | cvt | acute")->capture_default_str();
  auto* size = cmd->add_option("--size", args->options.size, "Target edge length (default: graded by the features, at most the input's mean spacing)");
  cmd->add_option("--vertices", args->options.target_vertices, "Target vertex count (small features that need more get more; under --time-limit T at most the larger of 16 times it and 1,000 T)")->excludes(size);
  cmd->add_option("--seed", args->options.seed, "Random seed (deterministic output)")->capture_default_str();
  cmd->add_option("--max-iterations", args->options.max_iterations, "Repair iteration cap (0: default)");
  cmd->add_option("--max-vertices", args->options.max_vertices, "Vertex budget")->capture_default_str();
  cmd->add_option("--time-limit", args->options.time_limit_s, "Time limit in seconds for the repair (its start included); reading, checking and writing the mesh come on top (0: none)");
  cmd->add_option("--pictures", args->pictures,
                  "Also write PREFIX_before.svg (the input), PREFIX_after.svg and their angle histograms")
      ->type_name("PREFIX");
  cmd->add_flag("--exact", args->exact,
                ".off output: vertices on slanted segments as exact rationals \"p/q\" lying on the segment (meshcheck reads them)");
  cmd->add_flag("--json", args->json, "Print a JSON report on stdout");
  cmd->add_flag("-q,--quiet", const_cast<GlobalOptions&>(global).quiet, "No output but errors");
  cmd->add_flag("-v,--verbose", const_cast<GlobalOptions&>(global).verbose, "Log each phase on stderr (off a terminal also each repair iteration)");
  cmd->callback([args, &global, &exit_code] { exit_code = run_guarded([&] { return run_repair(*args, global); }); });
}

}  // namespace acute::cli
