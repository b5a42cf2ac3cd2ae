// collido compare: the times of two studies (or two summary.json files) row by row, each row
// faster, slower or the same, decided by the ratio's 95% interval against the equivalence band.
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/study/result_store.h>
#include <collido/study/time_changes.h>

#include "commands.h"

namespace collido::cli {
namespace {

struct CompareArguments {
  std::string before;
  std::string now;
  std::string json;  ///< "" for none
  bool fail_on_slower = false;
};

bool isStudyFolder(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_directory(std::filesystem::path(path) / "results", ec);
}

// A summary.json, given as the file or as the study folder that holds it.
Result<nlohmann::json> readSummary(const std::string& path) {
  std::error_code ec;
  const std::string file = std::filesystem::is_directory(path, ec)
                               ? (std::filesystem::path(path) / "summary.json").string()
                               : path;
  if (!std::filesystem::exists(file, ec)) {
    return Status(StatusCode::kInvalidArgument,
                  file + ": not found (give two study folders or two summary.json files)");
  }
  return io::readJsonFile(file);
}

// Both study folders: intervals from their timed calls, paired by frame. Otherwise their
// summary.json files' intervals.
Result<std::vector<study::TimeChange>> changesBetween(const std::string& before,
                                                      const std::string& now) {
  if (isStudyFolder(before) && isStudyFolder(now)) {
    Result<std::vector<study::CombinationResult>> then = readStudy(before);
    if (!then.ok()) return then.status();
    Result<std::vector<study::CombinationResult>> current = readStudy(now);
    if (!current.ok()) return current.status();
    return study::timeChanges(then.value(), current.value());
  }
  Result<nlohmann::json> then = readSummary(before);
  if (!then.ok()) return then.status();
  Result<nlohmann::json> current = readSummary(now);
  if (!current.ok()) return current.status();
  return study::summaryTimeChanges(then.value(), before, current.value(), now);
}

int runCompare(const CompareArguments& args) {
  Result<std::vector<study::TimeChange>> changes = changesBetween(args.before, args.now);
  if (!changes.ok()) {
    std::cerr << "error: " << changes.status().message() << "\n";
    return 2;
  }
  if (changes.value().empty()) {
    std::cerr << "error: " << args.before << " and " << args.now
              << " share no measured setting, scene and query\n";
    return 2;
  }
  std::cout << study::timeChangesText(changes.value());
  if (!args.json.empty()) {
    const Status written =
        io::writeFileAtomically(args.json, study::timeChangesJson(changes.value()).dump(1) + "\n");
    if (!written.ok()) {
      std::cerr << "error: " << written.message() << "\n";
      return 2;
    }
  }
  for (const study::TimeChange& change : changes.value()) {
    if (args.fail_on_slower && change.change == study::Change::kSlower) return 1;
  }
  return 0;
}

}  // namespace

void addCompareCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CompareArguments>();
  CLI::App* command = app.add_subcommand(
      "compare",
      "Compare the times of two studies row by row (like Google Benchmark's compare.py): each "
      "(setting, scene, query) in both gets now/before with its 95% interval and a verdict, "
      "faster, slower or same; only an interval wholly beyond the 10% equivalence band is a "
      "change. Exit code: 0 done, 1 a row slower with --fail-on-slower, 2 bad input");
  command->add_option("BEFORE", args->before, "the baseline: a study folder or its summary.json")
      ->required();
  command->add_option("NOW", args->now, "the study to judge: a study folder or its summary.json")
      ->required();
  command->add_option("--json", args->json, "also write the rows and counts as JSON to this file");
  command->add_flag("--fail-on-slower", args->fail_on_slower,
                    "exit with 1 when some row is slower (for a CI gate)");
  command->callback([args, &exit_code] { exit_code = runCompare(*args); });
}

}  // namespace collido::cli
