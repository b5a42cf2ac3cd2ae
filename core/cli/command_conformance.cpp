// collido conformance PLUGIN.so: runs the conformance kit (the collido_conformance executable
// beside this one) against one plugin file, shows each check as it ends, and prints a
// pass/skip/fail table with every failure of every check.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <collido/host/plugin_library.h>
#include <collido/study/conformance_report.h>
#include <collido/study/worker_process.h>

#include "commands.h"

namespace collido::cli {
namespace {

namespace fs = std::filesystem;

struct ConformanceArguments {
  std::string plugin;
  std::string expectations_dir;
  std::string write_expectations_dir;
  std::string scenes_dir;
  std::string variant;
  std::string log;  // where to keep the kit's own output ("": not kept)
};

// Runs the kit with its progress lines shown as they come and its stderr into `log`; returns
// its exit status, or -signal.
int runKit(const std::string& kit, const std::vector<std::string>& arguments,
           const std::string& log) {
  study::WorkerLaunch launch;
  launch.executable = kit;
  launch.arguments = arguments;
  launch.log_path = log;
  launch.on_line = [](const std::string& line) { std::cout << line << std::endl; };
  std::cout.flush();
  const study::WorkerOutcome outcome = study::runWorkerProcess(launch);
  return outcome.signal != 0 ? -outcome.signal : outcome.exit_code;
}

int runConformance(const ConformanceArguments& args) {
  const std::string here = executableDirectory();
  const std::string kit = (here.empty() ? std::string(".") : here) + "/collido_conformance";
  if (!fs::exists(kit)) {
    std::cerr << "error: the conformance kit is not built (" << kit
              << "); build it with cmake --build <build folder> --target collido_conformance "
                 "(tools/study.sh does)\n";
    return 2;
  }
  std::error_code ec;
  const fs::path work =
      fs::temp_directory_path() / ("collido_conformance_" + std::to_string(getpid()));
  fs::create_directories(work, ec);
  const std::string json = (work / "report.json").string();
  const std::string log = (work / "kit.log").string();
  std::vector<std::string> argv = {"--plugin=" + fs::absolute(args.plugin).string(),
                                   "--gtest_output=json:" + json, "--progress"};
  if (!args.expectations_dir.empty()) argv.push_back("--expectations-dir=" + args.expectations_dir);
  if (!args.write_expectations_dir.empty()) {
    argv.push_back("--write-expectations-dir=" + args.write_expectations_dir);
  }
  if (!args.scenes_dir.empty()) argv.push_back("--scenes-dir=" + args.scenes_dir);
  if (!args.variant.empty()) argv.push_back("--variant=" + args.variant);
  // The command runs the whole kit. GoogleTest takes its sharding from the environment, where a
  // test harness that runs this command in one of its own shards (CTest's sanitizer suites do)
  // leaves it: the kit would run one shard of its checks and report the rest as never there.
  unsetenv("GTEST_TOTAL_SHARDS");
  unsetenv("GTEST_SHARD_INDEX");
  const int status = runKit(kit, argv, log);
  const std::vector<study::ConformanceRow> rows = study::readConformanceReport(json);
  // The kit's own output is kept only where asked; the folder goes either way.
  std::string kept_log;
  if (!args.log.empty()) {
    fs::copy_file(log, args.log, fs::copy_options::overwrite_existing, ec);
    if (!ec) kept_log = args.log;
  }
  const auto clean_up = [&work] {
    std::error_code ignored;
    fs::remove_all(work, ignored);
  };
  if (rows.empty()) {
    std::ifstream in(log);
    std::cerr << "error: the kit produced no report (exit " << status << "):\n" << in.rdbuf();
    clean_up();
    return status < 0 ? 1 : (status == 0 ? 1 : status);
  }
  clean_up();
  std::cout << study::conformanceTable(rows)
            << (kept_log.empty() ? "" : "; the kit's output: " + kept_log) << "\n";
  const bool failed = std::any_of(
      rows.begin(), rows.end(), [](const study::ConformanceRow& r) { return r.result == "FAIL"; });
  if (status < 0) std::cout << "the kit died of signal " << -status << "\n";
  return !failed && status == 0 ? 0 : 1;
}

}  // namespace

void addConformanceCommand(CLI::App& app, int& exit_code) {
  CLI::App* command = app.add_subcommand(
      "conformance",
      "Run the plugin conformance kit against a plugin file and print a pass/skip/fail table. "
      "Answers must match the exact oracle unless an expectations file records the known "
      "disagreements (see tests/conformance/README.md)");
  auto args = std::make_shared<ConformanceArguments>();
  command->add_option("plugin", args->plugin, "the plugin shared library")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--expectations-dir", args->expectations_dir,
                      "folder of <variant>.json files recording accepted disagreements");
  command->add_option("--write-expectations-dir", args->write_expectations_dir,
                      "write the measured disagreements there, for review");
  command->add_option("--scenes-dir", args->scenes_dir, "scenes to run (default: the bundled)");
  command->add_option("--variant", args->variant,
                      "test only this variant of the plugin, NAME or 'NAME[key=value;...]' with "
                      "backend options");
  command->add_option("--log", args->log, "keep the kit's own output (GoogleTest's) in this file");
  command->callback([args, &exit_code] { exit_code = runConformance(*args); });
}

}  // namespace collido::cli
