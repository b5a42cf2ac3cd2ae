#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/study/result_store.h>

namespace collido::study {

/// "fcl" for "fcl:obb", "bullet" for "bullet[margin=0]": the plugin a backend setting belongs to.
std::string backendFamily(const std::string& backend);

/// The mean over frames of each frame's median time: a scene's run time per query, dominated by
/// its dense frames.
double meanFrameMedianUs(const QueryMeasurement& m);

/// One backend setting's figures on one scene and query.
struct PickedSetting {
  std::string backend;  ///< the setting, as backend text
  double mean_us = 0.0;
  std::size_t memory_bytes = 0;
  std::size_t triangles = 0;
  std::size_t wrong_frames = 0;  ///< frames whose answer differed from the oracle's
  std::size_t frames = 0;
  /// All-pairs queries: the share of the exact pairs reported and of the reported pairs that are
  /// exact, over every frame (the dashboard's recall and precision budget).
  std::optional<double> recall;
  std::optional<double> precision;
};

/// A choice and the setting it beat: the best other backend family's.
struct Pick {
  PickedSetting chosen;
  std::optional<PickedSetting> runner_up;
};

/// What to pick for one scene (at one resolution) and query, among the settings that answered
/// every frame, built as declared, without an answer cap.
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
