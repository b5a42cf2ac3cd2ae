// collido: the command-line front of Collidoscope.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{
      "Collidoscope: compares collision-detection backends on hard geometry, every answer "
      "checked against an exact reference."};
  app.require_subcommand(1);
  app.fallthrough();  // --plugin may come after the subcommand too
  collido::cli::PluginOptions plugins;
  app.add_option("--plugin", plugins.paths,
                 "plugin file or folder to load before the default places (repeatable)");
  app.add_flag("--no-default-plugins", plugins.no_defaults,
               "load only plugins given with --plugin (not the build tree, install folder or "
               "COLLIDO_PLUGIN_PATH)");
  // Set in the environment, so that worker processes inherit the same limit.
  app.add_option_function<unsigned long long>(
         "--max-input-mb",
         [](unsigned long long mebibytes) {
           setenv("COLLIDO_MAX_INPUT_MB", std::to_string(mebibytes).c_str(), 1);
         },
         "largest input file (scene, mesh, sweep, ...) read, in MiB (default: "
         "$COLLIDO_MAX_INPUT_MB, else 1024)")
      ->check(CLI::PositiveNumber);
  int exit_code = 0;
  collido::cli::addBackendsCommand(app, plugins, exit_code);
  collido::cli::addCheckCommand(app, exit_code);
  collido::cli::addPlaceCommand(app, exit_code);
  collido::cli::addPoseErrorCommand(app, exit_code);
  collido::cli::addTracksCommand(app, exit_code);
  collido::cli::addRecordCloseCommand(app, exit_code);
  collido::cli::addImportCommand(app, exit_code);
  collido::cli::addSurfaceDistanceCommand(app, plugins, exit_code);
  collido::cli::addFrepCommand(app, plugins, exit_code);
  collido::cli::addRunCommand(app, plugins, exit_code);
  collido::cli::addConformanceCommand(app, exit_code);
  collido::cli::addStudyCommands(app, plugins, exit_code);
  collido::cli::addReportCommand(app, exit_code);
  collido::cli::addCompareCommand(app, exit_code);
  collido::cli::addViewCommands(app, plugins, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end with 0; any other parse error is bad input, exit 2 as documented
    // (CLI11's own codes, e.g. 105 for a failed check, named no contract).
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const std::exception& e) {
    std::cerr << "collido: " << e.what() << "\n";
    return 2;
  }
  return exit_code;
}
