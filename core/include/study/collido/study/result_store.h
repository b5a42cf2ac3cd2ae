#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/runner/frep_run.h>
#include <collido/runner/runner.h>
#include <collido/runner/surface_run.h>
#include <collido/status.h>
#include <collido/study/plan.h>

namespace collido::study {

/// How a worker process ended.
enum class WorkerStatus {
  kOk,           ///< results written
  kFailed,       ///< exited non-zero, or could not be started
  kCrashed,      ///< killed by a signal
  kTimeout,      ///< killed after the time limit
  kInterrupted,  ///< stopped because the study was interrupted (SIGINT, SIGTERM)
  kUnfinished,   ///< exited 0 but no result could be read
};

/// The status as records and tables spell it: "ok", "failed", "crashed", "timeout",
/// "interrupted", "unfinished".
const char* workerStatusName(WorkerStatus status);
/// The status of that spelling; std::nullopt for any other text.
std::optional<WorkerStatus> parseWorkerStatus(const std::string& name);

/// How a worker process ended, with what it left for a reader.
struct WorkerOutcome {
  WorkerStatus status = WorkerStatus::kOk;
  int exit_code = 0;
  int signal = 0;
  std::string signal_name;  ///< "SIGSEGV", ...; empty without a signal
  double wall_s = 0.0;
  std::size_t peak_rss_bytes = 0;  ///< the worker's maximum resident set
  std::string log_tail;            ///< the end of its stderr, for failures

  bool ok() const { return status == WorkerStatus::kOk; }
  /// How it ended, for people: "ok", "crashed (SIGSEGV)", "failed (exit 2)", "timeout", ...
  std::string text() const;
};

/// Everything one combination produced.
struct CombinationResult {
  Combination combination;
  WorkerOutcome outcome;
  std::vector<QueryMeasurement> measurements;  ///< empty unless the worker finished
  std::vector<std::string> problems;
  /// The resident memory the backend added at its peak while it built and answered, over what
  /// the worker held before (scene, oracle answers): the backend's own share (ResidentPeak).
  /// Absent when the worker did not finish or the kernel could not reset the peak.
  std::optional<std::size_t> backend_rss_bytes;
  /// A surface file's combination: its run for this one setting (the seed's rows, or one
  /// backend's against the certified reference); absent for other inputs and workers that
  /// wrote no answer.
  std::optional<SurfaceRun> surfaces;
  /// An FRep file's combination: likewise, the seed's run with its preview picture inline.
  std::optional<FrepRun> frep;

  /// The memory figure tables show: the backend's own share, else the worker's peak.
  std::size_t residentBytes() const { return backend_rss_bytes.value_or(outcome.peak_rss_bytes); }
};

nlohmann::json resultToJson(const CombinationResult& result);
Result<CombinationResult> resultFromJson(const nlohmann::json& json, const std::string& label);

/// A study's folder: plan.json, results/<id>.json (one per finished combination, written
/// atomically), logs/<id>.log (each worker's stderr), and the outputs made from the results.
class ResultStore {
 public:
  explicit ResultStore(std::string directory) : directory_(std::move(directory)) {}

  const std::string& directory() const { return directory_; }
  Status prepare() const;  ///< creates the folders

  bool has(const std::string& id) const;
  Status write(const CombinationResult& result) const;
  /// Every stored result, in id order, each combination's timing rounds joined into one result
  /// (joinRounds); unreadable files are errors naming the file.
  Result<std::vector<CombinationResult>> readAll() const;

  /// plan.json: the combinations in the order they run, the settings not planned on some scene
  /// (plan.h), the rounds and seed that order came from (left out when unknown), and the field
  /// table's sides.
  Status writePlan(const std::vector<Combination>& plan,
                   const std::vector<NotApplicable>& not_applicable = {},
                   const std::optional<RunOrder>& order = RunOrder{},
                   const FieldSides& field = {}) const;
  /// The stored plan, or an empty one when none was written.
  Result<std::vector<Combination>> readPlan() const;
  /// The stored plan's settings not planned on some scene; none without a plan, or in a plan
  /// written before studies left them out.
  Result<std::vector<NotApplicable>> readNotApplicable() const;
  /// The rounds and seed the stored plan's order came from; none without a plan, or in a plan
  /// that does not say (written before it did, or merged from shards that did not).
  Result<std::optional<RunOrder>> readRunOrder() const;
  /// The stored plan's field sides; the defaults without a plan, or in a plan written before
  /// they were a setting.
  Result<FieldSides> readFieldSides() const;

  std::string resultPath(const std::string& id) const;
  std::string logPath(const std::string& id) const;
  std::string scratchPath(const std::string& id) const;  ///< where a worker writes its answer

 private:
  std::string planPath() const;
  /// plan.json's JSON, or nothing when there is none.
  Result<std::optional<nlohmann::json>> readPlanJson() const;

  std::string directory_;
};

}  // namespace collido::study
