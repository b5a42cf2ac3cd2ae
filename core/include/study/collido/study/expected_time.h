#pragma once

#include <map>
#include <string>
#include <vector>

#include <collido/status.h>
#include <collido/study/result_store.h>

namespace collido::study {

/// Wall seconds each combination took in an earlier study, by Combination::label(); what the next
/// study's expected time is estimated from. A study writes its own as OUT/times.json.
struct CombinationTimes {
  std::map<std::string, double> seconds;
};

/// times.json: {"collidoscope_times": 1, "combinations": {label: wall seconds}} for every
/// combination that finished (crashes and timeouts say nothing about a normal run's time).
std::string timesJson(const std::vector<CombinationResult>& results);

/// Reads a times.json file, or a study folder (its times.json, else its results); errors name
/// the file.
Result<CombinationTimes> loadCombinationTimes(const std::string& path);

/// The time a list of combinations is expected to take.
struct TimeEstimate {
  std::vector<double> seconds;  ///< per combination, in the order given
  std::size_t measured = 0;     ///< combinations timed before under the same label
  std::size_t from_scene = 0;   ///< estimated from the mean of the same scene's other settings
  std::size_t unknown = 0;      ///< no time of the same scene: the mean over all known times
  /// The time the extra rounds of unstable rows may take after the planned ones (the sweep's
  /// adaptive budget): on 2 cores they use most of it.
  double extra_rounds_s = 0.0;

  /// Every combination's time and the extra rounds'.
  double total() const;
};

/// Estimates each combination from `times`: its own earlier time, else the mean of its scene's,
/// else the mean of all. With no times at all, every entry is 0 and `unknown` counts them.
TimeEstimate estimateTimes(const std::vector<const Combination*>& combinations,
                           const CombinationTimes& times);

/// The study's first line: "study: 77 combinations, 77 to run, about 2m40s (64 timed before,
/// 13 from their scene's other settings), results in OUT".
std::string startLine(std::size_t planned, std::size_t to_run, const TimeEstimate& estimate,
                      const std::string& shard, const std::string& out);

}  // namespace collido::study
