#include "commands/commands.h"
namespace acute::cli {
void add_mesh_command(CLI::App& app, const GlobalOptions&, int&) { app.add_subcommand("mesh", "(not yet implemented)"); }
}  // namespace acute::cli
