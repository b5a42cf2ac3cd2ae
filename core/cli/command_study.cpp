// collido study / worker / merge / plugin-info: argument parsing for the study driver
// (study/driver.h), and the worker mode each combination runs in.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>

#include <collido/host/install_layout.h>
#include <collido/io/files.h>
#include <collido/study/driver.h>
#include <collido/study/plugin_probe.h>
#include <collido/study/result_store.h>
#include <collido/study/worker.h>

#include "commands.h"

namespace collido::cli {
namespace {

using study::Combination;
using study::CombinationResult;

// LD_PRELOAD for the allocation hooks, when they were built beside this executable or installed
// with it.
std::vector<std::string> workerEnvironment() {
#ifdef COLLIDO_HEAP_HOOKS_FILE
  for (const std::string& folder : {executableDirectory(), installedLibraryDirectory()}) {
    if (folder.empty()) continue;
    const std::filesystem::path hooks = std::filesystem::path(folder) / COLLIDO_HEAP_HOOKS_FILE;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(hooks, ec)) continue;
    const char* existing = std::getenv("LD_PRELOAD");
    return {"LD_PRELOAD=" + hooks.string() +
            (existing != nullptr && *existing != '\0' ? std::string(":") + existing : "")};
  }
#endif
  return {};
}

int runWorkerMode(const std::string& request_path, const std::string& out_path, int repetitions,
                  const std::string& oracle_directory, const PluginOptions& plugins) {
  const Result<nlohmann::json> json = io::readJsonFile(request_path);
  if (!json.ok()) {
    std::cerr << "error: " << json.status().message() << "\n";
    return 2;
  }
  const Result<Combination> combination = study::combinationFromJson(json.value());
  if (!combination.ok()) {
    std::cerr << "error: " << request_path << ": " << combination.status().message() << "\n";
    return 2;
  }
  study::WorkerRequest request;
  request.combination = combination.value();
  request.plugin_paths = plugins.paths;
  request.default_plugins = !plugins.no_defaults;
  request.repetitions = repetitions;
  request.oracle_directory = oracle_directory;
  request.progress = [](std::size_t done, std::size_t total) {
    std::cout << "progress " << done << " " << total << std::endl;
  };
  Result<CombinationResult> result = study::runCombination(request);
  if (!result.ok()) {
    std::cerr << "error: " << result.status().message() << "\n";
    return 2;
  }
  if (Status s = io::writeFileAtomically(out_path, study::resultToJson(result.value()).dump());
      !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }
  if (!study::failsItsWorker(result.value())) return 0;
  for (const std::string& problem : result.value().problems)
    std::cerr << "error: " << problem << "\n";
  return 1;
}

// `collido study`: its options and its run.
void addStudyCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code) {
  CLI::App* command = app.add_subcommand(
      "study",
      "Run every combination of scenes x backend settings x sweep in worker processes, each "
      "answer checked against the exact oracle; a crash or hang costs one combination. Writes "
      "OUT/table.txt, OUT/records.jsonl, OUT/summary.json (Google Benchmark format) and "
      "OUT/results/. Exit code: 0 done, 2 bad input, 130 interrupted (resume with --resume)");
  auto args = std::make_shared<study::StudyRequest>();
  auto robot = std::make_shared<RobotInputOptions>();
  command->add_option("scenes", args->scenes,
                      "scene files (JSON), robots (URDF, with --trajectory and --environment), "
                      "or mesh files (any other extension): scenes of the robots and meshes are "
                      "written into OUT/scenes, the meshes' run with the default sweep unless "
                      "--sweep is given");
  addRobotInputOptions(*command, *robot);
  command->add_option("--surfaces", args->surface_files,
                      "NURBS surface files, each compared as collido surface-distance does: the "
                      "seed method and every backend setting in workers of their own (the "
                      "sweep's \"surfaces\" names the settings and tessellations)");
  command->add_option("--frep", args->frep_files,
                      "FRep files, each compared as collido frep does: the seed method and every "
                      "backend setting in workers of their own (the sweep's \"frep\" names the "
                      "settings and polygonization resolutions)");
  command
      ->add_option("--backends", args->backends,
                   "backends, NAME or NAME[key=value;...]; with --sweep, only these variants")
      ->delimiter(',');
  command->add_option("--sweep", args->sweep_path, "sweep file (JSON; docs/STUDY.md)");
  command->add_option("--out", args->out, "study folder")->required();
  command->add_flag("--resume", args->resume,
                    "continue the study in --out, skipping combinations already stored");
  command->add_flag("--retry-failed", args->retry_failed,
                    "with --resume, also run again combinations that crashed, failed or timed out");
  command->add_option("--shard", args->shard,
                      "run only part I of N (0 <= I < N), e.g. $SLURM_ARRAY_TASK_ID/4");
  command
      ->add_option("--oracle-store", args->oracle_directory,
                   "keep the exact oracle's answers in this folder (default: OUT/oracle); "
                   "shards given one folder on a shared filesystem reuse each other's")
      ->check(CLI::ExistingDirectory | CLI::NonexistentPath);
  command
      ->add_option("--timeout", args->timeout_s,
                   "seconds a combination may run before its worker is killed (default: the "
                   "sweep's timeout_s, else 600)")
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--repetitions", args->repetitions,
                   "timed calls per frame and query (default: the sweep's, else 5)")
      ->check(CLI::Range(1, 1000000));
  command->add_flag("--quiet", args->quiet, "no progress on stderr");
  command
      ->add_option("--plugin-timeout", args->plugin_timeout_s,
                   "seconds a plugin may take to load, in a process of its own, before it counts "
                   "as hanging and is skipped (default 30)")
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--protocol", args->protocol,
                   "timing protocol: cycled (each timed call on another frame than the last, the "
                   "default) or repeated (each frame's calls back to back; docs/STUDY.md)")
      ->check(CLI::IsMember({"repeated", "cycled"}));
  command
      ->add_option("--rounds", args->rounds,
                   "timing rounds: each scene combination runs this many times, each in a worker "
                   "of its own, and its timed calls are joined (default: the sweep's, else 1)")
      ->check(CLI::Range(1, 100));
  command
      ->add_option("--adaptive-seconds", args->adaptive_s,
                   "after the planned rounds, seconds to spend on extra rounds (up to 3) for "
                   "combinations whose rounds cannot pin a figure down to within 10% (default: "
                   "the sweep's adaptive_s, else 0)")
      ->check(nonNegativeNumber());
  command->add_option("--order-seed", args->order_seed,
                      "the seed of the random order combinations and rounds run in (recorded in "
                      "plan.json)");
  command->add_option("--expected-times", args->expected_times,
                      "an earlier study folder or its times.json: the expected time printed at "
                      "the start and the progress estimate come from its wall times");
  command->callback([args, robot, &plugins, &exit_code] {
    if (thisExecutable().empty()) {
      std::cerr << "error: cannot find this program's own path (/proc/self/exe) to start the "
                   "workers\n";
      exit_code = 2;
      return;
    }
    study::StudyRequest request = *args;
    if (Status s = importRobotInputs(request.scenes, *robot, request.out, std::cerr); !s.ok()) {
      std::cerr << "error: " << s.message() << "\n";
      exit_code = 2;
      return;
    }
    request.executable = thisExecutable();
    request.worker_environment = workerEnvironment();
    request.plugin_paths = plugins.paths;
    request.default_plugins = !plugins.no_defaults;
    request.interactive = isatty(STDERR_FILENO) != 0;
    exit_code = study::runStudy(request, std::cout, std::cerr);
  });
}

