// collido study / worker / merge: the study driver. The driver plans backends × scenes ×
// settings, runs each combination in a worker process (this executable in worker mode), and
// stores each finished combination atomically, so a crash costs one combination and an
// interrupted study resumes where it stopped.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include <collido/mesh/input_file.h>
#include <collido/runner/digest.h>
#include <collido/study/expected_time.h>
#include <collido/study/folder_lock.h>
#include <collido/study/outputs.h>
#include <collido/study/plugin_probe.h>
#include <collido/study/progress.h>
#include <collido/study/result_store.h>
#include <collido/study/stop_signals.h>
#include <collido/study/sweep.h>
#include <collido/study/worker.h>
#include <collido/study/worker_process.h>

#include "commands.h"

namespace collido::cli {
namespace {

using study::Combination;

// How long a plugin may take to load (its static constructors, the engine's start-up) before it
// counts as hanging: generous, since a cold disk can take seconds.
constexpr double kPluginLoadTimeoutS = 30.0;

// How often a running study remakes its outputs (table, records, summary) from what is stored.
constexpr std::chrono::seconds kOutputsRefresh{30};

using study::CombinationResult;
using study::ResultStore;

struct StudyArguments {
  std::vector<std::string> scenes;
  std::vector<std::string> backends;
  std::string sweep_path;
  std::string out;
  std::string shard;
  bool resume = false;
  bool retry_failed = false;
  double timeout_s = 0.0;
  int repetitions = 0;
  bool quiet = false;
  std::string expected_times;
  std::string protocol;
  double plugin_timeout_s = kPluginLoadTimeoutS;
};

// LD_PRELOAD for the allocation hooks, when they were built beside this executable.
std::vector<std::string> workerEnvironment() {
#ifdef COLLIDO_HEAP_HOOKS_FILE
  const std::filesystem::path hooks =
      std::filesystem::path(executableDirectory()) / COLLIDO_HEAP_HOOKS_FILE;
  std::error_code ec;
  if (std::filesystem::is_regular_file(hooks, ec)) {
    const char* existing = std::getenv("LD_PRELOAD");
    return {"LD_PRELOAD=" + hooks.string() +
            (existing != nullptr && *existing != '\0' ? std::string(":") + existing : "")};
  }
#endif
  return {};
}

// The backend settings to run: the sweep's (restricted to the variants --backends names, plus
// any --backends entry the sweep does not mention), else --backends, else every variant found.
std::vector<std::string> backendSettings(const StudyArguments& args, const study::Sweep& sweep,
                                         const study::PluginProbe& found) {
  std::vector<std::string> settings;
  std::set<std::string> named;
  for (const std::string& text : args.backends) {
    Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
        parseBackendText(text);
    named.insert(parsed.ok() ? parsed.value().first : text);
  }
  std::set<std::string> swept;
  for (const study::SweepBackend& backend : sweep.backends) {
    swept.insert(backend.variant);
    if (!named.empty() && named.count(backend.variant) == 0) continue;
    for (const std::string& setting : backend.settings())
      settings.push_back(setting);
  }
  for (const std::string& text : args.backends) {
    Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
        parseBackendText(text);
    if (!parsed.ok() || swept.count(parsed.value().first) == 0) settings.push_back(text);
  }
  if (settings.empty() && args.backends.empty() && sweep.backends.empty())
    settings = found.variantNames();
  return settings;
}

// Per setting from a sweep entry with "scenes", the scenes it runs on; a setting that an
// unrestricted entry also gives runs everywhere. Names matching no scene of the study are
// warned about (a typo would otherwise drop the setting silently).
std::map<std::string, std::set<std::string>> onlyScenes(
    const study::Sweep& sweep, const std::vector<study::PlannedScene>& scenes) {
  std::map<std::string, std::set<std::string>> only;
  std::set<std::string> everywhere;
  std::set<std::string> names;
  for (const study::PlannedScene& scene : scenes)
    names.insert(scene.name);
  for (const study::SweepBackend& backend : sweep.backends) {
    for (const std::string& setting : backend.settings()) {
      if (backend.scenes.empty()) {
        everywhere.insert(setting);
      } else {
        only[setting].insert(backend.scenes.begin(), backend.scenes.end());
      }
    }
    for (const std::string& scene : backend.scenes) {
      if (names.count(scene) == 0) {
        std::cerr << "warning: sweep: " << backend.variant << " names scene '" << scene
                  << "', which is not among the scenes studied\n";
      }
    }
  }
  for (const std::string& setting : everywhere)
    only.erase(setting);
  return only;
}

// Runs one combination in a worker and reads its answer back.
CombinationResult runInWorker(const Combination& c, const ResultStore& store, int repetitions,
                              double timeout_s, const std::string& plugin_file,
                              study::StudyProgress& progress, const std::atomic<bool>& stop) {
  const std::string request_path = store.scratchPath(c.id + ".request");
  const std::string answer_path = store.scratchPath(c.id);
  std::filesystem::remove(answer_path);
  CombinationResult result;
  result.combination = c;
  if (Status s = study::writeFileAtomically(request_path, study::combinationToJson(c).dump());
      !s.ok()) {
    result.outcome.status = "failed";
    result.outcome.log_tail = s.message();
    return result;
  }
  study::WorkerLaunch launch;
  launch.executable = thisExecutable();
  // The worker loads only the plugin its backend comes from: another plugin that misbehaves
  // while loading cannot cost this combination.
  launch.arguments = {"--no-default-plugins", "--plugin",
                      std::filesystem::absolute(plugin_file).string()};
  for (const std::string& a :
       {std::string("worker"), std::string("--request"), request_path, std::string("--out"),
        answer_path, std::string("--repetitions"), std::to_string(repetitions),
        std::string("--oracle-cache"), store.directory() + "/oracle"}) {
    launch.arguments.push_back(a);
  }
  launch.environment = workerEnvironment();
  launch.log_path = store.logPath(c.id);
  launch.timeout_s = timeout_s;
  launch.stop = &stop;
  launch.on_progress = [&progress](std::size_t done, std::size_t total) {
    progress.frames(done, total);
  };
  launch.on_tick = [&progress] { progress.tick(); };
  result.outcome = study::runWorkerProcess(launch);
  if (result.outcome.ok()) {
    std::ifstream in(answer_path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    Result<CombinationResult> answer = Result<CombinationResult>(
        Status(StatusCode::kInvalidArgument, answer_path + ": the worker wrote no answer"));
    try {
      if (in) answer = study::resultFromJson(nlohmann::json::parse(text.str()), answer_path);
    } catch (const nlohmann::json::exception& e) {
      answer = Status(StatusCode::kInvalidArgument, answer_path + ": " + e.what());
    }
    if (answer.ok()) {
      result.measurements = std::move(answer.value().measurements);
      result.problems = std::move(answer.value().problems);
      result.backend_rss_bytes = answer.value().backend_rss_bytes;
    } else {
      result.outcome.status = "unfinished";
      result.outcome.log_tail = answer.status().message();
    }
  }
  std::filesystem::remove(answer_path);
  std::filesystem::remove(request_path);
  return result;
}

std::string outcomeText(const CombinationResult& r) {
  if (!r.outcome.ok()) {
    std::string text = r.outcome.status;
    if (!r.outcome.signal_name.empty()) text += " (" + r.outcome.signal_name + ")";
    if (r.outcome.status == "failed") text += " (exit " + std::to_string(r.outcome.exit_code) + ")";
    return text;
  }
  std::size_t disagreements = 0;
  std::size_t failed = 0;
  for (const QueryMeasurement& m : r.measurements) {
    disagreements += m.disagreements;
    failed += m.status.rfind("failed", 0) == 0 ? 1 : 0;
  }
  std::string text = "ok in " + study::formatDuration(r.outcome.wall_s);
  if (disagreements != 0) text += ", " + std::to_string(disagreements) + " wrong answers";
  if (failed != 0) text += ", " + std::to_string(failed) + " failed queries";
  return text;
}

// A digest of every file the scene was read from (its content, in the order read).
Result<std::string> inputsDigest(const Scene& scene) {
  Digest digest;
  for (const std::string& file : scene.input_files) {
    Result<std::string> bytes = readInputFile(file, "input file");
    if (!bytes.ok()) return bytes.status();
    digest.text(bytes.value());
  }
  return digest.hex();
}

// "obbtree 0.4, engine OBB tree 0.4": what a change of plugin or engine version shows in.
std::string pluginIdentity(const study::PluginProbe& found, const std::string& backend) {
  Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
      parseBackendText(backend);
  const study::ProbedPlugin* plugin = parsed.ok() ? found.offering(parsed.value().first) : nullptr;
  if (plugin == nullptr) return "";
  return plugin->name + " " + plugin->version + ", engine " + plugin->engine_name + " " +
         plugin->engine_version;
}

// Why the same combinations (by label) now have other ids: which scenes' files, plugins or
// repetitions changed; "" when the combinations themselves differ.
std::string changedInputs(const std::vector<Combination>& before,
                          const std::vector<Combination>& now) {
  std::map<std::string, const Combination*> earlier;
  for (const Combination& c : before)
    earlier[c.label()] = &c;
  if (earlier.size() != now.size()) return "";
  std::set<std::string> scenes;
  std::set<std::string> plugins;
  std::set<std::string> repetitions;
  std::set<std::string> protocols;
  for (const Combination& c : now) {
    const auto found = earlier.find(c.label());
    if (found == earlier.end()) return "";
    const Combination& old = *found->second;
    if (old.scene_digest != c.scene_digest) scenes.insert(c.scene_name);
    if (old.plugin_identity != c.plugin_identity) {
      plugins.insert("'" + (old.plugin_identity.empty() ? "?" : old.plugin_identity) + "' -> '" +
                     c.plugin_identity + "'");
    }
    const auto named = [](const std::string& p) { return p.empty() ? std::string("repeated") : p; };
    if (named(old.protocol) != named(c.protocol))
      protocols.insert(named(old.protocol) + " -> " + named(c.protocol));
    if (old.repetitions != c.repetitions) {
      repetitions.insert(std::to_string(old.repetitions) + " -> " + std::to_string(c.repetitions));
    }
  }
  std::string text;
  const auto add = [&text](const std::string& what, const std::set<std::string>& items) {
    if (items.empty()) return;
    text += (text.empty() ? "" : "; ") + what;
    bool first = true;
    for (const std::string& item : items) {
      text += (first ? " " : ", ") + item;
      first = false;
    }
  };
  add("the files (scene file or meshes) of", scenes);
  add("plugin", plugins);
  add("repetitions", repetitions);
  add("timing protocol", protocols);
  return text;
}

// The plugins, each looked at by a child process (a scratch folder of its own holds their
// answers), so that none is loaded into the driver.
study::PluginProbe probeInChildren(const PluginOptions& plugins, double timeout_s) {
  const PluginCandidates candidates = pluginCandidates(plugins.paths, !plugins.no_defaults);
  std::error_code ec;
  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path(ec) / ("collido_plugins_" + std::to_string(getpid()));
  std::filesystem::create_directories(scratch, ec);
  study::PluginProbe probe =
      study::probePlugins(thisExecutable(), candidates, timeout_s, scratch.string());
  std::filesystem::remove_all(scratch, ec);
  return probe;
}

int runStudy(const StudyArguments& args, const PluginOptions& plugins) {
  study::Sweep sweep;
  if (!args.sweep_path.empty()) {
    Result<study::Sweep> loaded = study::loadSweep(args.sweep_path);
    if (!loaded.ok()) {
      std::cerr << "error: " << loaded.status().message() << "\n";
      return 2;
    }
    sweep = std::move(loaded).value();
  }
  std::vector<study::PlannedScene> scenes;
  std::map<std::string, std::string> scene_digests;  // by the planned path
  for (const std::string& path : args.scenes) {
    Result<Scene> scene = loadScene(path);
    if (!scene.ok()) {
      std::cerr << "error: " << scene.status().message() << "\n";
      return 2;
    }
    scenes.push_back({std::filesystem::absolute(path).lexically_normal().string(),
                      scene.value().name, scene.value().hasGeneratedShapes(),
                      scene.value().category});
    Result<std::string> digest = inputsDigest(scene.value());
    if (!digest.ok()) {
      std::cerr << "error: " << digest.status().message() << "\n";
      return 2;
    }
    scene_digests[scenes.back().path] = digest.value();
  }
  const study::PluginProbe found = probeInChildren(plugins, args.plugin_timeout_s);
  for (const std::string& problem : found.problems)
    std::cerr << "warning: " << problem << "\n";
  const std::vector<std::string> settings = backendSettings(args, sweep, found);
  Result<std::vector<std::string>> plugin_files = study::pluginFilesOf(settings, found);
  if (!plugin_files.ok()) {
    std::cerr << "error: " << plugin_files.status().message() << "\n";
    return 2;
  }
  std::map<std::string, std::string> plugin_file_of;
  for (std::size_t i = 0; i < settings.size(); ++i)
    plugin_file_of[settings[i]] = plugin_files.value()[i];
  if (settings.empty()) {
    std::cerr << "error: no backends to run (build the plugins or pass --plugin)\n";
    return 2;
  }
  std::size_t shard_index = 0;
  std::size_t shard_count = 1;
  if (!args.shard.empty()) {
    Result<std::pair<std::size_t, std::size_t>> shard = study::parseShard(args.shard);
    if (!shard.ok()) {
      std::cerr << "error: " << shard.status().message() << "\n";
      return 2;
    }
    std::tie(shard_index, shard_count) = shard.value();
  }
  const int repetitions = args.repetitions > 0 ? args.repetitions : sweep.repetitions.value_or(5);
  const double timeout_s = args.timeout_s > 0 ? args.timeout_s : sweep.timeout_s.value_or(600.0);
  const std::string protocol =
      !args.protocol.empty() ? args.protocol : sweep.protocol.value_or("repeated");
  std::vector<Combination> whole =
      study::planStudy(scenes, settings, sweep, onlyScenes(sweep, scenes));
  for (Combination& c : whole) {
    const std::string& digest = scene_digests.at(c.scene_path);
    const std::string identity = pluginIdentity(found, c.backend);
    c = study::withInputs(std::move(c), digest, identity, repetitions, protocol);
  }
  const std::vector<Combination> plan = study::shardOf(whole, shard_index, shard_count);

  // One driver per folder: a second one on the same --out would delete the first one's scratch
  // files and store results under its plan. Held until this function returns.
  Result<study::FolderLock> lock = study::FolderLock::acquire(args.out);
  if (!lock.ok()) {
    std::cerr << "error: " << lock.status().message() << "\n";
    return 2;
  }
  const ResultStore store(args.out);
  Result<std::vector<Combination>> stored_plan = store.readPlan();
  if (!stored_plan.ok()) {
    std::cerr << "error: " << stored_plan.status().message() << "\n";
    return 2;
  }
  if (!stored_plan.value().empty()) {
    if (!args.resume) {
      std::cerr << "error: " << args.out
                << " already holds a study; pass --resume to continue it, or another --out\n";
      return 2;
    }
    std::set<std::string> before;
    for (const Combination& c : stored_plan.value())
      before.insert(c.id);
    std::set<std::string> now;
    for (const Combination& c : plan)
      now.insert(c.id);
    if (before != now) {
      const std::string changed = changedInputs(stored_plan.value(), plan);
      if (!changed.empty()) {
        std::cerr << "error: " << args.out << ": the inputs changed since this study started ("
                  << changed
                  << "); its stored results would mix with new ones. Start it afresh in another "
                     "--out, or remove the folder\n";
      } else {
        std::cerr << "error: " << args.out
                  << " holds a different study (other scenes, backends, sweep or shard); resume "
                     "with the same arguments, or choose another --out\n";
      }
      return 2;
    }
  }
  if (Status s = store.prepare(); !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }
  if (Status s = store.writePlan(plan); !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }

  std::vector<const Combination*> todo;
  for (const Combination& c : plan) {
    if (args.resume && store.has(c.id)) {
      if (!args.retry_failed) continue;
      std::ifstream in(store.resultPath(c.id));
      std::stringstream text;
      text << in.rdbuf();
      try {
        Result<CombinationResult> stored =
            study::resultFromJson(nlohmann::json::parse(text.str()), store.resultPath(c.id));
        if (stored.ok() && stored.value().outcome.ok()) continue;
      } catch (const nlohmann::json::exception&) {
        // unreadable: run it again
      }
    }
    todo.push_back(&c);
  }
  study::CombinationTimes times;
  if (!args.expected_times.empty()) {
    Result<study::CombinationTimes> loaded = study::loadCombinationTimes(args.expected_times);
    if (loaded.ok()) {
      times = std::move(loaded).value();
    } else {  // an estimate is a courtesy: without one the study still runs
      std::cerr << "warning: " << loaded.status().message() << "; no expected time\n";
    }
  }
  const study::TimeEstimate estimate = study::estimateTimes(todo, times);
  std::cerr << study::startLine(plan.size(), todo.size(), estimate,
                                shard_count > 1 ? args.shard : "", args.out)
            << "\n";

  // Ctrl-C, SIGTERM or a lost session stops the running worker; what finished stays stored.
  const study::StopOnSignals stop;
  study::StudyProgress progress(std::cerr, todo.size(), !args.quiet && isatty(STDERR_FILENO) != 0);
  progress.setExpected(estimate.seconds);
  bool interrupted = false;
  std::chrono::steady_clock::time_point outputs_made = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < todo.size(); ++i) {
    const Combination& c = *todo[i];
    progress.start(i, c.label());
    CombinationResult result = runInWorker(
        c, store, repetitions, timeout_s, plugin_file_of.at(c.backend), progress, stop.requested());
    if (result.outcome.status == "interrupted") {
      interrupted = true;
      break;
    }
    if (Status s = store.write(result); !s.ok()) {
      std::cerr << "\nerror: " << s.message() << "\n";
      return 2;
    }
    if (!args.quiet) progress.finish(outcomeText(result));
    // The outputs are made from every stored result: remade after each combination, a study of
    // n combinations did O(n^2) work. While it runs they are refreshed at most every 30 s (a
    // running study can be looked at), and made once more at the end.
    if (std::chrono::steady_clock::now() - outputs_made > kOutputsRefresh) {
      Result<std::vector<CombinationResult>> all = store.readAll();
      if (all.ok()) (void)study::writeStudyOutputs(store.directory(), all.value());
      outputs_made = std::chrono::steady_clock::now();
    }
    if (stop.requested().load()) {
      interrupted = true;
      break;
    }
  }

  Result<std::vector<CombinationResult>> all = store.readAll();
  if (!all.ok()) {
    std::cerr << "error: " << all.status().message() << "\n";
    return 2;
  }
  if (Status s = study::writeStudyOutputs(store.directory(), all.value()); !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }
  if (interrupted) {
    std::cerr << "\nstudy interrupted: " << all.value().size() << " of " << plan.size()
              << " combinations are stored; continue with the same command and --resume\n";
    return 130;
  }
  std::cout << study::studyTable(all.value());
  const bool robustness =
      std::filesystem::exists(std::filesystem::path(store.directory()) / "robustness.txt");
  std::cerr << "results: " << store.directory() << "/{table.txt,records.jsonl,summary.json"
            << (robustness ? ",robustness.txt" : "") << "}\n";
  return 0;
}

int runWorkerMode(const std::string& request_path, const std::string& out_path, int repetitions,
                  const std::string& oracle_directory, const PluginOptions& plugins) {
  std::ifstream in(request_path, std::ios::binary);
  if (!in) {
    std::cerr << "error: " << request_path << ": cannot be read\n";
    return 2;
  }
  std::stringstream text;
  text << in.rdbuf();
  Result<Combination> combination = Status(StatusCode::kInvalidArgument, "");
  try {
    combination = study::combinationFromJson(nlohmann::json::parse(text.str()));
  } catch (const nlohmann::json::exception& e) {
    combination = Status(StatusCode::kInvalidArgument, e.what());
  }
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
  if (Status s = study::writeFileAtomically(out_path, study::resultToJson(result.value()).dump());
      !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }
  return 0;
}

// Whether `folder` holds a study's plan or results.
bool holdsStudy(const std::string& folder) {
  std::error_code ec;
  const std::filesystem::path path(folder);
  return std::filesystem::exists(path / "plan.json", ec) ||
         (std::filesystem::is_directory(path / "results", ec) &&
          !std::filesystem::is_empty(path / "results", ec));
}

bool sameFolder(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec) && !ec;
}

int runMerge(const std::string& out, const std::vector<std::string>& inputs, bool replace) {
  std::vector<Combination> plan;
  std::set<std::string> planned;
  std::map<std::string, std::pair<std::string, std::string>> label_source;  // label: id, folder
  std::map<std::string, CombinationResult> results;
  for (const std::string& input : inputs) {
    const ResultStore shard(input);
    Result<std::vector<Combination>> shard_plan = shard.readPlan();
    Result<std::vector<CombinationResult>> shard_results = shard.readAll();
    if (!shard_plan.ok() || !shard_results.ok()) {
      std::cerr << "error: "
                << (shard_plan.ok() ? shard_results.status() : shard_plan.status()).message()
                << "\n";
      return 2;
    }
    if (shard_plan.value().empty() && shard_results.value().empty()) {
      std::cerr << "error: " << input << ": no study here (no plan.json, no results/)\n";
      return 2;
    }
    for (const Combination& c : shard_plan.value()) {
      // Shards of one study share their inputs; the same combination run on other inputs (a
      // scene or plugin changed between shards) would sit beside itself in the table.
      const auto [known, fresh] = label_source.emplace(c.label(), std::make_pair(c.id, input));
      if (!fresh && known->second.first != c.id) {
        std::cerr << "error: " << input << " and " << known->second.second << " ran " << c.label()
                  << " on different inputs (a scene file, mesh, plugin or the repetitions "
                     "changed between them); merge only shards of one study\n";
        return 2;
      }
      if (planned.insert(c.id).second) plan.push_back(c);
    }
    for (CombinationResult& r : shard_results.value()) {
      if (planned.insert(r.combination.id).second) plan.push_back(r.combination);
      const auto existing = results.find(r.combination.id);
      // The same combination in two inputs: keep a finished run over a failed one.
      if (existing == results.end() || (!existing->second.outcome.ok() && r.outcome.ok())) {
        results[r.combination.id] = std::move(r);
      }
    }
  }
  // A folder that holds another study would keep its results beside the merged ones: the table
  // would then count combinations of neither input.
  Result<study::FolderLock> lock = study::FolderLock::acquire(out);
  if (!lock.ok()) {
    std::cerr << "error: " << lock.status().message() << "\n";
    return 2;
  }
  const bool out_is_input = std::any_of(
      inputs.begin(), inputs.end(), [&out](const std::string& in) { return sameFolder(in, out); });
  if (holdsStudy(out) && !out_is_input) {
    if (!replace) {
      std::cerr << "error: " << out
                << " already holds a study; merge into a new folder, or pass --replace to "
                   "replace what it holds\n";
      return 2;
    }
    std::error_code ec;
    for (const char* stale : {"results", "plan.json", "robustness.txt"})
      std::filesystem::remove_all(std::filesystem::path(out) / stale, ec);
  }
  const ResultStore store(out);
  if (Status s = store.prepare(); !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }
  std::vector<CombinationResult> merged;
  for (auto& [id, result] : results) {
    if (Status s = store.write(result); !s.ok()) {
      std::cerr << "error: " << s.message() << "\n";
      return 2;
    }
    merged.push_back(result);
  }
  if (Status s = store.writePlan(plan); !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }
  if (Status s = study::writeStudyOutputs(out, merged); !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }
  std::cout << study::studyTable(merged);
  const std::size_t missing = plan.size() - merged.size();
  std::cerr << "merged " << merged.size() << " of " << plan.size() << " planned combinations into "
            << out << (missing != 0 ? " (" + std::to_string(missing) + " not run yet)" : "")
            << "\n";
  return 0;
}

}  // namespace

