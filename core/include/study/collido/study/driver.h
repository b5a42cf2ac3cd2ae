#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <collido/study/plan.h>

namespace collido::study {

/// What a study is asked to do (collido study's arguments), and how its workers start.
struct StudyRequest {
  std::vector<std::string> scenes;         ///< scene files
  std::vector<std::string> surface_files;  ///< NURBS surface files (collido surface-distance)
  std::vector<std::string> frep_files;     ///< FRep files (collido frep)
  std::vector<std::string> backends;       ///< NAME or NAME[key=value;...]; with a sweep, a filter
  std::string sweep_path;                  ///< "" for none
  std::string out;                         ///< the study folder
  std::string shard;                       ///< "I/N", or "" for the whole study
  /// Where the oracle's answers are kept (study/oracle_store.h); "": OUT/oracle. Shards given
  /// one folder on a shared filesystem reuse each other's answers.
  std::string oracle_directory;
  bool resume = false;
  bool retry_failed = false;
  double timeout_s = 0.0;    ///< 0: the sweep's, else 600
  int repetitions = 0;       ///< 0: the sweep's, else 5
  int rounds = 0;            ///< 0: the sweep's, else 1 (RunOrder)
  double adaptive_s = -1.0;  ///< < 0: the sweep's, else 0 (the extra rounds' time budget)
  std::uint64_t order_seed = RunOrder{}.seed;  ///< the seed of the order combinations run in
  std::string protocol;                        ///< "" : the sweep's, else "cycled"
  std::string expected_times;      ///< an earlier study or its times.json, for the expected time
  double plugin_timeout_s = 30.0;  ///< how long a plugin may take to load in its probe
  bool quiet = false;              ///< no progress lines
  bool interactive = false;        ///< progress redrawn in place (a terminal)

  std::string executable;                       ///< the collido executable the workers run
  std::vector<std::string> worker_environment;  ///< "NAME=value" added for every worker
  std::vector<std::string> plugin_paths;        ///< --plugin
  bool default_plugins = true;                  ///< also the default plugin folders
};

/// Runs a study: every combination of the scenes, the backend settings and the sweep, each in a
/// worker process (docs/STUDY.md). Progress and problems go to `err`, the table at the end to
/// `out`. Returns the exit code: 0 done, 2 bad input, 130 interrupted (resume it).
int runStudy(const StudyRequest& request, std::ostream& out, std::ostream& err);

/// Joins the folders of a sharded study into `out_dir` (collido merge), refusing a folder that
/// holds another study unless `replace`; returns the exit code (0, or 2).
int mergeStudies(const std::string& out_dir, const std::vector<std::string>& inputs, bool replace,
                 std::ostream& out, std::ostream& err);

}  // namespace collido::study
