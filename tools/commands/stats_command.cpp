#include "commands/commands.h"
namespace acute::cli {
void add_stats_command(CLI::App& app, const GlobalOptions&, int&) { app.add_subcommand("stats", "(not yet implemented)"); }
}  // namespace acute::cli
