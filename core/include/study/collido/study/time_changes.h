#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/runner/time_statistic.h>
#include <collido/status.h>
#include <collido/study/result_store.h>

namespace collido::study {

/// What a change of time against a baseline counts as: only a ratio whose whole 95% interval
/// lies beyond the equivalence band is a change (significant and large); anything else is the
/// same within noise.
enum class Change { kFaster, kSlower, kSame };

/// "faster", "slower" or "same".
const char* changeName(Change change);

/// One (setting, scene, query) measured in a baseline and now.
struct TimeChange {
  std::string backend;
  std::string setting;  ///< Combination::settingText()
  std::string scene;
  std::string query;
  double before_us = 0.0;  ///< meanFrameTimeUs
  double now_us = 0.0;
  Interval before_ci95;
  Interval now_ci95;
  /// Now over before, with its 95% interval; none where a time is 0.
  std::optional<Ratio> ratio;
  Change change = Change::kSame;
};

/// Every setting, scene and query of the ordinary scenes (not the stress scenes) measured in
/// both studies, in `now`'s order: the
/// ratio's interval from both studies' bootstraps, paired by frame where they ran the same
/// frames (their frames are drawn alike; their calls and rounds independently).
std::vector<TimeChange> timeChanges(const std::vector<CombinationResult>& before,
                                    const std::vector<CombinationResult>& now);

/// The same from two summary.json documents (Google Benchmark's format with ci95_us), matched
/// by benchmark name, where no frame is at hand: each interval is read as a normal one of the
/// log time, and the ratio's interval combines them as independent. Errors name `before_name` or
/// `now_name` and the entry.
Result<std::vector<TimeChange>> summaryTimeChanges(const nlohmann::json& before,
                                                   const std::string& before_name,
                                                   const nlohmann::json& now,
                                                   const std::string& now_name);

/// The table `collido compare` prints, with a closing line of counts.
std::string timeChangesText(const std::vector<TimeChange>& changes);

/// The same as JSON: the band, the counts and one entry per row.
nlohmann::json timeChangesJson(const std::vector<TimeChange>& changes);

}  // namespace collido::study
