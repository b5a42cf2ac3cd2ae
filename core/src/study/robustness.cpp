// The robustness matrix: the answers of every backend setting on the stress scenes, grouped by
// robustness category and compared with the exact oracle's.
//
// Each stress case is one boolean and one all-pairs query of one frame, so answers count cases.
// A kind of question a backend does not answer is "unsupported", and one whose queries failed or
// whose worker died is "failed": neither is ever shown as zero errors, and rates are taken over
// the answers actually checked.
#include <collido/study/robustness.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include <collido/runner/text_table.h>
#include <collido/stress/stress_cases.h>

namespace collido::study {
namespace {

using OrderedJson = nlohmann::ordered_json;

std::string settingLabel(const Combination& c) {
  const std::string setting = c.settingText();
  return setting.empty() ? c.backend : c.backend + " " + setting;
}

// Stress categories in the suite's order, then any other name alphabetically.
std::size_t categoryRank(const std::string& category) {
  const std::vector<stress::Category>& all = stress::allCategories();
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (category == stress::categoryName(all[i])) return i;
  }
  return all.size();
}

// A distance answer at contact scale (RobustnessCell::distance).
void addDistanceFrame(const FrameRecord& f, RobustnessAnswers& answers) {
  ++answers.answered;
  if (!f.oracle_distance || !f.reported_distance) {
    ++answers.wrong;
    return;
  }
  const double exact = *f.oracle_distance;
  const double reported = *f.reported_distance;
  if (exact == 0.0 && reported != 0.0) ++answers.false_negatives;
  if (exact != 0.0 && reported == 0.0) ++answers.false_positives;
  const bool wrong = (exact == 0.0) != (reported == 0.0) || f.invalid_distance_witness ||
                     !(std::abs(reported - exact) <= kStressDistanceRelativeError * exact);
  if (wrong) ++answers.wrong;
}

void addFrame(const FrameRecord& f, QueryKind query_kind, RobustnessAnswers& answers) {
  const QueryKindInfo& kind = queryKindInfo(query_kind);
  if (kind.has(AnswerPart::kDistance)) {
    addDistanceFrame(f, answers);
    return;
  }
  ++answers.answered;
  if (f.disagrees(query_kind)) ++answers.wrong;
  if (f.oracle_intersecting && !f.reported_intersecting) ++answers.false_negatives;
  if (!f.oracle_intersecting && f.reported_intersecting) ++answers.false_positives;
  answers.invalid_pairs += f.invalid_pairs;
  if (!kind.has(AnswerPart::kPairSet)) return;
  answers.true_pairs += f.oracle_pairs;
  answers.reported_pairs += f.reported_pairs;
  answers.extra_pairs += f.reported_pairs - std::min(f.reported_pairs, f.matched_pairs);
  // An answer cut short by a limit leaves pairs out on purpose: not counted as missed.
  if (!f.truncated)
    answers.missed_pairs += f.oracle_pairs - std::min(f.oracle_pairs, f.matched_pairs);
}

std::optional<double> share(std::size_t part, std::size_t whole) {
  if (whole == 0) return std::nullopt;
  return static_cast<double>(part) / static_cast<double>(whole);
}

OrderedJson nullable(const std::optional<double>& value) {
  return value ? OrderedJson(*value) : OrderedJson();
}

// "7.1% (3/42)", or the status where nothing was answered; a trailing "+n failed" when some
// queries of a measured cell have no answer.
std::string rateText(const RobustnessAnswers& a) {
  const AnswersStatus status = a.status();
  if (status == AnswersStatus::kFailed) return "failed (" + std::to_string(a.failed) + ")";
  if (status != AnswersStatus::kMeasured) return answersStatusName(status);
  std::string text = formatNumber("%.1f%%", 100.0 * *a.wrongRate()) + " (" +
                     std::to_string(a.wrong) + "/" + std::to_string(a.answered) + ")";
  if (a.failed != 0) text += " +" + std::to_string(a.failed) + " failed";
  return text;
}

std::string shareText(const std::optional<double>& value) {
  return value ? formatNumber("%.4f", *value) : "-";
}

OrderedJson answersJson(const RobustnessAnswers& a, bool pairs) {
  OrderedJson json = {{"status", answersStatusName(a.status())},
                      {"answered", a.answered},
                      {"wrong", a.wrong},
                      {"wrong_rate", nullable(a.wrongRate())},
                      {"false_negatives", a.false_negatives},
                      {"false_positives", a.false_positives},
                      {"unsupported", a.unsupported},
                      {"failed", a.failed},
                      {"invalid_pairs", a.invalid_pairs}};
  if (pairs) {
    json["true_pairs"] = a.true_pairs;
    json["reported_pairs"] = a.reported_pairs;
    json["missed_pairs"] = a.missed_pairs;
    json["missed_share"] = nullable(a.missedShare());
    json["extra_pairs"] = a.extra_pairs;
    json["extra_share"] = nullable(a.extraShare());
  }
  return json;
}

}  // namespace

