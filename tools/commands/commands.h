// The subcommands of the `acute` program. Each registers itself on the app and runs through
// run_guarded(), which maps exceptions to the documented exit codes.
#pragma once

#include <acute/mesher.h>

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace acute::cli {

/// Exit codes of the `acute` program.
enum ExitCode : int { Ok = 0, BoundsNotMet = 1, InvalidInputCode = 2, IoErrorCode = 3, InternalErrorCode = 4 };

/// Options shared by every subcommand.
struct GlobalOptions {
  bool quiet = false;
  bool verbose = false;
};

/// Prints the first few bad triangles left, one line each, on stderr.
void print_bad_triangles(const std::vector<BadTriangle>& remaining);

/// Runs body; prints "acute: <message>" on one line for a libacute exception and returns the code.
int run_guarded(const std::function<int()>& body);

void add_stats_command(CLI::App& app, const GlobalOptions& global, int& exit_code);
void add_render_command(CLI::App& app, const GlobalOptions& global, int& exit_code);
void add_mesh_command(CLI::App& app, const GlobalOptions& global, int& exit_code);
void add_repair_command(CLI::App& app, const GlobalOptions& global, int& exit_code);

}  // namespace acute::cli
