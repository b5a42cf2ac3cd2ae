#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace collido::study {

/// The study's progress on a terminal: a bar for the whole study with an estimate of the time
/// left, and one for the running combination's frames, redrawn in place. On anything but a
/// terminal it prints one line per finished combination instead.
class StudyProgress {
 public:
  using Clock = std::chrono::steady_clock;
  /// Where the time comes from: the steady clock, or a test's own.
  using Now = std::function<Clock::time_point()>;

  StudyProgress(std::ostream& out, std::size_t combinations, bool interactive,
                Now now = Clock::now);

  void start(std::size_t index, const std::string& label);
  void frames(std::size_t done, std::size_t total);
  void finish(const std::string& outcome);
  /// Redraws the bars (at most ten times a second).
  void tick();
  /// "1m05s": the estimated time left. With expected times per combination (setExpected), the
  /// expected time of what is left, scaled by how the finished part compared with its
  /// expectation; else the mean time per combination so far.
  std::string estimateLeft() const;
  /// Expected seconds of each combination, in the order they run (estimateTimes).
  void setExpected(std::vector<double> seconds);

 private:
  void draw();

  std::ostream& out_;
  std::size_t combinations_;
  bool interactive_;
  Now now_;
  Clock::time_point started_;
  Clock::time_point last_draw_{};
  std::size_t finished_ = 0;
  std::size_t index_ = 0;
  std::string label_;
  std::size_t frames_done_ = 0;
  std::size_t frames_total_ = 0;
  std::vector<double> expected_;
};

/// A duration in seconds as people read it: "42s", "3m07s", "1h02m".
std::string formatDuration(double seconds);

/// A bar of `width` cells filled to `fraction` (clamped to [0, 1]).
std::string progressBar(double fraction, std::size_t width);

}  // namespace collido::study
