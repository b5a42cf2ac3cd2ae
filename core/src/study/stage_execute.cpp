// The study's fifth stage: each combination in a worker process (the collido executable in
// worker mode), one at a time, each finished result stored atomically, so a crash costs one
// combination and an interrupted study resumes where it stopped.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>

#include <collido/io/files.h>
#include <collido/io/html_page.h>
#include <collido/runner/time_statistic.h>
#include <collido/study/expected_time.h>
#include <collido/study/outputs.h>
#include <collido/study/progress.h>
#include <collido/study/report_html.h>
#include <collido/study/stop_signals.h>
#include <collido/study/worker_process.h>

#include "stages.h"

namespace collido::study {
namespace {

// How often a running study remakes its outputs (table, records, summary) from what is stored.
constexpr std::chrono::seconds kOutputsRefresh{30};

// The worker's answer: a mesh combination's measurements when it finished; a surface or FRep
// combination's document whatever its exit code (a seed whose answers differ from the file's
// expected ones fails and still shows them). A worker that failed before writing keeps its status.
void readAnswer(const std::string& answer_path, CombinationResult& result) {
  const bool comparison = result.combination.kind != InputKind::kScene;
  if (!comparison && !result.outcome.ok()) return;
  const Result<nlohmann::json> json = io::readJsonFile(answer_path, "the worker wrote no answer");
  Result<CombinationResult> answer =
      json.ok() ? resultFromJson(json.value(), answer_path) : json.status();
  if (!answer.ok()) {
    if (result.outcome.ok()) {
      result.outcome.status = WorkerStatus::kUnfinished;
      result.outcome.log_tail = answer.status().message();
    }
    return;
  }
  result.measurements = std::move(answer.value().measurements);
  result.problems = std::move(answer.value().problems);
  result.backend_rss_bytes = answer.value().backend_rss_bytes;
  result.surfaces = std::move(answer.value().surfaces);
  result.frep = std::move(answer.value().frep);
}

// Runs one combination in a worker and reads its answer back.
CombinationResult runInWorker(const Combination& c, const ResultStore& store, int repetitions,
                              double timeout_s, const std::string& plugin_file,
                              const StudyRequest& request, StudyProgress& progress,
                              const std::atomic<bool>& stop, int worker_cpu) {
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
  const std::string oracle_directory =
      request.oracle_directory.empty()
          ? store.directory() + "/oracle"
          : std::filesystem::absolute(request.oracle_directory).string();
  launch.arguments.insert(
      launch.arguments.end(),
      {"worker", "--request", request_path, "--out", answer_path, "--repetitions",
       std::to_string(repetitions), "--oracle-cache", oracle_directory});
  launch.environment = request.worker_environment;
  launch.log_path = store.logPath(c.id);
  launch.timeout_s = timeout_s;
  launch.stop = &stop;
  // One processor of its own, the driver kept off it (WorkerProcessor); a setting that runs on
  // several threads gets them all.
  launch.cpu = runsOnOneThread(c.backend) ? worker_cpu : -1;
  launch.on_progress = [&progress](std::size_t done, std::size_t total) {
    progress.frames(done, total);
  };
  launch.on_tick = [&progress] { progress.tick(); };
  result.outcome = runWorkerProcess(launch);
  readAnswer(answer_path, result);
  std::filesystem::remove(answer_path);
  std::filesystem::remove(request_path);
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

/// How many extra rounds a combination may get for its unstable rows.
constexpr int kMaxExtraRounds = 3;

/// What running a queue of workers needs from the study.
struct WorkerQueue {
  const ResultStore& store;
  int repetitions;
  double timeout_s;
  const std::map<std::string, std::string>& plugin_file_of;
  const StudyRequest& request;
  const StopOnSignals& stop;
  std::ostream& err;
  int worker_cpu = -1;  // WorkerProcessor::cpu()
};

// Runs `todo` one worker at a time, storing each result; stops when asked to, or before a worker
// that would start past `deadline`. Fails when a result cannot be stored.
Result<StudyEnd> runQueue(
    const std::vector<const Combination*>& todo, const WorkerQueue& q, StudyProgress& progress,
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max()) {
  std::chrono::steady_clock::time_point outputs_made = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < todo.size(); ++i) {
    if (std::chrono::steady_clock::now() >= deadline) return StudyEnd::kDone;
    const Combination& c = *todo[i];
    progress.start(
        i, c.round == 0 ? c.label() : c.label() + " · round " + std::to_string(c.round + 1));
    const auto plugin_file = q.plugin_file_of.find(c.backend);
    CombinationResult result =
        runInWorker(c, q.store, q.repetitions, q.timeout_s,
                    plugin_file == q.plugin_file_of.end() ? std::string() : plugin_file->second,
                    q.request, progress, q.stop.requested(), q.worker_cpu);
    if (result.outcome.status == WorkerStatus::kInterrupted) return StudyEnd::kInterrupted;
    if (Status s = q.store.write(result); !s.ok()) {
      q.err << "\n";  // ends the progress line
      return s;
    }
    if (!q.request.quiet) progress.finish(outcomeText(result));
    // The outputs are made from every stored result: remade after each combination, a study of
    // n combinations did O(n^2) work. While it runs they are refreshed at most every 30 s (a
    // running study can be looked at), and made once more at the end.
    if (std::chrono::steady_clock::now() - outputs_made > kOutputsRefresh) {
      Result<std::vector<CombinationResult>> all = q.store.readAll();
      if (all.ok()) (void)writeStudyOutputs(q.store.directory(), all.value());
      outputs_made = std::chrono::steady_clock::now();
    }
    if (q.stop.requested().load()) return StudyEnd::kInterrupted;
  }
  return StudyEnd::kDone;
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

// The expected time of `todo`, from an earlier study's times when the request names one.
TimeEstimate expectedTime(const StudyRequest& request, const std::vector<const Combination*>& todo,
                          std::ostream& err) {
  CombinationTimes times;
  if (!request.expected_times.empty()) {
    Result<CombinationTimes> loaded = loadCombinationTimes(request.expected_times);
    if (loaded.ok()) {
      times = std::move(loaded).value();
    } else {  // an estimate is a courtesy: without one the study still runs
      err << "warning: " << loaded.status().message() << "; no expected time\n";
    }
  }
  return estimateTimes(todo, times);
}

}  // namespace

Result<StudyEnd> executePlan(const StudyRequest& request, const StudyPlan& plan,
                             const StudyBackends& backends, const StudyFolder& folder,
                             std::ostream& err) {
  TimeEstimate estimate = expectedTime(request, folder.todo, err);
  // The extra rounds follow the planned ones, when some were run (not for a study of one round).
  if (plan.order.rounds > 1 && !folder.todo.empty()) estimate.extra_rounds_s = plan.adaptive_s;
  err << startLine(plan.combinations.size(), folder.todo.size(), estimate, plan.shard, request.out)
      << "\n";
  // Ctrl-C, SIGTERM or a lost session stops the running worker; what finished stays stored.
  const StopOnSignals stop;
  StudyProgress progress(err, folder.todo.size(), !request.quiet && request.interactive);
  progress.setExpected(estimate.seconds);
  const WorkerProcessor worker_processor;
  const WorkerQueue queue{
      folder.store, plan.repetitions,      plan.timeout_s, backends.plugin_file_of, request, stop,
      err,          worker_processor.cpu()};
  Result<StudyEnd> end = runQueue(folder.todo, queue, progress);
  // Then more rounds where the rounds so far cannot pin a figure down, within the time budget.
  const int rounds = plan.order.rounds;
  const std::chrono::steady_clock::time_point deadline =
      std::chrono::steady_clock::now() +
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(plan.adaptive_s));
  for (int extra = 0;
       end.ok() && end.value() == StudyEnd::kDone && plan.adaptive_s > 0.0 && rounds > 1 &&
       extra < kMaxExtraRounds && std::chrono::steady_clock::now() < deadline;
       ++extra) {
    const std::vector<Combination> more = extraRounds(folder.store, rounds + extra);
    if (more.empty()) break;
    err << "study: round " << rounds + extra + 1 << " for " << more.size()
        << " combinations whose rounds disagree (unstable rows)\n";
    std::vector<const Combination*> pointers(more.size());
    for (std::size_t i = 0; i < more.size(); ++i)
      pointers[i] = &more[i];
    StudyProgress extra_progress(err, pointers.size(), !request.quiet && request.interactive);
    end = runQueue(pointers, queue, extra_progress, deadline);
  }
  return end;
}

}  // namespace collido::study
