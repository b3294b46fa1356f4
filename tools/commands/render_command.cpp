#include "commands/commands.h"
namespace acute::cli {
void add_render_command(CLI::App& app, const GlobalOptions&, int&) { app.add_subcommand("render", "(not yet implemented)"); }
}  // namespace acute::cli
