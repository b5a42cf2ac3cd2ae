// The study's stages, in the order runStudy calls them: load the inputs, probe the plugins, plan
// the combinations, reconcile the plan with the study folder (resume), execute the workers and
// publish the outputs. Each returns what the next one needs, or the Status that stops the study
// before anything is lost.
#pragma once

#include <cstddef>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include <collido/status.h>
#include <collido/study/driver.h>
#include <collido/study/folder_lock.h>
#include <collido/study/not_applicable.h>
#include <collido/study/plan.h>
#include <collido/study/plugin_probe.h>
#include <collido/study/result_store.h>
#include <collido/study/sweep.h>

namespace collido::study {

/// The request's inputs, every one read and checked before the study starts.
struct StudyInputs {
  Sweep sweep;                              ///< empty without --sweep
  std::vector<PlannedScene> scenes;         ///< mesh scenes
  std::vector<PlannedScene> surface_files;  ///< NURBS surface files
  std::vector<PlannedScene> frep_files;     ///< FRep files
  /// By planned path: a digest of every file the input was read from.
  std::map<std::string, std::string> digests;
  std::size_t shard_index = 0;
  std::size_t shard_count = 1;
  /// The mesh scenes' timing protocol: --protocol, else the sweep's, else cycled.
  TimingProtocol protocol = TimingProtocol::kCycled;
};

/// Load: the sweep, the scenes (solving their constraints once), the surface and FRep files, the
/// shard and the timing protocol. Mesh files among the scenes become scenes written into
/// OUT/scenes (said on `err`), studied with the default sweep unless one is given. Fails naming
/// the file and the problem.
Result<StudyInputs> loadInputs(const StudyRequest& request, std::ostream& err);

/// The backend settings to run, what each answers and the plugin file it comes from.
struct StudyBackends {
  PluginProbe found;
  std::vector<std::string> settings;                  ///< on mesh scenes
  std::vector<std::string> surface_settings;          ///< on surface files
  std::vector<std::string> frep_settings;             ///< on FRep files
  std::map<std::string, std::string> plugin_file_of;  ///< by setting
  SettingAbilities abilities;                         ///< of the mesh settings
};

/// Probe: the plugins and then the settings, each looked at by a child process so that none is
/// loaded into the driver. Warns on `err` of settings left out; fails when none is left.
Result<StudyBackends> probeBackends(const StudyRequest& request, const StudyInputs& inputs,
                                    std::ostream& err);

/// This run's combinations (the shard's, every round) and how each runs.
struct StudyPlan {
  std::vector<Combination> combinations;
  std::vector<NotApplicable> not_applicable;
  RunOrder order;
  int repetitions = 5;
  double timeout_s = 600.0;
  double adaptive_s = 0.0;  ///< time for extra rounds of unstable rows
  std::string shard;        ///< "I/N" when this run is one shard of several, else ""
  FieldSides field;         ///< the field table's sides, the sweep's
};

/// Plan: the combinations of the inputs and the settings, with the digests and plugin versions
/// that tell a resumed study whether its inputs changed. Warns on `err` of sweep entries that
/// name no scene of the study.
StudyPlan planCombinations(const StudyRequest& request, const StudyInputs& inputs,
                           const StudyBackends& backends, std::ostream& err);

/// The study folder, held by this run, and what is left to run in it.
struct StudyFolder {
  FolderLock lock;
  ResultStore store;
  std::vector<const Combination*> todo;  ///< into StudyPlan::combinations, in run order
};

/// Reconcile: locks the folder and compares its stored plan with this one. A folder holding
/// another study, or this one with changed inputs, is refused (saying which inputs changed);
/// with --resume, what is stored is not run again (with --retry-failed, failures are).
Result<StudyFolder> reconcileFolder(const StudyRequest& request, const StudyPlan& plan);

/// How the execution ended.
enum class StudyEnd { kDone, kInterrupted };

/// Execute: each combination left in its worker, one at a time, each result stored as it
/// finishes; then extra rounds for unstable rows within the plan's time budget. Stops at a
/// signal; fails when a result cannot be stored.
Result<StudyEnd> executePlan(const StudyRequest& request, const StudyPlan& plan,
                             const StudyBackends& backends, const StudyFolder& folder,
                             std::ostream& err);

/// Publish: the outputs made from every stored result; when the study is done, its table on
/// `out` and where the outputs are on `err`.
Status publishResults(const StudyPlan& plan, const StudyFolder& folder, StudyEnd end,
                      std::ostream& out, std::ostream& err);

}  // namespace collido::study