std::vector<QueryMeasurement> tableMeasurements(const CombinationResult& result) {
  if (result.combination.category.empty()) return result.measurements;
  std::vector<QueryMeasurement> merged;
  std::vector<std::size_t> cases;
  std::vector<std::size_t> failed;
  std::vector<std::string> first_failure;
  for (const QueryMeasurement& m : result.measurements) {
    auto found = std::find_if(merged.begin(), merged.end(),
                              [&m](const QueryMeasurement& x) { return x.kind == m.kind; });
    if (found == merged.end()) {
      QueryMeasurement all;
      all.backend = m.backend;
      all.scene = m.scene;
      all.kind = m.kind;
      all.status = m.status;
      all.heap_bytes = 0;
      all.heap_peak_bytes = 0;
      all.heap_allocations = 0;
      all.heap_probe = m.heap_probe;
      merged.push_back(all);
      cases.push_back(0);
      failed.push_back(0);
      first_failure.emplace_back();
      found = merged.end() - 1;
    }
    const std::size_t i = static_cast<std::size_t>(found - merged.begin());
    QueryMeasurement& all = *found;
    ++cases[i];
    if (m.status.failed()) {
      if (failed[i]++ == 0) first_failure[i] = m.query + ": " + m.status.text();
    }
    // A skipped kind is skipped for every case alike; a measured one keeps "ok" unless one
    // case failed (said below).
    if (m.ok()) all.status = MeasurementStatus();
    for (FrameRecord f : m.frames) {
      f.frame = all.frames.size();
      all.frames.push_back(f);
    }
    all.times_us.insert(all.times_us.end(), m.times_us.begin(), m.times_us.end());
    all.counts_bv_tests = all.counts_bv_tests || m.counts_bv_tests;
    all.counts_primitive_tests = all.counts_primitive_tests || m.counts_primitive_tests;
    all.build_ms += m.build_ms;
    all.triangles += m.triangles;
    all.memory_bytes += m.memory_bytes;
    const auto add = [](auto& total, const auto& part) {
      if (total && part) {
        *total += *part;
      } else {
        total.reset();
      }
    };
    add(all.heap_bytes, m.heap_bytes);
    add(all.heap_peak_bytes, m.heap_peak_bytes);
    add(all.heap_allocations, m.heap_allocations);
  }
  for (std::size_t i = 0; i < merged.size(); ++i) {
    QueryMeasurement& all = merged[i];
    all.query = std::string(queryKindName(all.kind)) + ", " + std::to_string(cases[i]) + " cases";
    if (failed[i] != 0) {
      all.status =
          MeasurementStatus::failed(std::to_string(failed[i]) + " of " + std::to_string(cases[i]) +
                                    " cases, first " + first_failure[i]);
    }
    summariseMeasurement(all);
  }
  return merged;
}

std::optional<double> RobustnessAnswers::wrongRate() const {
  return share(wrong, answered);
}

std::optional<double> RobustnessAnswers::missedShare() const {
  return share(missed_pairs, true_pairs);
}

std::optional<double> RobustnessAnswers::extraShare() const {
  return share(extra_pairs, reported_pairs);
}

const char* answersStatusName(AnswersStatus status) {
  switch (status) {
    case AnswersStatus::kMeasured:
      return "measured";
    case AnswersStatus::kUnsupported:
      return "unsupported";
    case AnswersStatus::kFailed:
      return "failed";
    case AnswersStatus::kNone:
      return "none";
  }
  return "none";
}

