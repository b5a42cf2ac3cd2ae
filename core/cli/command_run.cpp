#include <unistd.h>

#include <csignal>
#include <iostream>

#include <collido/io/files.h>
#include <collido/runner/runner.h>
#include <collido/study/oracle_store.h>
#include <collido/study/result_store.h>

#include "commands.h"

namespace collido::cli {
namespace {

struct RunArguments {
  std::vector<std::string> scenes;
  std::vector<std::string> backends;
  std::string json_path;
  std::string oracle_directory;
  int repetitions = 5;
  std::string protocol = "repeated";
  bool quiet = false;
  bool fail_on_disagreement = false;
  bool reuse_unchanged = false;
  bool skip_apart = false;
};

// collido run keeps every backend in this process (one scene loaded once, answers compared in
// memory); a crashing engine therefore ends the run. Say so, and where the isolation is, before
// the signal takes its default course.
extern "C" void explainCrash(int signal) {
  static const char kMessage[] =
      "\ncollido run: a backend crashed; collido run keeps every backend in this one process, so "
      "this run's results are lost (the progress lines above name the backend that was "
      "running). collido study runs each backend in a worker process of its own, where a crash "
      "costs one combination.\n";
  (void)!write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  std::raise(signal);  // the handler was reset (SA_RESETHAND): the default action ends the process
}

void explainCrashes() {
#if defined(__SANITIZE_ADDRESS__)
  return;  // AddressSanitizer's own report of the crash says more
#endif
  struct sigaction action {};
  action.sa_handler = explainCrash;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
    sigaction(signal, &action, nullptr);
}

int run(const RunArguments& args, const PluginOptions& plugin_options) {
  std::vector<Scene> scenes;
  SceneLoadOptions load;
  if (!args.oracle_directory.empty()) load.placement_store = args.oracle_directory + "/placements";
  for (const std::string& path : args.scenes) {
    Result<Scene> scene = loadScene(path, load);
    if (!scene.ok()) {
      std::cerr << "error: " << scene.status().message() << "\n";
      return 2;
    }
    scenes.push_back(std::move(scene).value());
  }
  const PluginDiscovery found = discoverPlugins(plugin_options.paths, !plugin_options.no_defaults);
  for (const std::string& problem : found.problems)
    std::cerr << "warning: " << problem << "\n";
  std::vector<std::string> names = args.backends;
  if (names.empty()) {
    for (const auto& plugin : found.plugins) {
      for (const VariantInfo& v : plugin->variants())
        names.push_back(v.name);
    }
  }
  Result<std::vector<BackendSpec>> specs = resolveBackends(names, found.plugins);
  if (!specs.ok()) {
    std::cerr << "error: " << specs.status().message() << "\n";
    return 2;
  }
  if (specs.value().empty()) {
    std::cerr << "error: no backends to run (build the plugins or pass --plugin)\n";
    return 2;
  }
  RunOptions options;
  options.repetitions = args.repetitions;
  options.protocol = parseTimingProtocol(args.protocol).value_or(TimingProtocol::kRepeated);
  options.reuse_unchanged = args.reuse_unchanged;
  options.skip_apart_pairs = args.skip_apart;
  if (!args.quiet) options.progress = [](const std::string& line) { std::cerr << line << "\n"; };
  // runScenes, with each scene's oracle answers read from and kept in the store when one is named.
  RunReport report;
  explainCrashes();
  for (const Scene& scene : scenes) {
    OracleCache oracle(scene);
    const study::StoredOracle stored(args.oracle_directory, oracle);
    runSceneOnBackends(scene, specs.value(), options, oracle, report);
    stored.keepNew();
  }
  std::cout << formatRunTable(report);
  if (!args.json_path.empty()) {
    // The study's atomic write: a reader never sees half a report.
    if (Status s = io::writeFileAtomically(args.json_path, runReportJson(report) + "\n"); !s.ok()) {
      std::cerr << "error: " << s.message() << "\n";
      return 2;
    }
  }
  bool failed = !report.problems.empty();
  bool disagreed = false;
  for (const QueryMeasurement& m : report.measurements) {
    failed = failed || m.status.failed();
    disagreed = disagreed || m.disagreements != 0;
  }
  if (failed) return 1;
  return args.fail_on_disagreement && disagreed ? 3 : 0;
}

}  // namespace

void addRunCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code) {
  CLI::App* command = app.add_subcommand(
      "run",
      "Run the scenes' queries on backends, check every answer against the exact oracle, and "
      "print time, error and memory per backend, scene and query. Every backend runs in this "
      "process, so a crashing engine ends the run: collido study isolates each in a worker. Exit "
      "code: 0 ok, 1 a backend failed, 2 bad input, 3 disagreement with --fail-on-disagreement");
  auto args = std::make_shared<RunArguments>();
  command->add_option("scenes", args->scenes, "scene files (JSON)")->required();
  command
      ->add_option("--backends", args->backends,
                   "backends to run, NAME or NAME[key=value;...] (default: every variant found)")
      ->delimiter(',');
  command->add_option("--json", args->json_path, "also write the results, per frame, as JSON");
  command
      ->add_option("--oracle-cache", args->oracle_directory,
                   "keep the exact answers in this folder (a study's store): answers stored "
                   "there for an identical scene are read, not computed, and new ones added")
      ->check(CLI::ExistingDirectory | CLI::NonexistentPath);
  command
      ->add_option("--protocol", args->protocol,
                   "timing protocol: repeated (each frame's calls back to back, the default) or "
                   "cycled (each timed call on another frame than the last; docs/STUDY.md)")
      ->check(CLI::IsMember({"repeated", "cycled"}));
  command->add_option("--repetitions", args->repetitions, "timed calls per frame and query")
      ->check(CLI::Range(1, 1000000));
  command->add_flag("--reuse-unchanged", args->reuse_unchanged,
                    "answer an object pair with its answer of the frame before when neither "
                    "object moved, changed state or deformed (still checked against the oracle)");
  command->add_flag("--skip-apart", args->skip_apart,
                    "do not ask a two-object collision query in a frame where the shared broad "
                    "phase proves the pair apart (group queries always go through it)");
  command->add_flag("--quiet", args->quiet, "no progress lines on stderr");
  command->add_flag("--fail-on-disagreement", args->fail_on_disagreement,
                    "exit with 3 when any answer differs from the oracle's");
  command->callback([args, &plugins, &exit_code] { exit_code = run(*args, plugins); });
}

}  // namespace collido::cli
