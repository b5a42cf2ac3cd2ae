#pragma once

#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <collido/status.h>
#include <collido/study/result_store.h>

namespace collido::cli {

/// Plugin search options shared by the subcommands.
struct PluginOptions {
  std::vector<std::string> paths;  ///< --plugin: files or folders searched first
  bool no_defaults = false;        ///< --no-default-plugins
};

/// This executable's path (to start child processes of it), "" when it cannot be found.
std::string thisExecutable();

/// The plugin options as arguments for a child process of this executable (paths absolute).
std::vector<std::string> pluginArguments(const PluginOptions& plugins);

/// A study folder's results (rounds joined), or an error naming the folder when it holds none.
Result<std::vector<study::CombinationResult>> readStudy(const std::string& directory);

/// Each add*Command registers a subcommand whose callback runs it and stores its exit code.
void addBackendsCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code);
void addCheckCommand(CLI::App& app, int& exit_code);
void addPlaceCommand(CLI::App& app, int& exit_code);
void addPoseErrorCommand(CLI::App& app, int& exit_code);
void addTracksCommand(CLI::App& app, int& exit_code);
void addRecordCloseCommand(CLI::App& app, int& exit_code);
void addImportCommand(CLI::App& app, int& exit_code);
void addSurfaceDistanceCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code);
void addFrepCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code);
void addRunCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code);
void addConformanceCommand(CLI::App& app, int& exit_code);
/// study, merge, and the internal worker mode the study starts.
void addReportCommand(CLI::App& app, int& exit_code);
/// compare: two studies' times, row by row, with a verdict per row.
void addCompareCommand(CLI::App& app, int& exit_code);
void addViewCommands(CLI::App& app, const PluginOptions& plugins, int& exit_code);
void addStudyCommands(CLI::App& app, const PluginOptions& plugins, int& exit_code);

/// What `collido study` imports a URDF among its scenes with (collido/urdf/urdf_import.h).
struct RobotInputOptions {
  std::string trajectory;                ///< joints CSV; "": seeded random configurations
  std::vector<std::string> environment;  ///< FILE or FILE@X,Y,Z[,ROLL,PITCH,YAW]
};

/// Registers --trajectory and --environment on `command`.
void addRobotInputOptions(CLI::App& command, RobotInputOptions& options);

/// Each URDF among `scenes` imported into OUT/scenes/<its stem>.json and replaced by that scene;
/// fails naming the file, or when the options are given without a URDF.
Status importRobotInputs(std::vector<std::string>& scenes, const RobotInputOptions& options,
                         const std::string& out, std::ostream& err);

/// An option that takes a number >= 0. Its error names the value given (CLI11's own
/// NonNegativeNumber prints its range up to the largest double).
inline CLI::Validator nonNegativeNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return text + " is not a number";
        return value >= 0.0 ? std::string() : text + " is negative: give a number >= 0";
      },
      "NUMBER >= 0", "NONNEGATIVE");
}

}  // namespace collido::cli