AnswersStatus RobustnessAnswers::status() const {
  if (answered != 0) return AnswersStatus::kMeasured;
  if (failed != 0) return AnswersStatus::kFailed;
  if (unsupported != 0) return AnswersStatus::kUnsupported;
  return AnswersStatus::kNone;
}

std::vector<RobustnessCell> robustnessMatrix(const std::vector<CombinationResult>& results) {
  // Cases per scene (at its resolution) from any finished run of it: a worker that died is then
  // charged with the cases it should have answered.
  std::map<std::string, std::size_t> scene_cases;
  const auto scene_key = [](const Combination& c) {
    return c.scene_path + "|" + std::to_string(c.resolution) + "|" + std::to_string(c.limit);
  };
  for (const CombinationResult& r : results) {
    if (r.combination.category.empty() || !r.outcome.ok()) continue;
    const std::size_t booleans = static_cast<std::size_t>(
        std::count_if(r.measurements.begin(), r.measurements.end(),
                      [](const QueryMeasurement& m) { return m.kind == QueryKind::kBoolean; }));
    scene_cases.emplace(scene_key(r.combination), booleans);
  }

  std::vector<RobustnessCell> cells;
  std::map<std::pair<std::string, std::string>, std::size_t> index;
  std::map<std::string, std::size_t> setting_order;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (c.category.empty()) continue;
    const std::string setting = settingLabel(c);
    setting_order.emplace(setting, setting_order.size());
    const auto [found, added] = index.emplace(std::make_pair(setting, c.category), cells.size());
    if (added) {
      RobustnessCell cell;
      cell.setting = setting;
      cell.category = c.category;
      cells.push_back(cell);
    }
    RobustnessCell& cell = cells[found->second];
    if (!r.outcome.ok()) {
      cell.worker_failures.push_back(c.scene_name + ": " + r.outcome.text());
      const auto known = scene_cases.find(scene_key(c));
      const std::size_t lost = known == scene_cases.end() ? 0 : known->second;
      cell.cases += lost;
      cell.boolean.failed += lost;
      (c.category == stress::categoryName(stress::Category::kDistance) ? cell.distance
                                                                       : cell.all_pairs)
          .failed += lost;
      continue;
    }
    for (const QueryMeasurement& m : r.measurements) {
      if (m.kind != QueryKind::kBoolean && m.kind != QueryKind::kAllPairs &&
          m.kind != QueryKind::kDistance)
        continue;
      RobustnessAnswers& answers = m.kind == QueryKind::kBoolean    ? cell.boolean
                                   : m.kind == QueryKind::kAllPairs ? cell.all_pairs
                                                                    : cell.distance;
      if (m.kind == QueryKind::kBoolean) ++cell.cases;
      if (m.status.skipped()) {
        ++answers.unsupported;
      } else if (!m.ok()) {
        ++answers.failed;
      } else {
        for (const FrameRecord& f : m.frames)
          addFrame(f, m.kind, answers);
      }
    }
  }
  std::stable_sort(cells.begin(), cells.end(),
                   [&setting_order](const RobustnessCell& a, const RobustnessCell& b) {
                     const std::size_t sa = setting_order.at(a.setting);
                     const std::size_t sb = setting_order.at(b.setting);
                     if (sa != sb) return sa < sb;
                     const std::size_t ca = categoryRank(a.category);
                     const std::size_t cb = categoryRank(b.category);
                     if (ca != cb) return ca < cb;
                     return a.category < b.category;
                   });
  return cells;
}

