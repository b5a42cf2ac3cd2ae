#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <collido/runner/runner.h>

namespace collido {

/// A 95% confidence interval.
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

/// The one time statistic every table, summary and chart of a study shows: the mean over frames
/// of each frame's median timed call, in microseconds per query. Each frame weighs once, as a
/// step of the workload does; the median keeps one slow call from deciding a frame.
double meanFrameTimeUs(const QueryMeasurement& m);

/// That statistic and its interval in words, as the outputs name them.
inline constexpr const char* kTimeStatisticText =
    "mean over frames of each frame's median call (us per query), with its 95% bootstrap "
    "interval (rounds, frames and calls resampled)";

/// `values` cut into `parts` runs of equal length, in order; none when they are empty or do not
/// divide evenly (the layout of QueryMeasurement::times_us by frame, and of a frame's calls by
/// round).
std::optional<std::vector<std::vector<double>>> splitEvenly(const std::vector<double>& values,
                                                            std::size_t parts);

/// Each frame's timed calls, split from QueryMeasurement::times_us (frame-major, the same count
/// per frame). A frame whose calls cannot be told apart from its neighbours' (a measurement
/// written with another layout) holds its median alone.
std::vector<std::vector<double>> callsPerFrame(const QueryMeasurement& m);

/// The bootstrap distribution of meanFrameTimeUs (docs/STUDY.md, "Times and their intervals"):
/// each replicate draws the rounds (worker processes) with replacement, the frames with
/// replacement and, within each drawn frame, its calls from the drawn rounds with replacement,
/// and takes the mean of the drawn frames' medians. The frames drawn depend on the frame count
/// alone, so two measurements of the same frames draw the same ones: their replicates pair by
/// frame. Rounds and calls are drawn from a seed made of the times themselves, so the same
/// measurement always gives the same interval.
class TimeBootstrap {
 public:
  static constexpr int kReplicates = 2000;

  explicit TimeBootstrap(const QueryMeasurement& m);
  /// The same for any per-frame timings: each frame's calls (one or more each), `rounds` equal
  /// runs of them one after the other (taken as one where they do not divide evenly).
  explicit TimeBootstrap(const std::vector<std::vector<double>>& calls_per_frame,
                         std::size_t rounds = 1);

  double estimate() const { return estimate_; }
  /// The percentile interval of the replicates.
  Interval ci95() const;
  const std::vector<double>& replicates() const { return *replicates_; }

 private:
  double estimate_ = 0.0;
  std::shared_ptr<const std::vector<double>> replicates_;  ///< shared with equal draws
};

/// With several rounds: the slowest round's statistic over the fastest's (each round's own mean
/// over frames of its calls' medians); none with one round or a round at 0.
std::optional<double> roundSpread(const QueryMeasurement& m);

/// With several rounds: the half-width of the 95% interval of the mean of the rounds' own
/// statistics (Student's t over the rounds), relative to that mean: how finely the worker
/// processes pin the figure down; none with one round or a mean of 0.
std::optional<double> roundHalfWidth(const QueryMeasurement& m);

/// A measurement whose rounds cannot resolve the equivalence band (roundHalfWidth above it) is
/// unstable: its processes disagreed, so its figure is suspect and its interval wide. A study
/// gives such combinations more rounds within its time budget, then flags what stays so.
bool unstable(const QueryMeasurement& m);

/// A ratio of two figures with its 95% interval.
struct Ratio {
  double value = 0.0;
  Interval ci95;
};

/// `numerator`'s statistic over `denominator`'s, with the percentile interval of the replicates'
/// ratios (paired by frame when both have the same frame count); none when the denominator's
/// estimate or a replicate of it is 0.
std::optional<Ratio> timeRatio(const TimeBootstrap& numerator, const TimeBootstrap& denominator);

/// The practical-equivalence band: two times within 10% of each other are treated as the same
/// (docs/STUDY.md says why 10%).
inline constexpr double kEquivalenceBand = 0.10;

/// Where a ratio's interval lies against the band [1/(1+band), 1+band].
enum class Difference {
  kClearlyLess,  ///< wholly below the band
  kSame,         ///< meets the band: practically the same within the noise
  kClearlyMore,  ///< wholly above the band
};

Difference differenceOf(const Interval& ratio, double band = kEquivalenceBand);

/// "133.9 [130.2, 137.5]": a time with its interval, to a tenth of a microsecond.
std::string withInterval(double value, const Interval& ci);

/// "1.09x [1.02, 1.17]"; "4.00x" where the interval is the ratio itself (a counted figure, or
/// times that vary in step).
std::string ratioWithInterval(const Ratio& ratio);

}  // namespace collido
