#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <collido/status.h>
#include <collido/study/result_store.h>

namespace collido::study {

/// What a worker process is asked to do: one combination.
struct WorkerRequest {
  Combination combination;
  std::vector<std::string> plugin_paths;  ///< --plugin, searched first
  bool default_plugins = true;
  int repetitions = 5;
  /// Where the oracle's answers are kept between workers (study/oracle_store.h); "": not kept.
  std::string oracle_directory;
  std::function<void(std::size_t, std::size_t)> progress;  ///< frames done, frames in all
};

/// Runs one combination in this process. A mesh scene is loaded at the combination's resolution
/// (and, when coarser than 1, at resolution 1 with the same poses, as the finest truth), its
/// answers capped at its limit, built for its needs and measured. A surface or FRep file runs
/// its seed method, or one backend on the combination's grid against the seed's answers, into
/// CombinationResult::surfaces or ::frep. Errors are bad input (scene, backend); an engine's
/// failure is recorded in the measurements or the comparison's rows instead.
Result<CombinationResult> runCombination(const WorkerRequest& request);

/// Whether a finished combination fails its worker (exit code 1, its answer written all the
/// same): a surface or FRep seed method that certified nothing or answered otherwise than its
/// file expects, as its problems say.
bool failsItsWorker(const CombinationResult& result);

}  // namespace collido::study