std::string robustnessText(const std::vector<RobustnessCell>& cells) {
  if (cells.empty()) return "";
  std::vector<std::string> settings;
  std::vector<std::string> categories;
  std::map<std::pair<std::string, std::string>, const RobustnessCell*> at;
  for (const RobustnessCell& cell : cells) {
    if (std::find(settings.begin(), settings.end(), cell.setting) == settings.end()) {
      settings.push_back(cell.setting);
    }
    if (std::find(categories.begin(), categories.end(), cell.category) == categories.end()) {
      categories.push_back(cell.category);
    }
    at[{cell.setting, cell.category}] = &cell;
  }
  std::sort(categories.begin(), categories.end(), [](const std::string& a, const std::string& b) {
    const std::size_t ra = categoryRank(a);
    const std::size_t rb = categoryRank(b);
    return ra != rb ? ra < rb : a < b;
  });

  std::ostringstream out;
  enum class Answers { kBoolean, kAllPairs, kDistance };
  const auto of = [](const RobustnessCell& cell, Answers which) -> const RobustnessAnswers& {
    return which == Answers::kBoolean    ? cell.boolean
           : which == Answers::kAllPairs ? cell.all_pairs
                                         : cell.distance;
  };
  const auto matrix = [&](const char* title, Answers which) {
    out << title << "\n";
    std::vector<std::string> header = {"backend"};
    header.insert(header.end(), categories.begin(), categories.end());
    std::vector<std::vector<std::string>> rows;
    for (const std::string& setting : settings) {
      std::vector<std::string> row = {setting};
      for (const std::string& category : categories) {
        const auto found = at.find({setting, category});
        row.push_back(found == at.end() ? "-" : rateText(of(*found->second, which)));
      }
      rows.push_back(row);
    }
    out << formatTextTable(header, rows, 1);
  };
  matrix("Wrong boolean answers (share of cases whose answer differs from the oracle's):",
         Answers::kBoolean);
  out << "\n";
  matrix("Wrong all-pairs answers (share of cases whose pair set differs from the oracle's):",
         Answers::kAllPairs);
  const bool distances = std::any_of(cells.begin(), cells.end(), [](const RobustnessCell& cell) {
    return cell.distance.status() != AnswersStatus::kNone;
  });
  if (distances) {
    out << "\n";
    matrix(("Wrong distance answers (0 for meshes apart, positive for touching ones, or off the "
            "exact distance by more than " +
            formatNumber("%g", kStressDistanceRelativeError) + " of it):")
               .c_str(),
           Answers::kDistance);
  }

  out << "\nEvery count (FN/FP: boolean answers apart that intersect / intersecting that are "
         "apart; missed: true pairs not reported, share of true pairs; extra: reported pairs that "
         "do not intersect, share of reported pairs):\n";
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> failures;
  for (const RobustnessCell& cell : cells) {
    const RobustnessAnswers& b = cell.boolean;
    const RobustnessAnswers& p = cell.all_pairs;
    // A count where answers were checked, else the status.
    const auto count = [](const RobustnessAnswers& a, std::size_t n) -> std::string {
      return a.status() == AnswersStatus::kMeasured ? std::to_string(n)
                                                    : answersStatusName(a.status());
    };
    const bool pairs_measured = p.status() == AnswersStatus::kMeasured;
    rows.push_back({cell.setting, cell.category, std::to_string(cell.cases), count(b, b.wrong),
                    std::to_string(b.false_negatives), std::to_string(b.false_positives),
                    count(p, p.wrong), pairs_measured ? std::to_string(p.true_pairs) : "-",
                    pairs_measured ? std::to_string(p.missed_pairs) : "-",
                    pairs_measured ? shareText(p.missedShare()) : "-",
                    pairs_measured ? std::to_string(p.extra_pairs) : "-",
                    pairs_measured ? shareText(p.extraShare()) : "-",
                    count(cell.distance, cell.distance.wrong),
                    std::to_string(b.invalid_pairs + p.invalid_pairs),
                    std::to_string(b.failed + p.failed + cell.distance.failed)});
    for (const std::string& f : cell.worker_failures)
      failures.push_back(cell.setting + " / " + f);
  }
  out << formatTextTable(
      {"backend", "category", "cases", "bool wrong", "FN", "FP", "pairs wrong", "true pairs",
       "missed", "missed share", "extra", "extra share", "dist wrong", "invalid", "no answer"},
      rows, 2);
  if (!failures.empty()) {
    out << "\nWorkers that did not finish (their cases count as no answer):\n";
    for (const std::string& f : failures)
      out << "  " << f << "\n";
  }
  return out.str();
}

nlohmann::ordered_json robustnessJson(const std::vector<RobustnessCell>& cells) {
  OrderedJson list = OrderedJson::array();
  for (const RobustnessCell& cell : cells) {
    list.push_back({{"backend", cell.setting},
                    {"category", cell.category},
                    {"cases", cell.cases},
                    {"boolean", answersJson(cell.boolean, false)},
                    {"all_pairs", answersJson(cell.all_pairs, true)},
                    {"distance", answersJson(cell.distance, false)},
                    {"worker_failures", cell.worker_failures}});
  }
  return list;
}

}  // namespace collido::study
