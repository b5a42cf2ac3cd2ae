#include <collido/study/continuous_table.h>

#include <cstddef>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include <collido/runner/text_table.h>
#include <collido/runner/time_statistic.h>
#include <collido/study/plan.h>
#include <collido/study/robustness.h>
#include <collido/study/selection_table.h>

namespace collido::study {
namespace {

// One setting's answers to one query over a step, counted per step.
struct StepAnswers {
  std::string backend;
  bool discrete = false;  // the runner's sub-steps, not the backend's own answer
  QueryMeasurement measurement;
  std::size_t touching = 0;  // steps the oracle proves touching
  std::size_t missed = 0;
  std::size_t falsely = 0;
  std::size_t coarse = 0;  // time coarser than asked
  std::size_t wrong = 0;   // brackets contradicting the oracle's, or a witness that does not touch

  bool right() const { return missed == 0 && falsely == 0 && coarse == 0 && wrong == 0; }
};

StepAnswers countSteps(const CombinationResult& r, const QueryMeasurement& m) {
  StepAnswers s{r.combination.backend, answersBySubsteps(r.combination.backend), m};
  for (const FrameRecord& f : m.frames) {
    const bool touches = f.oracle_touches.value_or(false);
    s.touching += touches ? 1 : 0;
    s.missed += touches && !f.reported_intersecting ? 1 : 0;
    s.falsely += f.oracle_touches && !*f.oracle_touches && f.reported_intersecting ? 1 : 0;
    s.coarse += f.coarserThanAsked() ? 1 : 0;
    // A missed contact's free part runs past it, which the oracle counts invalid too: missed.
    s.wrong += f.invalid_first_contact && f.reported_intersecting ? 1 : 0;
  }
  return s;
}

template <typename Admit>
const StepAnswers* fastest(const std::vector<StepAnswers>& answers, Admit admit) {
  const StepAnswers* best = nullptr;
  for (const StepAnswers& a : answers) {
    if (!admit(a)) continue;
    if (best == nullptr || meanFrameTimeUs(a.measurement) < meanFrameTimeUs(best->measurement))
      best = &a;
  }
  return best;
}

std::string timeText(const StepAnswers& a) {
  return withInterval(meanFrameTimeUs(a.measurement), TimeBootstrap(a.measurement).ci95());
}

// The certified pick against the peer's fastest certified answer: "3.1x [2.9, 3.3] faster",
// "≈ the same" within the band, or slower.
std::string againstPeer(const StepAnswers& ours, const StepAnswers* peer) {
  if (peer == nullptr) return "-";
  const std::optional<Ratio> ratio =
      timeRatio(TimeBootstrap(peer->measurement), TimeBootstrap(ours.measurement));
  if (!ratio) return "-";
  std::string verdict = "faster";
  switch (differenceOf(ratio->ci95)) {
    case Difference::kClearlyMore:
      break;
    case Difference::kSame:
      verdict = "the same within the band";
      break;
    case Difference::kClearlyLess:
      verdict = "slower";
      break;
  }
  std::string text =
      peer->backend + " " + timeText(*peer) + ": " + ratioWithInterval(*ratio) + " " + verdict;
  if (!peer->right())
    text += " (wrong on " + std::to_string(peer->measurement.disagreements) + " of " +
            std::to_string(peer->measurement.frames.size()) + " steps)";
  return text;
}

// A discrete setting with its time and, when it did not reach the asked width, its time error.
std::string discreteText(const StepAnswers& a) {
  std::string text = a.backend + " " + timeText(a);
  if (a.coarse > 0 && a.measurement.max_first_contact_error)
    text += ", time err " + formatNumber("%.3g", *a.measurement.max_first_contact_error);
  return text;
}

}  // namespace

std::string continuousTable(const std::vector<CombinationResult>& results,
                            const FieldSides& sides) {
  // Per scene (and resolution) and query, built as declared, as the other picks are.
  using Key = std::tuple<std::string, std::string>;
  std::map<Key, std::vector<StepAnswers>> groups;
  std::vector<Key> order;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (!r.outcome.ok() || !c.category.empty() || c.needs != NeedsMode::kDeclared || c.limit != 0)
      continue;
    const std::string scene = c.resolution == 1.0
                                  ? c.scene_name
                                  : c.scene_name + " r=" + formatNumber("%g", c.resolution);
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok() || !queryKindInfo(m.kind).over_a_step) continue;
      const Key key{scene, m.query};
      if (groups.count(key) == 0) order.push_back(key);
      groups[key].push_back(countSteps(r, m));
    }
  }
  if (order.empty()) return "";
  const std::string peer_family = backendFamily(sides.peer);
  std::vector<std::vector<std::string>> picks;
  std::vector<std::vector<std::string>> rows;
  for (const Key& key : order) {
    const std::vector<StepAnswers>& answers = groups[key];
    const auto certified = [](const StepAnswers& a) { return !a.discrete && a.right(); };
    const StepAnswers* pick = fastest(answers, certified);
    const StepAnswers* peer = fastest(answers, [&](const StepAnswers& a) {
      return !a.discrete && backendFamily(a.backend) == peer_family;
    });
    // The fastest discrete setting right on every step, else the fastest that missed nothing.
    const StepAnswers* discrete =
        fastest(answers, [](const StepAnswers& a) { return a.discrete && a.right(); });
    if (discrete == nullptr) {
      discrete = fastest(answers, [](const StepAnswers& a) {
        return a.discrete && a.missed == 0 && a.falsely == 0 && a.wrong == 0;
      });
    }
    picks.push_back({std::get<0>(key), std::get<1>(key),
                     pick ? pick->backend + " " + timeText(*pick) : "none right on every step",
                     pick ? againstPeer(*pick, peer) : "-",
                     discrete ? discreteText(*discrete) : "none missed nothing"});
    for (const StepAnswers& a : answers) {
      const QueryMeasurement& m = a.measurement;
      rows.push_back(
          {a.backend, std::get<0>(key), std::get<1>(key), timeText(a),
           std::to_string(m.frames.size()), std::to_string(a.touching), std::to_string(a.missed),
           std::to_string(a.falsely),
           m.max_first_contact_error ? formatNumber("%.3g", *m.max_first_contact_error) : "-",
           std::to_string(a.coarse), std::to_string(a.wrong)});
    }
  }
  std::ostringstream out;
  out << formatTextTable(
      {"scene", "query", "pick: fastest certified, right on every step (us a step)",
       "against " + peer_family + "'s own (their time over ours)",
       "fastest discrete right here (else: that missed nothing)"},
      picks, 4);
  out << "\n"
      << formatTextTable({"backend", "scene", "query", "us a step [95% CI]", "steps", "touching",
                          "missed", "false", "time err", "coarse", "wrong"},
                         rows, 4);
  out << "us a step: the " << kTimeStatisticText
      << ". touching: steps the oracle proves touching (docs/ORACLE.md, \"First contact over a "
         "step\"); missed and false: steps whose verdict differs; time err: the largest error of "
         "the first-contact time within the reported bracket, as a share of the step; coarse: "
         "steps whose time is off by more than two bracket widths asked (sub-steps at N give "
         "1/N); wrong: brackets that contradict the oracle's or witnesses that do not touch. "
         "Certified answers are a backend's own; substeps=N is the runner's discrete checks at "
         "N + 1 times of the step, which catch a contact only where a check lands.\n";
  return out.str();
}

}  // namespace collido::study
