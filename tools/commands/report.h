// The end of `acute mesh` and `acute repair`: the "bounds not met" message, then one JSON object
// on stdout (--json) or one summary line (unless -q). The keys both commands share are written
// here; each command adds its own in `extra`.
#pragma once

#include "commands/commands.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace acute::cli {

struct RunReport {
  std::string label;                    ///< first word of the summary line ("acute", "repair")
  std::string input;
  std::string status;                   ///< "ok", "bounds_not_met", ...
  bool bounds_not_met = false;
  std::string bad_summary;              ///< "12 bad triangle(s)" for the not-met message
  std::vector<BadTriangle> remaining;   ///< examples for the not-met message
  std::size_t n_vertices = 0, n_triangles = 0;
  std::optional<std::size_t> n_steiner;
  double min_angle = 0, max_angle = 0;
  std::string figures;                  ///< command-specific part of the summary line
  int iterations = 0;
  double seconds = 0;
  std::vector<std::string> outputs;     ///< shown after "->" on the summary line
  std::vector<std::string> pictures;    ///< --pictures files written
  nlohmann::json extra = nlohmann::json::object();  ///< command-specific JSON keys
};

void print_report(const RunReport& report, bool json, const GlobalOptions& global);

}  // namespace acute::cli
