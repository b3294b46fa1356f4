// acute: make 2D triangle meshes with every angle in [30, 90) degrees, and report on meshes.
#include "commands/commands.h"

int main(int argc, char** argv) {
  using namespace acute::cli;
  CLI::App app{"acute: 2D triangle meshes with no obtuse and no small angles"};
  app.require_subcommand(1);
  app.footer(
      "Run `acute SUBCOMMAND --help` for its options.\n\n"
      "Examples:\n"
      "  acute mesh meshes/A.poly -o A.off                  # every angle in [30, 90)\n"
      "  acute mesh meshes/A.poly -o A.vtu --vertices 20000 --dual A_dual.vtu\n"
      "  acute repair ugly.off -o fixed.off --pictures fix  # fix_before.svg, fix_after.svg, histograms\n"
      "  acute stats A.off --domain meshes/A.poly --histogram\n"
      "  acute render A.off -o A.svg --domain meshes/A.poly\n"
      "  acute render A.off -o A_hist.svg --histogram\n\n"
      "Exit codes: 0 ok, 1 bounds not met (best mesh still written), 2 invalid input, 3 I/O error.");
  app.set_version_flag("--version", std::string("acute 0.1.0"));
  GlobalOptions global;
  int exit_code = ExitCode::Ok;
  add_mesh_command(app, global, exit_code);
  add_repair_command(app, global, exit_code);
  add_stats_command(app, global, exit_code);
  add_render_command(app, global, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : ExitCode::InvalidInputCode;
  }
  return exit_code;
}
