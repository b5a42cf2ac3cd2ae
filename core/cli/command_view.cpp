// collido view: a scene's 3D view with every backend's answers, triangle by triangle. Each
// backend answers in a child process of its own (collido view-answers), so an engine that
// crashes or hangs loses its own answers only; the exact oracle's answers are computed once,
// before the children start (or read from the study's store), and kept on disk between them.
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include <collido/io/files.h>
#include <collido/runner/runner.h>
#include <collido/runner/view_answers.h>
#include <collido/study/oracle_store.h>
#include <collido/study/plan.h>
#include <collido/study/report_html.h>
#include <collido/study/result_store.h>
#include <collido/study/stop_signals.h>
#include <collido/study/worker_process.h>
#include <collido/view/view_page.h>

#include "commands.h"

namespace collido::cli {
namespace {

struct ViewArguments {
  std::string scene;
  std::string out;
  std::vector<std::string> backends;
  std::string results;
  std::string oracle_store;  ///< the exact answers' store ("": the study's RESULTS/oracle, if any)
  std::string web;
  double timeout_s = 600.0;
  double resolution = 1.0;
  unsigned jobs = 0;  ///< backends answering at once; 0: one per processor
  bool quiet = false;
};

// The scene at `resolution`, its solved placement kept in `oracle_directory`'s store; a bad one
// is reported on stderr.
Result<Scene> loadReporting(const std::string& path, double resolution,
                            const std::string& oracle_directory) {
  SceneLoadOptions load;
  load.resolution = resolution;
  if (!oracle_directory.empty()) load.placement_store = oracle_directory + "/placements";
  Result<Scene> scene = loadScene(path, load);
  if (!scene.ok()) std::cerr << "error: " << scene.status().message() << "\n";
  return scene;
}

// A number that reads back to the same double.
std::string exactText(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

// The variants a study ran on this scene (as declared, at `resolution`), in its plan's order.
Result<std::vector<std::string>> studyBackends(const std::string& directory,
                                               const std::string& scene_name, double resolution) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(std::filesystem::path(directory) / "plan.json", ec)) {
    return Status(StatusCode::kInvalidArgument,
                  directory + ": not a study folder (no plan.json; make one with collido study)");
  }
  Result<std::vector<study::Combination>> plan = study::ResultStore(directory).readPlan();
  if (!plan.ok()) return plan.status();
  std::vector<std::string> backends;
  std::set<std::string> seen;
  for (const study::Combination& c : plan.value()) {
    if (c.scene_name != scene_name || c.resolution != resolution || c.limit != 0 ||
        c.needs != study::NeedsMode::kDeclared) {
      continue;
    }
    if (seen.insert(c.backend).second) backends.push_back(c.backend);
  }
  if (backends.empty()) {
    return Status(StatusCode::kInvalidArgument, directory + ": the study ran nothing on scene '" +
                                                    scene_name + "' at resolution " +
                                                    exactText(resolution) + " as declared");
  }
  return backends;
}

std::vector<std::string> everyVariant(const PluginOptions& plugins) {
  const PluginDiscovery found = discoverPlugins(plugins.paths, !plugins.no_defaults);
  std::vector<std::string> names;
  for (const auto& plugin : found.plugins) {
    for (const VariantInfo& v : plugin->variants())
      names.push_back(v.name);
  }
  return names;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// One backend's answers, from a child process.
view::ViewBackend answersOf(const ViewArguments& args, const PluginOptions& plugins,
                            const std::string& backend, const std::string& work,
                            const std::string& oracle_directory, std::size_t index,
                            const std::atomic<bool>& stop) {
  view::ViewBackend result;
  result.label = backend;
  const std::string out = work + "/answers_" + std::to_string(index) + ".json";
  study::WorkerLaunch launch;
  launch.executable = thisExecutable();
  launch.arguments = pluginArguments(plugins);
  for (const std::string& a :
       {std::string("view-answers"), std::string("--scene"), args.scene, std::string("--backend"),
        backend, std::string("--out"), out, std::string("--oracle-cache"), oracle_directory,
        std::string("--resolution"), exactText(args.resolution)}) {
    launch.arguments.push_back(a);
  }
  launch.log_path = work + "/log_" + std::to_string(index) + ".txt";
  launch.timeout_s = args.timeout_s;
  launch.stop = &stop;
  const study::WorkerOutcome outcome = study::runWorkerProcess(launch);
  if (!outcome.ok()) {
    result.problem = outcome.text() + ": " + outcome.log_tail;
    return result;
  }
  result.answers_json = readFile(out);
  if (result.answers_json.empty()) result.problem = "the backend's process wrote no answers";
  return result;
}

// The exact answers (and solved placements) from the study's store when it has them: the study
// computed them for the same scene. Else they are computed in the work folder once, shared with
// the backends' processes.
std::string oracleDirectoryOf(const ViewArguments& args, const std::filesystem::path& work) {
  std::error_code ec;
  if (!args.oracle_store.empty()) return std::filesystem::absolute(args.oracle_store).string();
  if (!args.results.empty() &&
      std::filesystem::is_directory(std::filesystem::path(args.results) / "oracle", ec))
    return (std::filesystem::path(args.results) / "oracle").string();
  return (work / "oracle").string();
}

// The backends to show: those asked, else those the study ran on the scene, else every variant
// found. A misspelt backend is bad input, said before any work (an engine failing is not).
Result<std::vector<std::string>> backendsToShow(const ViewArguments& args,
                                                const PluginOptions& plugins, const Scene& scene) {
  std::vector<std::string> backends = args.backends;
  if (backends.empty() && !args.results.empty()) {
    Result<std::vector<std::string>> ran = studyBackends(args.results, scene.name, args.resolution);
    if (!ran.ok()) return ran.status();
    backends = std::move(ran).value();
  }
  if (backends.empty()) backends = everyVariant(plugins);
  if (backends.empty()) {
    return Status(StatusCode::kInvalidArgument,
                  "no backends to show (build the plugins, pass --plugin or --backends)");
  }
  const PluginDiscovery found = discoverPlugins(plugins.paths, !plugins.no_defaults);
  if (Result<std::vector<BackendSpec>> specs = resolveBackends(backends, found.plugins);
      !specs.ok())
    return specs.status();
  return backends;
}

// Every backend's answers, side by side (views time nothing), each in its own process: --jobs at
// a time, by default one per processor.
std::vector<view::ViewBackend> answersSideBySide(const ViewArguments& args,
                                                 const PluginOptions& plugins,
                                                 const std::vector<std::string>& backends,
                                                 const std::string& work,
                                                 const std::string& oracle_directory,
                                                 const study::StopOnSignals& stop) {
  const unsigned processors = std::max(1U, std::thread::hardware_concurrency());
  const std::size_t jobs =
      std::min<std::size_t>(backends.size(), args.jobs == 0 ? processors : args.jobs);
  std::vector<view::ViewBackend> answers(backends.size());
  std::atomic<std::size_t> next{0};
  std::mutex output;
  const auto answerNext = [&] {
    for (std::size_t i = next++; i < backends.size() && !stop.requested().load(); i = next++) {
      if (!args.quiet) {
        const std::lock_guard<std::mutex> lock(output);
        std::cerr << "view: " << backends[i] << "\n";
      }
      answers[i] =
          answersOf(args, plugins, backends[i], work, oracle_directory, i, stop.requested());
      if (!answers[i].problem.empty() && !stop.requested().load()) {
        const std::lock_guard<std::mutex> lock(output);
        std::cerr << "warning: " << backends[i] << ": " << answers[i].problem << "\n";
      }
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t t = 1; t < jobs; ++t)
    threads.emplace_back(answerNext);
  answerNext();
  for (std::thread& t : threads)
    t.join();
  return answers;
}

int view(const ViewArguments& args, const PluginOptions& plugins) {
  const std::filesystem::path work =
      std::filesystem::path(args.out).parent_path() /
      (std::filesystem::path(args.out).filename().string() + ".work");
  // The work folder (the children's answers, an oracle store of its own) goes with any return.
  struct RemoveOnReturn {
    std::filesystem::path folder;
    ~RemoveOnReturn() {
      std::error_code ignored;
      std::filesystem::remove_all(folder, ignored);
    }
  } const remove_work{work};
  const std::string oracle_directory = oracleDirectoryOf(args, work);
  const Result<Scene> scene = loadReporting(args.scene, args.resolution, oracle_directory);
  if (!scene.ok()) return 2;
  const Result<std::vector<std::string>> backends = backendsToShow(args, plugins, scene.value());
  Status ready =
      backends.ok() ? view::checkViewFrontEnd(study::webDirectory(args.web)) : backends.status();
  if (ready.ok() && thisExecutable().empty()) {
    ready = Status(StatusCode::kInvalidArgument,
                   "cannot find this program's own path (/proc/self/exe) to start the backends' "
                   "processes");
  }
  if (ready.ok()) {
    std::error_code ec;
    std::filesystem::create_directories(work / "oracle", ec);
    if (ec) ready = Status(StatusCode::kInvalidArgument, work.string() + ": " + ec.message());
  }
  if (!ready.ok()) {
    std::cerr << "error: " << ready.message() << "\n";
    return 2;
  }
  // The exact answers once, before any backend.
  {
    OracleCache oracle(scene.value());
    const study::StoredOracle stored(oracle_directory, oracle);
    precomputeOracleAnswers(oracle);
    stored.keepNew();
  }
  // Ctrl-C, SIGTERM or a lost session stops the running backends' processes, not only this one.
  const study::StopOnSignals stop;
  const std::vector<view::ViewBackend> answers =
      answersSideBySide(args, plugins, backends.value(), work.string(), oracle_directory, stop);
  if (stop.requested().load()) {
    std::cerr << "view interrupted (signal " << stop.signal() << "): nothing written\n";
    return 130;
  }
  Result<std::string> page =
      view::renderViewPage(scene.value(), answers, study::webDirectory(args.web));
  Status written = page.ok() ? io::writeFileAtomically(args.out, page.value()) : page.status();
  if (!written.ok()) {
    std::cerr << "error: " << written.message() << "\n";
    return 2;
  }
  if (!args.quiet) std::cerr << "view: wrote " << args.out << "\n";
  return 0;
}

struct AnswersArguments {
  std::string scene;
  std::string backend;
  std::string out;
  std::string oracle_directory;
  double resolution = 1.0;
};

// The child: one backend's answers on the scene, the oracle's shared through the store.
int viewAnswers(const AnswersArguments& args, const PluginOptions& plugins) {
  const Result<Scene> scene = loadReporting(args.scene, args.resolution, args.oracle_directory);
  if (!scene.ok()) return 2;
  const PluginDiscovery found = discoverPlugins(plugins.paths, !plugins.no_defaults);
  Result<std::vector<BackendSpec>> specs = resolveBackends({args.backend}, found.plugins);
  if (!specs.ok()) {
    std::cerr << "error: " << specs.status().message() << "\n";
    return 2;
  }
  OracleCache oracle(scene.value());
  const study::StoredOracle stored(args.oracle_directory, oracle);
  RunOptions options;
  options.repetitions = 1;
  options.keep_answers = true;
  const RunReport report = runScene(scene.value(), specs.value().front(), options, oracle);
  stored.keepNew();
  const std::string json = viewAnswersJson(scene.value(), report, specs.value().front().label());
  if (Status s = io::writeFileAtomically(args.out, json); !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }
  return 0;
}

}  // namespace

void addViewCommands(CLI::App& app, const PluginOptions& plugins, int& exit_code) {
  CLI::App* command = app.add_subcommand(
      "view",
      "Write a scene's 3D view: one HTML page that opens offline, showing the meshes frame by "
      "frame and, per backend and query, the triangles it reports as intersecting, the exact "
      "oracle's and the difference (docs/VIEW.md)");
  auto args = std::make_shared<ViewArguments>();
  command->add_option("scene", args->scene, "scene file (JSON)")->required();
  command->add_option("-o,--out", args->out, "the page to write (HTML)")->required();
  command
      ->add_option("--backends", args->backends,
                   "backends to show, NAME or NAME[key=value;...] (default: those the study of "
                   "--results ran on the scene, else every variant found)")
      ->delimiter(',');
  command->add_option("--results", args->results,
                      "a study folder (collido study --out): show the backends it ran here");
  command
      ->add_option("--oracle-store", args->oracle_store,
                   "the folder of stored exact answers to read and add to (as collido study's "
                   "--oracle-store; default: --results' oracle/ when it has one)")
      ->check(CLI::ExistingDirectory | CLI::NonexistentPath);
  command->add_option("--timeout", args->timeout_s,
                      "seconds a backend may take for all its answers (default 600)");
  command
      ->add_option("--resolution", args->resolution,
                   "scales the generated shapes' sample counts (as collido study's sweeps do)")
      ->check(CLI::PositiveNumber);
  command->add_option("--web", args->web,
                      "the front-end folder (default: $COLLIDO_WEB_DIR, else the "
                      "install's share/collido/web, else the source web/)");
  command
      ->add_option("--jobs", args->jobs,
                   "backends answering at once, each in its own process (default: one per "
                   "processor)")
      ->check(CLI::Range(1U, 256U));
  command->add_flag("--quiet", args->quiet, "no progress on stderr");
  command->callback([args, &plugins, &exit_code] { exit_code = view(*args, plugins); });

  CLI::App* child = app.add_subcommand("view-answers", "");  // the view's child process
  child->group("");
  auto answers = std::make_shared<AnswersArguments>();
  child->add_option("--scene", answers->scene)->required();
  child->add_option("--backend", answers->backend)->required();
  child->add_option("--out", answers->out)->required();
  child->add_option("--oracle-cache", answers->oracle_directory);
  child->add_option("--resolution", answers->resolution);
  child->callback([answers, &plugins, &exit_code] { exit_code = viewAnswers(*answers, plugins); });
}

}  // namespace collido::cli
