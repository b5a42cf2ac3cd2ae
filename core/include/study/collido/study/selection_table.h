#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/runner/time_statistic.h>
#include <collido/study/result_store.h>

namespace collido::study {

/// "fcl" for "fcl:obb", "bullet" for "bullet[margin=0]": the plugin a backend setting belongs to.
std::string backendFamily(const std::string& backend);

/// One backend setting's figures on one scene and query.
struct PickedSetting {
  std::string backend;   ///< the setting, as backend text
  double mean_us = 0.0;  ///< meanFrameTimeUs
  Interval ci95_us;      ///< its 95% interval (TimeBootstrap)
  std::size_t memory_bytes = 0;
  std::size_t triangles = 0;
  std::size_t wrong_frames = 0;  ///< frames whose answer differed from the oracle's
  std::size_t frames = 0;
  /// All-pairs queries: the share of the exact pairs reported and of the reported pairs that are
  /// exact, over every frame (the dashboard's recall and precision budget).
  std::optional<double> recall;
  std::optional<double> precision;
  /// Every other setting of the same scene and query: its time over this one's, with the 95%
  /// interval paired by frame (none where a time is 0).
  std::vector<std::pair<std::string, std::optional<Ratio>>> versus;
  /// Those this one is clearly faster than: the interval wholly above the equivalence band.
  std::vector<std::string> clearly_faster_than;
};

/// A choice, the settings it does not clearly beat, and the setting it beat: the best other
/// backend family's.
struct Pick {
  PickedSetting chosen;
  std::optional<PickedSetting> runner_up;
  /// The runner-up's time (or memory) over the pick's, with its 95% interval (paired by frame;
  /// memory is counted, not sampled, so its interval is the ratio itself).
  std::optional<Ratio> runner_up_ratio;
  /// The other settings the pick was chosen among whose time (or memory) over the pick's meets
  /// the equivalence band: ties, fastest (or smallest) first. Empty: a clear win.
  std::vector<std::string> ties;
};

/// What to pick for one scene (at one resolution) and query, among the settings that answered
/// every frame, built as declared, without an answer cap. A pick is the best by its estimate; it
/// is a clear win only over the settings its interval separates from it beyond the band
/// (kEquivalenceBand), and names the others as ties.
struct SceneQueryPicks {
  std::string scene;
  double resolution = 1.0;
  std::string query;
  std::optional<Pick> fastest_exact;   ///< fastest with no wrong frame
  std::optional<Pick> fastest_within;  ///< fastest with wrong frames within the budget
  std::optional<Pick> smallest_exact;  ///< least model memory with no wrong frame
  std::vector<PickedSetting> fastest_per_family;
  /// Every setting considered, in the study's order (the dashboard applies its own budget).
  std::vector<PickedSetting> settings;
  /// When the fastest setting of all is wrong on some frame and faster than the fastest exact
  /// one (or none is exact): what choosing it costs, for people.
  std::string cost;
};

/// How much error a reader accepts for "fastest within the budget".
struct PickBudget {
  double wrong_frame_share = 0.05;  ///< at most this share of a query's frames wrong
};

/// Per scene and query of the ordinary scenes (stress scenes are the robustness matrix's), the
/// settings to pick, in the order the study ran them.
std::vector<SceneQueryPicks> whatToPick(const std::vector<CombinationResult>& results,
                                        const PickBudget& budget = {});

/// The "What to pick" section of table.txt; empty without a scene.
std::string whatToPickText(const std::vector<SceneQueryPicks>& picks, const PickBudget& budget);

/// The same for summary.json ("what_to_pick").
nlohmann::json whatToPickJson(const std::vector<SceneQueryPicks>& picks, const PickBudget& budget);

}  // namespace collido::study
