// collido conformance PLUGIN.so: runs the conformance kit (the collido_conformance executable
// beside this one) against one plugin file, shows each check as it ends, and prints a
// pass/skip/fail table with every failure of every check.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/host/plugin_library.h>
#include <collido/io/files.h>
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

// A failure message without GoogleTest's "file:line" and "Failed" lines, one string per line.
std::vector<std::string> messageLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const bool location = line.rfind('/', 0) == 0 && line.find(' ') == std::string::npos;
    if (!line.empty() && !location && line != "Failed") out.push_back(line);
  }
  if (out.empty()) out.push_back(text);
  return out;
}

struct Row {
  std::string check;
  std::string result;
  std::string detail;
  std::vector<std::string> more;  ///< the lines of every further failure message
};

std::vector<Row> readReport(const std::string& path) {
  std::vector<Row> rows;
  // No report, or a broken one (the kit crashed while writing it): no rows, and the caller shows
  // the kit's log instead.
  const Result<nlohmann::json> read = io::readJsonFile(path);
  if (!read.ok()) return rows;
  const nlohmann::json& report = read.value();
  for (const auto& suite : report.value("testsuites", nlohmann::json::array())) {
    for (const auto& test : suite.value("testsuite", nlohmann::json::array())) {
      Row row;
      std::string suite_name = suite.value("name", "");
      if (const auto slash = suite_name.find('/'); slash != std::string::npos) {
        suite_name = suite_name.substr(slash + 1);
      }
      row.check = suite_name + "." + test.value("name", "");
      if (test.contains("failures")) {
        row.result = "FAIL";
        // Every failure of the check (a scene reports each query that failed), in full.
        for (const auto& failure : test["failures"]) {
          for (const std::string& line : messageLines(failure.value("failure", ""))) {
            if (row.detail.empty()) {
              row.detail = line;
            } else {
              row.more.push_back(line);
            }
          }
        }
      } else if (test.value("result", "") == "SKIPPED") {
        row.result = "skip";
        row.detail = test.value("detail", "");
      } else {
        row.result = "pass";
        row.detail = test.value("detail", "");
      }
      rows.push_back(row);
    }
  }
  return rows;
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
  const std::vector<Row> rows = readReport(json);
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
  std::size_t width = 5;
  for (const Row& r : rows)
    width = std::max(width, r.check.size());
  std::map<std::string, int> totals;
  std::cout << std::string("check") + std::string(width - 5, ' ') << "  result  detail\n";
  for (const Row& r : rows) {
    ++totals[r.result];
    std::cout << r.check << std::string(width - r.check.size(), ' ') << "  " << r.result
              << std::string(6 - r.result.size(), ' ') << "  " << r.detail << "\n";
    for (const std::string& line : r.more)
      std::cout << std::string(width + 10, ' ') << line << "\n";
  }
  std::cout << "\n"
            << totals["pass"] << " passed, " << totals["skip"] << " skipped, " << totals["FAIL"]
            << " failed" << (kept_log.empty() ? "" : "; the kit's output: " + kept_log) << "\n";
  if (status < 0) std::cout << "the kit died of signal " << -status << "\n";
  return totals["FAIL"] == 0 && status == 0 ? 0 : 1;
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