// Internal: one plugin loaded in a process of its own, its variants reported (the study's probe).
void addPluginInfoCommand(CLI::App& app, int& exit_code) {
  CLI::App* info = app.add_subcommand("plugin-info", "");  // internal: one plugin, probed
  info->group("");
  auto info_file = std::make_shared<std::string>();
  auto info_out = std::make_shared<std::string>();
  auto info_settings = std::make_shared<std::vector<std::string>>();
  info->add_option("file", *info_file)->required();
  info->add_option("--out", *info_out)->required();
  info->add_option("--setting", *info_settings);  // backend texts, each created
  info->callback([info_file, info_out, info_settings, &exit_code] {
    Result<std::shared_ptr<PluginLibrary>> plugin = PluginLibrary::open(*info_file);
    if (!plugin.ok()) {
      std::cerr << "error: " << plugin.status().message() << "\n";
      exit_code = 2;
      return;
    }
    const Status written = io::writeFileAtomically(
        *info_out, study::pluginInfoJson(plugin.value(), *info_settings).dump());
    if (!written.ok()) std::cerr << "error: " << written.message() << "\n";
    exit_code = written.ok() ? 0 : 2;
  });
}

// Internal: one combination, run in a worker process the study started.
void addWorkerCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code) {
  CLI::App* worker = app.add_subcommand("worker", "");  // internal: one combination
  worker->group("");
  auto request = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto repetitions = std::make_shared<int>(5);
  auto oracle_directory = std::make_shared<std::string>();
  worker->add_option("--request", *request)->required();
  worker->add_option("--out", *out)->required();
  worker->add_option("--repetitions", *repetitions);
  worker->add_option("--oracle-cache", *oracle_directory);
  worker->callback([request, out, repetitions, oracle_directory, &plugins, &exit_code] {
    exit_code = runWorkerMode(*request, *out, *repetitions, *oracle_directory, plugins);
  });
}

// `collido merge`: the folders of a sharded study joined into one.
void addMergeCommand(CLI::App& app, int& exit_code) {
  CLI::App* merge = app.add_subcommand(
      "merge",
      "Join the folders of a sharded study (collido study --shard I/N) into one, with its "
      "table, records and summary");
  auto merge_out = std::make_shared<std::string>();
  auto inputs = std::make_shared<std::vector<std::string>>();
  merge->add_option("inputs", *inputs, "study folders to join")->required();
  merge->add_option("--out", *merge_out, "the joined study folder")->required();
  auto replace = std::make_shared<bool>(false);
  merge->add_flag("--replace", *replace,
                  "when --out already holds a study, replace it (else that is refused)");
  merge->callback([merge_out, inputs, replace, &exit_code] {
    exit_code = study::mergeStudies(*merge_out, *inputs, *replace, std::cout, std::cerr);
  });
}

}  // namespace

void addStudyCommands(CLI::App& app, const PluginOptions& plugins, int& exit_code) {
  addStudyCommand(app, plugins, exit_code);
  addPluginInfoCommand(app, exit_code);
  addWorkerCommand(app, plugins, exit_code);
  addMergeCommand(app, exit_code);
}

}  // namespace collido::cli
