#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <collido/study/result_store.h>

namespace collido::study {

/// A worker process to start: the collido executable in worker mode, one combination.
struct WorkerLaunch {
  std::string executable;
  std::vector<std::string> arguments;    ///< after the program name
  std::vector<std::string> environment;  ///< "NAME=value" set on top of ours
  std::string log_path;                  ///< receives the worker's stderr
  double timeout_s = 0.0;                ///< 0: no limit
  /// Called with (done, total) for each "progress D T" line the worker prints on stdout.
  std::function<void(std::size_t, std::size_t)> on_progress;
  /// Called with each other line the worker prints on stdout (without its newline).
  std::function<void(const std::string&)> on_line;
  /// Called a few times a second while the worker runs (to redraw a progress bar).
  std::function<void()> on_tick;
  /// When it becomes true the worker is killed and the outcome is "interrupted".
  const std::atomic<bool>* stop = nullptr;
  /// The processor the worker runs on (set before it starts, inherited by what it starts); -1:
  /// wherever the scheduler puts it.
  int cpu = -1;
};

/// While it lives, keeps the calling thread (a driver of timed workers) off one processor, the last
/// of those it may use, so that a worker pinned there (WorkerLaunch::cpu) shares it with nothing
/// the study runs and is not moved between processors mid-call; restores the driver's processors
/// when it ends. Reserves none where fewer than two are allowed.
class WorkerProcessor {
 public:
  WorkerProcessor();
  ~WorkerProcessor();
  WorkerProcessor(const WorkerProcessor&) = delete;
  WorkerProcessor& operator=(const WorkerProcessor&) = delete;

  /// The reserved processor, or -1.
  int cpu() const { return cpu_; }

 private:
  std::vector<int> driver_cpus_;  // the processors this process could use before
  int cpu_ = -1;
};

/// Starts the worker in its own process group, dying with this process (PR_SET_PDEATHSIG), follows
/// its progress, kills it (and anything it started) at the time limit or when `stop` is raised, and
/// reports how it ended: exit code or signal, wall time, peak resident memory and the tail of its
/// log. Never throws for anything the worker does.
WorkerOutcome runWorkerProcess(const WorkerLaunch& launch);

/// The last `bytes` bytes of a file ("" when it cannot be read).
std::string fileTail(const std::string& path, std::size_t bytes);

}  // namespace collido::study