void addStudyCommands(CLI::App& app, const PluginOptions& plugins, int& exit_code) {
  CLI::App* command = app.add_subcommand(
      "study",
      "Run every combination of scenes x backend settings x sweep in worker processes, each "
      "answer checked against the exact oracle; a crash or hang costs one combination. Writes "
      "OUT/table.txt, OUT/records.jsonl, OUT/summary.json (Google Benchmark format) and "
      "OUT/results/. Exit code: 0 done, 2 bad input, 130 interrupted (resume with --resume)");
  auto args = std::make_shared<StudyArguments>();
  command->add_option("scenes", args->scenes, "scene files (JSON)")->required();
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
                   "timing protocol: repeated (each frame's calls back to back, the default) or "
                   "cycled (each timed call on another frame than the last; docs/STUDY.md)")
      ->check(CLI::IsMember({"repeated", "cycled"}));
  command->add_option("--expected-times", args->expected_times,
                      "an earlier study folder or its times.json: the expected time printed at "
                      "the start and the progress estimate come from its wall times");
  command->callback([args, &plugins, &exit_code] { exit_code = runStudy(*args, plugins); });

  CLI::App* info = app.add_subcommand("plugin-info", "");  // internal: one plugin, probed
  info->group("");
  auto info_file = std::make_shared<std::string>();
  auto info_out = std::make_shared<std::string>();
  info->add_option("file", *info_file)->required();
  info->add_option("--out", *info_out)->required();
  info->callback([info_file, info_out, &exit_code] {
    Result<std::shared_ptr<PluginLibrary>> plugin = PluginLibrary::open(*info_file);
    if (!plugin.ok()) {
      std::cerr << "error: " << plugin.status().message() << "\n";
      exit_code = 2;
      return;
    }
    const Status written =
        study::writeFileAtomically(*info_out, study::pluginInfoJson(*plugin.value()).dump());
    if (!written.ok()) std::cerr << "error: " << written.message() << "\n";
    exit_code = written.ok() ? 0 : 2;
  });

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
    exit_code = runMerge(*merge_out, *inputs, *replace);
  });
}

}  // namespace collido::cli
