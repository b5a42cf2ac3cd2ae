// The study driver: plans backends x scenes x settings, runs each combination in a worker
// process (the collido executable in worker mode), and stores each finished combination
// atomically, so a crash costs one combination and an interrupted study resumes where it
// stopped. collido study and collido merge only parse their arguments and call it.
#include <collido/study/driver.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <collido/io/files.h>
#include <collido/mesh/input_file.h>
#include <collido/runner/digest.h>
#include <collido/runner/time_statistic.h>
#include <collido/scene/frep_file.h>
#include <collido/scene/surface_file.h>
#include <collido/study/expected_time.h>
#include <collido/study/folder_lock.h>
#include <collido/study/outputs.h>
#include <collido/study/plugin_probe.h>
#include <collido/study/progress.h>
#include <collido/study/report_html.h>
#include <collido/study/result_store.h>
#include <collido/study/stop_signals.h>
#include <collido/study/sweep.h>
#include <collido/study/worker_process.h>

namespace collido::study {
namespace {

// How often a running study remakes its outputs (table, records, summary) from what is stored.
constexpr std::chrono::seconds kOutputsRefresh{30};

// The backend settings to run: the sweep's (restricted to the variants --backends names, plus
// any --backends entry the sweep does not mention), else --backends, else every variant found.
// An optional sweep entry that no plugin offers is left out with a warning (the GPL-only cgal
// comparator in a default build).
std::vector<std::string> backendSettings(const StudyRequest& args, const Sweep& sweep,
                                         const PluginProbe& found, std::ostream& err) {
  std::vector<std::string> settings;
  std::set<std::string> named;
  for (const std::string& text : args.backends) {
    Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
        parseBackendText(text);
    named.insert(parsed.ok() ? parsed.value().first : text);
  }
  std::set<std::string> swept;
  for (const SweepBackend& backend : sweep.backends) {
    swept.insert(backend.variant);
    if (!named.empty() && named.count(backend.variant) == 0) continue;
    if (backend.optional && found.offering(backend.variant) == nullptr) {
      err << "warning: sweep: no plugin offers the optional '" << backend.variant
          << "'; left out\n";
      continue;
    }
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
std::map<std::string, std::set<std::string>> onlyScenes(const Sweep& sweep,
                                                        const std::vector<PlannedScene>& scenes,
                                                        std::ostream& err) {
  std::map<std::string, std::set<std::string>> only;
  std::set<std::string> everywhere;
  std::set<std::string> names;
  for (const PlannedScene& scene : scenes)
    names.insert(scene.name);
  for (const SweepBackend& backend : sweep.backends) {
    for (const std::string& setting : backend.settings()) {
      if (backend.scenes.empty()) {
        everywhere.insert(setting);
      } else {
        only[setting].insert(backend.scenes.begin(), backend.scenes.end());
      }
    }
    for (const std::string& scene : backend.scenes) {
      if (names.count(scene) == 0) {
        err << "warning: sweep: " << backend.variant << " names scene '" << scene
            << "', which is not among the scenes studied\n";
      }
    }
  }
  for (const std::string& setting : everywhere)
    only.erase(setting);
  return only;
}

// What a combination's worker runs (after the plugin options): a mesh scene's worker mode, or a
// surface or FRep file's own command for one backend (against the seed's certified answers,
// computed untimed) or for the seed method alone.
std::vector<std::string> workerCommand(const Combination& c, int repetitions,
                                       const std::string& request_path,
                                       const std::string& answer_path,
                                       const std::string& preview_path,
                                       const std::string& oracle_directory) {
  if (c.kind == InputKind::kScene) {
    return {"worker",
            "--request",
            request_path,
            "--out",
            answer_path,
            "--repetitions",
            std::to_string(repetitions),
            "--oracle-cache",
            oracle_directory};
  }
  const bool surfaces = c.kind == InputKind::kSurfaces;
  std::vector<std::string> command = {surfaces ? "surface-distance" : "frep",
                                      c.scene_path,
                                      "--repetitions",
                                      std::to_string(repetitions),
                                      "--json",
                                      answer_path};
  if (c.backend == kSeedMethod) {
    if (!surfaces) command.insert(command.end(), {"--preview", preview_path});
    return command;
  }
  command.insert(command.end(), {"--backends-only", "--backends", c.backend,
                                 surfaces ? "--tessellations" : "--resolutions", c.gridText()});
  return command;
}

// A surface or FRep worker's answer (its command's --json), kept whatever its exit code: a seed
// whose answers differ from the file's expected ones exits 1 and still shows them. Its preview
// picture goes inline, so the answer does not depend on a file in the scratch folder.
void readComparison(const std::string& answer_path, const std::string& preview_path,
                    CombinationResult& result) {
  // Answers are written atomically: a worker that failed before writing one keeps its status.
  Result<nlohmann::json> answer = io::readJsonFile(answer_path, "the worker wrote no answer");
  if (!answer.ok()) {
    if (result.outcome.ok()) {
      result.outcome.status = WorkerStatus::kUnfinished;
      result.outcome.log_tail = answer.status().message();
    }
    return;
  }
  result.comparison = std::move(answer).value();
  if (result.comparison.contains("preview")) {
    result.comparison.erase("preview");
    std::ifstream picture(preview_path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(picture)),
                            std::istreambuf_iterator<char>());
    if (!bytes.empty()) result.comparison["preview_png"] = "data:image/png;base64," + base64(bytes);
  }
}

// Runs one combination in a worker and reads its answer back.
CombinationResult runInWorker(const Combination& c, const ResultStore& store, int repetitions,
                              double timeout_s, const std::string& plugin_file,
                              const StudyRequest& request, StudyProgress& progress,
                              const std::atomic<bool>& stop) {
  const std::string request_path = store.scratchPath(c.id + ".request");
  const std::string answer_path = store.scratchPath(c.id);
  std::filesystem::remove(answer_path);
  CombinationResult result;
  result.combination = c;
  if (Status s = io::writeFileAtomically(request_path, combinationToJson(c).dump()); !s.ok()) {
    result.outcome.status = WorkerStatus::kFailed;
    result.outcome.log_tail = s.message();
    return result;
  }
  WorkerLaunch launch;
  launch.executable = request.executable;
  // The worker loads only the plugin its backend comes from: another plugin that misbehaves
  // while loading cannot cost this combination. A seed method needs none.
  launch.arguments = {"--no-default-plugins"};
  if (!plugin_file.empty()) {
    launch.arguments.push_back("--plugin");
    launch.arguments.push_back(std::filesystem::absolute(plugin_file).string());
  }
  const std::string preview_path = store.scratchPath(c.id + ".png");
  const std::string oracle_directory =
      request.oracle_directory.empty()
          ? store.directory() + "/oracle"
          : std::filesystem::absolute(request.oracle_directory).string();
  const std::vector<std::string> command =
      workerCommand(c, repetitions, request_path, answer_path, preview_path, oracle_directory);
  launch.arguments.insert(launch.arguments.end(), command.begin(), command.end());
  launch.environment = request.worker_environment;
  launch.log_path = store.logPath(c.id);
  launch.timeout_s = timeout_s;
  launch.stop = &stop;
  launch.on_progress = [&progress](std::size_t done, std::size_t total) {
    progress.frames(done, total);
  };
  launch.on_tick = [&progress] { progress.tick(); };
  result.outcome = runWorkerProcess(launch);
  if (c.kind != InputKind::kScene) {
    readComparison(answer_path, preview_path, result);
  } else if (result.outcome.ok()) {
    const Result<nlohmann::json> json = io::readJsonFile(answer_path, "the worker wrote no answer");
    Result<CombinationResult> answer =
        json.ok() ? resultFromJson(json.value(), answer_path) : json.status();
    if (answer.ok()) {
      result.measurements = std::move(answer.value().measurements);
      result.problems = std::move(answer.value().problems);
      result.backend_rss_bytes = answer.value().backend_rss_bytes;
    } else {
      result.outcome.status = WorkerStatus::kUnfinished;
      result.outcome.log_tail = answer.status().message();
    }
  }
  std::filesystem::remove(answer_path);
  std::filesystem::remove(request_path);
  std::filesystem::remove(preview_path);
  return result;
}

std::string outcomeText(const CombinationResult& r) {
  if (!r.outcome.ok()) return r.outcome.text();
  std::size_t disagreements = 0;
  std::size_t failed = 0;
  for (const QueryMeasurement& m : r.measurements) {
    disagreements += m.disagreements;
    failed += m.status.failed() ? 1 : 0;
  }
  std::string text = "ok in " + formatDuration(r.outcome.wall_s);
  if (disagreements != 0) text += ", " + std::to_string(disagreements) + " wrong answers";
  if (failed != 0) text += ", " + std::to_string(failed) + " failed queries";
  return text;
}

// A digest of the content of `files`, in order (a scene's: every file it was read from).
Result<std::string> filesDigest(const std::vector<std::string>& files, const char* what) {
  Digest digest;
  for (const std::string& file : files) {
    Result<std::string> bytes = readInputFile(file, what);
    if (!bytes.ok()) return bytes.status();
    digest.text(bytes.value());
  }
  return digest.hex();
}

// The settings a kind of comparison runs: its sweep entry's, else the mesh settings; a setting
// no plugin offers is left out with a warning (OpenCASCADE is optional, and a sweep may name it).
std::vector<std::string> comparisonSettings(const SweepComparison& sweep,
                                            const std::vector<std::string>& mesh_settings,
                                            const PluginProbe& found, const char* what,
                                            std::ostream& err) {
  std::vector<std::string> settings;
  for (const std::string& text : sweep.backends.empty() ? mesh_settings : sweep.backends) {
    Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
        parseBackendText(text);
    if (parsed.ok() && found.offering(parsed.value().first) != nullptr) {
      settings.push_back(text);
    } else {
      err << "warning: " << what << ": no plugin offers '" << text << "'; left out\n";
    }
  }
  return settings;
}

// "obbtree 0.4, engine OBB tree 0.4": what a change of plugin or engine version shows in.
std::string pluginIdentity(const PluginProbe& found, const std::string& backend) {
  Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
      parseBackendText(backend);
  const ProbedPlugin* plugin = parsed.ok() ? found.offering(parsed.value().first) : nullptr;
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

// A scratch folder for the probe children's answers, removed with it.
class ProbeScratch {
 public:
  ProbeScratch() {
    std::error_code ec;
    path_ =
        (std::filesystem::temp_directory_path(ec) / ("collido_plugins_" + std::to_string(getpid())))
            .string();
    std::filesystem::create_directories(path_, ec);
  }
  ProbeScratch(const ProbeScratch&) = delete;
  ProbeScratch& operator=(const ProbeScratch&) = delete;
  ~ProbeScratch() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// The plugins, each looked at by a child process, so that none is loaded into the driver.
PluginProbe probeInChildren(const StudyRequest& request) {
  const PluginCandidates candidates =
      pluginCandidates(request.plugin_paths, request.default_plugins);
  const ProbeScratch scratch;
  return probePlugins(request.executable, candidates, request.plugin_timeout_s, scratch.path());
}

// What each mesh setting answers, so the plan leaves out those a scene cannot use.
SettingAbilities abilitiesInChildren(const StudyRequest& request,
                                     const std::vector<std::string>& settings,
                                     const std::map<std::string, std::string>& plugin_file_of,
                                     std::ostream& err) {
  const ProbeScratch scratch;
  std::vector<std::string> problems;
  SettingAbilities abilities = probeSettings(request.executable, settings, plugin_file_of,
                                             request.plugin_timeout_s, scratch.path(), problems);
  for (const std::string& problem : problems)
    err << "warning: " << problem << "\n";
  return abilities;
}

/// How many extra rounds a combination may get for its unstable rows.
constexpr int kMaxExtraRounds = 3;

/// What running a queue of workers needs from the study.
struct WorkerQueue {
  const ResultStore& store;
  int repetitions;
  double timeout_s;
  const std::map<std::string, std::string>& plugin_file_of;
  const StudyRequest& args;
  const StopOnSignals& stop;
  std::ostream& err;
};

enum class QueueEnd { kDone, kInterrupted, kStoreFailed };

// Runs `todo` one worker at a time, storing each result; stops when asked to, or before a worker
// that would start past `deadline`.
QueueEnd runQueue(
    const std::vector<const Combination*>& todo, const WorkerQueue& q, StudyProgress& progress,
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max()) {
  std::chrono::steady_clock::time_point outputs_made = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < todo.size(); ++i) {
    if (std::chrono::steady_clock::now() >= deadline) return QueueEnd::kDone;
    const Combination& c = *todo[i];
    progress.start(
        i, c.round == 0 ? c.label() : c.label() + " · round " + std::to_string(c.round + 1));
    const auto plugin_file = q.plugin_file_of.find(c.backend);
    CombinationResult result =
        runInWorker(c, q.store, q.repetitions, q.timeout_s,
                    plugin_file == q.plugin_file_of.end() ? std::string() : plugin_file->second,
                    q.args, progress, q.stop.requested());
    if (result.outcome.status == WorkerStatus::kInterrupted) return QueueEnd::kInterrupted;
    if (Status s = q.store.write(result); !s.ok()) {
      q.err << "\nerror: " << s.message() << "\n";
      return QueueEnd::kStoreFailed;
    }
    if (!q.args.quiet) progress.finish(outcomeText(result));
    // The outputs are made from every stored result: remade after each combination, a study of
    // n combinations did O(n^2) work. While it runs they are refreshed at most every 30 s (a
    // running study can be looked at), and made once more at the end.
    if (std::chrono::steady_clock::now() - outputs_made > kOutputsRefresh) {
      Result<std::vector<CombinationResult>> all = q.store.readAll();
      if (all.ok()) (void)writeStudyOutputs(q.store.directory(), all.value());
      outputs_made = std::chrono::steady_clock::now();
    }
    if (q.stop.requested().load()) return QueueEnd::kInterrupted;
  }
  return QueueEnd::kDone;
}

// Round `round` of each finished mesh combination with an unstable row (unstable(): its rounds
// so far cannot pin the figure down to within the equivalence band), unless already stored.
std::vector<Combination> extraRounds(const ResultStore& store, int round) {
  std::vector<Combination> more;
  Result<std::vector<CombinationResult>> all = store.readAll();
  if (!all.ok()) return more;
  for (const CombinationResult& r : all.value()) {
    if (!r.outcome.ok() || r.combination.kind != InputKind::kScene) continue;
    const bool wanting =
        std::any_of(r.measurements.begin(), r.measurements.end(),
                    [](const QueryMeasurement& m) { return m.ok() && unstable(m); });
    Combination next = inRound(r.combination, round);
    if (wanting && !store.has(next.id)) more.push_back(std::move(next));
  }
  return more;
}

int runStudyImpl(const StudyRequest& args, std::ostream& out, std::ostream& err) {
  Sweep sweep;
  if (!args.sweep_path.empty()) {
    Result<Sweep> loaded = loadSweep(args.sweep_path);
    if (!loaded.ok()) {
      err << "error: " << loaded.status().message() << "\n";
      return 2;
    }
    sweep = std::move(loaded).value();
  }
  if (args.scenes.empty() && args.surface_files.empty() && args.frep_files.empty()) {
    err << "error: no scene, surface or FRep file to study\n";
    return 2;
  }
  std::vector<PlannedScene> scenes;
  std::map<std::string, std::string> scene_digests;  // by the planned path
  // Scenes placed by constraints are solved here once; the workers read the stored solve.
  SceneLoadOptions load;
  load.placement_store =
      (args.oracle_directory.empty() ? args.out + "/oracle" : args.oracle_directory) +
      "/placements";
  for (const std::string& path : args.scenes) {
    Result<Scene> scene = loadScene(path, load);
    if (!scene.ok()) {
      err << "error: " << scene.status().message() << "\n";
      return 2;
    }
    QueryKindSet asked;
    for (const SceneQuery& query : scene.value().queries)
      asked |= query.request.kind;
    scenes.push_back({std::filesystem::absolute(path).lexically_normal().string(),
                      scene.value().name, scene.value().hasGeneratedShapes(),
                      scene.value().category, asked});
    Result<std::string> digest = filesDigest(scene.value().input_files, "input file");
    if (!digest.ok()) {
      err << "error: " << digest.status().message() << "\n";
      return 2;
    }
    scene_digests[scenes.back().path] = digest.value();
  }
  // NURBS surface and FRep files, checked now so that bad input stops the study before it starts.
  std::vector<PlannedScene> surface_files;
  std::vector<PlannedScene> frep_files;
  for (const auto& [paths, kind] : {std::make_pair(&args.surface_files, InputKind::kSurfaces),
                                    std::make_pair(&args.frep_files, InputKind::kFrep)}) {
    for (const std::string& path : *paths) {
      Status loaded;
      if (kind == InputKind::kSurfaces) {
        if (Result<std::vector<NamedSurface>> file = loadSurfaces(path); !file.ok())
          loaded = file.status();
      } else if (Result<FrepFile> file = loadFrepFile(path); !file.ok()) {
        loaded = file.status();
      }
      if (!loaded.ok()) {
        err << "error: " << loaded.message() << "\n";
        return 2;
      }
      Result<std::string> digest =
          filesDigest({path}, kind == InputKind::kSurfaces ? "surface file" : "FRep file");
      if (!digest.ok()) {
        err << "error: " << digest.status().message() << "\n";
        return 2;
      }
      const std::string planned = std::filesystem::absolute(path).lexically_normal().string();
      (kind == InputKind::kSurfaces ? surface_files : frep_files)
          .push_back({planned, std::filesystem::path(path).stem().string()});
      scene_digests[planned] = digest.value();
    }
  }
  const PluginProbe found = probeInChildren(args);
  for (const std::string& problem : found.problems)
    err << "warning: " << problem << "\n";
  const std::vector<std::string> settings = backendSettings(args, sweep, found, err);
  const std::vector<std::string> surface_settings =
      surface_files.empty() ? std::vector<std::string>()
                            : comparisonSettings(sweep.surfaces, settings, found, "surfaces", err);
  const std::vector<std::string> frep_settings =
      frep_files.empty() ? std::vector<std::string>()
                         : comparisonSettings(sweep.frep, settings, found, "frep", err);
  std::vector<std::string> every_setting = settings;
  every_setting.insert(every_setting.end(), surface_settings.begin(), surface_settings.end());
  every_setting.insert(every_setting.end(), frep_settings.begin(), frep_settings.end());
  Result<std::vector<std::string>> plugin_files = pluginFilesOf(every_setting, found);
  if (!plugin_files.ok()) {
    err << "error: " << plugin_files.status().message() << "\n";
    return 2;
  }
  std::map<std::string, std::string> plugin_file_of;
  for (std::size_t i = 0; i < every_setting.size(); ++i)
    plugin_file_of[every_setting[i]] = plugin_files.value()[i];
  if (settings.empty()) {
    err << "error: no backends to run (build the plugins or pass --plugin)\n";
    return 2;
  }
  std::size_t shard_index = 0;
  std::size_t shard_count = 1;
  if (!args.shard.empty()) {
    Result<std::pair<std::size_t, std::size_t>> shard = parseShard(args.shard);
    if (!shard.ok()) {
      err << "error: " << shard.status().message() << "\n";
      return 2;
    }
    std::tie(shard_index, shard_count) = shard.value();
  }
  const int repetitions = args.repetitions > 0 ? args.repetitions : sweep.repetitions.value_or(5);
  const double timeout_s = args.timeout_s > 0 ? args.timeout_s : sweep.timeout_s.value_or(600.0);
  // Cycled by default: each timed call on another frame than the last, as an independent
  // harness and a simulation step meet them (docs/STUDY.md, "Timing protocols").
  const std::string protocol =
      !args.protocol.empty() ? args.protocol : sweep.protocol.value_or("cycled");
  const RunOrder order{args.rounds > 0 ? args.rounds : sweep.rounds.value_or(1), args.order_seed};
  const std::map<std::string, std::set<std::string>> only_scenes = onlyScenes(sweep, scenes, err);
  const SettingAbilities abilities = abilitiesInChildren(args, settings, plugin_file_of, err);
  std::vector<Combination> whole = planStudy(scenes, settings, sweep, only_scenes, abilities);
  const std::vector<NotApplicable> not_applicable =
      notApplicable(scenes, settings, only_scenes, abilities);
  for (Combination& c : whole) {
    const std::string& digest = scene_digests.at(c.scene_path);
    const std::string identity = pluginIdentity(found, c.backend);
    c = withInputs(std::move(c), digest, identity, repetitions, protocol);
  }
  // Surfaces and FRep files: a single input per frame, timed by the repeated protocol whatever
  // the study's (docs/STUDY.md, "Timing protocols").
  for (std::vector<Combination> comparisons :
       {planComparisons(surface_files, InputKind::kSurfaces, surface_settings, sweep.surfaces.grid),
        planComparisons(frep_files, InputKind::kFrep, frep_settings, sweep.frep.grid)}) {
    for (Combination& c : comparisons) {
      const std::string identity =
          c.backend == kSeedMethod ? std::string() : pluginIdentity(found, c.backend);
      const std::string digest = scene_digests.at(c.scene_path);
      whole.push_back(withInputs(std::move(c), digest, identity, repetitions, "repeated"));
    }
  }
  // A shard runs every round of its combinations, so that it can join them.
  const std::vector<Combination> plan =
      inRounds(shardOf(whole, shard_index, shard_count), order.rounds);

  // One driver per folder: a second one on the same --out would delete the first one's scratch
  // files and store results under its plan. Held until this function returns.
  Result<FolderLock> lock = FolderLock::acquire(args.out);
  if (!lock.ok()) {
    err << "error: " << lock.status().message() << "\n";
    return 2;
  }
  const ResultStore store(args.out);
  Result<std::vector<Combination>> stored_plan = store.readPlan();
  if (!stored_plan.ok()) {
    err << "error: " << stored_plan.status().message() << "\n";
    return 2;
  }
  if (!stored_plan.value().empty()) {
    if (!args.resume) {
      err << "error: " << args.out
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
        err << "error: " << args.out << ": the inputs changed since this study started (" << changed
            << "); its stored results would mix with new ones. Start it afresh in another "
               "--out, or remove the folder\n";
      } else {
        err << "error: " << args.out
            << " holds a different study (other scenes, backends, sweep or shard); resume "
               "with the same arguments, or choose another --out\n";
      }
      return 2;
    }
  }
  if (Status s = store.prepare(); !s.ok()) {
    err << "error: " << s.message() << "\n";
    return 2;
  }
  if (Status s = store.writePlan(plan, not_applicable, order); !s.ok()) {
    err << "error: " << s.message() << "\n";
    return 2;
  }

  std::vector<const Combination*> todo;
  for (const std::size_t index : runOrder(plan.size(), order.seed)) {
    const Combination& c = plan[index];
    if (args.resume && store.has(c.id)) {
      if (!args.retry_failed) continue;
      // An unreadable result is run again.
      const Result<nlohmann::json> json = io::readJsonFile(store.resultPath(c.id));
      if (json.ok()) {
        const Result<CombinationResult> stored =
            resultFromJson(json.value(), store.resultPath(c.id));
        if (stored.ok() && stored.value().outcome.ok()) continue;
      }
    }
    todo.push_back(&c);
  }
  CombinationTimes times;
  if (!args.expected_times.empty()) {
    Result<CombinationTimes> loaded = loadCombinationTimes(args.expected_times);
    if (loaded.ok()) {
      times = std::move(loaded).value();
    } else {  // an estimate is a courtesy: without one the study still runs
      err << "warning: " << loaded.status().message() << "; no expected time\n";
    }
  }
  const TimeEstimate estimate = estimateTimes(todo, times);
  err << startLine(plan.size(), todo.size(), estimate, shard_count > 1 ? args.shard : "", args.out)
      << "\n";

  // Ctrl-C, SIGTERM or a lost session stops the running worker; what finished stays stored.
  const StopOnSignals stop;
  StudyProgress progress(err, todo.size(), !args.quiet && args.interactive);
  progress.setExpected(estimate.seconds);
  const WorkerQueue queue{store, repetitions, timeout_s, plugin_file_of, args, stop, err};
  QueueEnd end = runQueue(todo, queue, progress);
  // Then more rounds where the rounds so far cannot pin a figure down, within the time budget.
  const double adaptive_s = args.adaptive_s >= 0.0 ? args.adaptive_s : sweep.adaptive_s.value_or(0);
  const std::chrono::steady_clock::time_point deadline =
      std::chrono::steady_clock::now() +
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(adaptive_s));
  for (int extra = 0; end == QueueEnd::kDone && adaptive_s > 0.0 && order.rounds > 1 &&
                      extra < kMaxExtraRounds && std::chrono::steady_clock::now() < deadline;
       ++extra) {
    const std::vector<Combination> more = extraRounds(store, order.rounds + extra);
    if (more.empty()) break;
    err << "study: round " << order.rounds + extra + 1 << " for " << more.size()
        << " combinations whose rounds disagree (unstable rows)\n";
    std::vector<const Combination*> pointers(more.size());
    for (std::size_t i = 0; i < more.size(); ++i)
      pointers[i] = &more[i];
    StudyProgress extra_progress(err, pointers.size(), !args.quiet && args.interactive);
    end = runQueue(pointers, queue, extra_progress, deadline);
  }
  if (end == QueueEnd::kStoreFailed) return 2;
  const bool interrupted = end == QueueEnd::kInterrupted;

  Result<std::vector<CombinationResult>> all = store.readAll();
  if (!all.ok()) {
    err << "error: " << all.status().message() << "\n";
    return 2;
  }
  if (Status s = writeStudyOutputs(store.directory(), all.value()); !s.ok()) {
    err << "error: " << s.message() << "\n";
    return 2;
  }
  if (interrupted) {
    err << "\nstudy interrupted: " << all.value().size() << " of " << plan.size()
        << " combinations are stored; continue with the same command and --resume\n";
    return 130;
  }
  out << studyTable(all.value(), not_applicable);
  const bool robustness =
      std::filesystem::exists(std::filesystem::path(store.directory()) / "robustness.txt");
  err << "results: " << store.directory() << "/{table.txt,records.jsonl,summary.json"
      << (robustness ? ",robustness.txt" : "") << "}\n";
  return 0;
}

}  // namespace

int runStudy(const StudyRequest& request, std::ostream& out, std::ostream& err) {
  return runStudyImpl(request, out, err);
}

}  // namespace collido::study
