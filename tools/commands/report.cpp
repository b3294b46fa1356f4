#include "commands/report.h"

#include <cstdio>
#include <iostream>

namespace acute::cli {

void print_report(const RunReport& r, bool json, const GlobalOptions& global) {
  if (r.bounds_not_met && !global.quiet) {
    std::cerr << "acute: bounds not met: " << r.bad_summary << " remain, e.g.\n";
    print_bad_triangles(r.remaining);
  }
  if (json) {
    nlohmann::json j = r.extra;
    j["input"] = r.input;
    j["status"] = r.status;
    j["n_vertices"] = r.n_vertices;
    j["n_triangles"] = r.n_triangles;
    j["n_steiner"] = r.n_steiner ? nlohmann::json(*r.n_steiner) : nlohmann::json(nullptr);
    j["min_angle"] = r.min_angle;
    j["max_angle"] = r.max_angle;
    j["iterations"] = r.iterations;
    j["seconds"] = r.seconds;
    if (!r.pictures.empty()) j["pictures"] = r.pictures;
    std::cout << j.dump(2) << "\n";
    return;
  }
  if (global.quiet) return;
  std::string steiner = r.n_steiner ? " (" + std::to_string(*r.n_steiner) + " Steiner)" : std::string();
  std::string outputs;
  for (const auto& out : r.outputs) outputs += (outputs.empty() ? " -> " : ", ") + out;
  std::printf("%s: %zu vertices%s, %zu triangles, angles %.4f..%.4f deg, %s, %d iterations, %.3f s%s\n", r.label.c_str(),
              r.n_vertices, steiner.c_str(), r.n_triangles, r.min_angle, r.max_angle, r.figures.c_str(), r.iterations,
              r.seconds, outputs.c_str());
  for (const auto& p : r.pictures) std::printf("  picture %s\n", p.c_str());
}

}  // namespace acute::cli
