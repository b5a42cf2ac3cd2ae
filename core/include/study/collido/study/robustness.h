#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/study/result_store.h>

namespace collido::study {

/// What a backend's answers of one kind on a stress category came to.
enum class AnswersStatus {
  kMeasured,     ///< some answers checked
  kUnsupported,  ///< every query skipped: the backend does not answer this kind
  kFailed,       ///< no answer: queries failed or workers died
  kNone,         ///< nothing asked
};

/// "measured", "unsupported", "failed" or "none": as the tables and robustness.json spell it.
const char* answersStatusName(AnswersStatus status);

/// How one kind of question went for one backend setting on one robustness category, over every
/// query of that kind in the category's stress scenes (each query one case, one frame).
struct RobustnessAnswers {
  std::size_t answered = 0;  ///< answers checked against the oracle (query × frame)
  std::size_t wrong = 0;     ///< answers differing from the oracle's (FrameRecord::disagrees)
  std::size_t false_negatives = 0;  ///< reported apart where the oracle finds contact
  std::size_t false_positives = 0;  ///< reported intersecting where the oracle finds none
  std::size_t unsupported = 0;      ///< queries the backend does not answer (skipped)
  std::size_t failed = 0;  ///< queries with no answer: failed, or their worker did not finish
  // All-pairs answers only (zero for boolean ones):
  std::size_t true_pairs = 0;      ///< the oracle's pairs, over the answers
  std::size_t reported_pairs = 0;  ///< distinct in-range pairs reported
  std::size_t missed_pairs = 0;    ///< true pairs not reported (answers cut by a limit excluded)
  std::size_t extra_pairs = 0;     ///< reported pairs that do not intersect
  std::size_t invalid_pairs = 0;   ///< out-of-range or repeated pairs, and false witnesses

  /// wrong / answered; empty when nothing was answered (never a zero for an unanswered kind).
  std::optional<double> wrongRate() const;
  /// missed / true pairs; empty without true pairs.
  std::optional<double> missedShare() const;
  /// extra / reported pairs; empty without reported pairs.
  std::optional<double> extraShare() const;
  AnswersStatus status() const;
};

/// How far a distance answer of the stress suite may be from the exact distance, relative to it.
/// The runner's general check allows rounding of the coordinates' magnitude, which at contact
/// scale is the whole gap.
constexpr double kStressDistanceRelativeError = 1e-6;

/// One cell of the robustness matrix: a backend setting on a robustness category.
struct RobustnessCell {
  std::string setting;    ///< backend setting as the dashboard labels it, e.g. "obbtree[...]" or
                          ///< "fcl:obb needs=every"
  std::string category;   ///< Combination::category, e.g. "near_touching"
  std::size_t cases = 0;  ///< cases asked (each case asks one boolean and one all-pairs query,
                          ///< or, in the distance category, one boolean and one distance query)
  RobustnessAnswers boolean;
  RobustnessAnswers all_pairs;
  /// Distance answers (the distance category), held to the exact distance at contact scale:
  /// wrong when 0 for meshes apart, positive for touching ones, or off by more than
  /// kStressDistanceRelativeError of the exact distance (FN/FP: the 0-or-not verdict).
  RobustnessAnswers distance;
  /// Combinations of the category whose worker crashed, timed out or failed: "stress_touching:
  /// crashed (SIGSEGV)".
  std::vector<std::string> worker_failures;
};

/// The measurements the study's tables and dashboard show for a combination. A stress scene
/// asks a pair of questions per case (dozens of queries); these show one measurement per query
/// kind over all its cases instead ("boolean, 42 cases": one frame per case, every timed call,
/// builds and memory summed), the robustness matrix giving the per-category detail. Other
/// scenes' measurements are returned as they are.
std::vector<QueryMeasurement> tableMeasurements(const CombinationResult& result);

/// The robustness matrix of a study: one cell per (backend setting, robustness category) over
/// the results of stress scenes (those with a category), settings in result order, categories in
/// the stress suite's order. Results of ordinary scenes are left out.
std::vector<RobustnessCell> robustnessMatrix(const std::vector<CombinationResult>& results);

/// The matrix for people: the share of wrong boolean and of wrong all-pairs answers per setting
/// and category ("unsupported" / "failed" where nothing was answered), then every count. Empty
/// when there is no cell.
std::string robustnessText(const std::vector<RobustnessCell>& cells);

/// The matrix as JSON: an array of cells with every count, the rates and shares (null where
/// undefined) and each kind's status, keys in a fixed order.
nlohmann::ordered_json robustnessJson(const std::vector<RobustnessCell>& cells);

}  // namespace collido::study
