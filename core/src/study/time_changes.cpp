#include <collido/study/time_changes.h>

#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include <collido/runner/measurement_json.h>
#include <collido/runner/text_table.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;

/// The normal quantile of a two-sided 95% interval.
constexpr double kZ95 = 1.959963984540054;

Change changeOf(const std::optional<Ratio>& ratio) {
  if (!ratio) return Change::kSame;
  switch (differenceOf(ratio->ci95)) {
    case Difference::kClearlyMore:
      return Change::kSlower;
    case Difference::kClearlyLess:
      return Change::kFaster;
    case Difference::kSame:
      break;
  }
  return Change::kSame;
}

using Key = std::tuple<std::string, std::string, std::string, std::string>;

Key keyOf(const Combination& c, const QueryMeasurement& m) {
  return {c.backend, c.settingText(), c.scene_name, m.query};
}

// Each ordinary measurement of `results` that answered: its setting, scene and query.
std::vector<std::pair<Key, const QueryMeasurement*>> answered(
    const std::vector<CombinationResult>& results) {
  std::vector<std::pair<Key, const QueryMeasurement*>> list;
  for (const CombinationResult& r : results) {
    // Stress scenes are the robustness matrix's: a query a case, timed for no verdict.
    if (!r.outcome.ok() || !r.combination.category.empty()) continue;
    for (const QueryMeasurement& m : r.measurements) {
      if (m.ok() && !m.frames.empty()) list.emplace_back(keyOf(r.combination, m), &m);
    }
  }
  return list;
}

// The log-normal reading of an interval: the log time's standard error, or none.
std::optional<double> logStandardError(const Interval& ci) {
  if (!(ci.lo > 0.0) || !(ci.hi >= ci.lo)) return std::nullopt;
  return (std::log(ci.hi) - std::log(ci.lo)) / (2.0 * kZ95);
}

}  // namespace

const char* changeName(Change change) {
  switch (change) {
    case Change::kFaster:
      return "faster";
    case Change::kSlower:
      return "slower";
    case Change::kSame:
      break;
  }
  return "same";
}

std::vector<TimeChange> timeChanges(const std::vector<CombinationResult>& before,
                                    const std::vector<CombinationResult>& now) {
  std::map<Key, const QueryMeasurement*> earlier;
  for (const auto& [key, m] : answered(before))
    earlier.emplace(key, m);
  std::vector<TimeChange> changes;
  for (const auto& [key, m] : answered(now)) {
    const auto found = earlier.find(key);
    if (found == earlier.end()) continue;
    const TimeBootstrap then(*found->second);
    const TimeBootstrap current(*m);
    TimeChange change;
    std::tie(change.backend, change.setting, change.scene, change.query) = key;
    change.before_us = then.estimate();
    change.now_us = current.estimate();
    change.before_ci95 = then.ci95();
    change.now_ci95 = current.ci95();
    change.ratio = timeRatio(current, then);
    change.change = changeOf(change.ratio);
    changes.push_back(std::move(change));
  }
  return changes;
}

Result<std::vector<TimeChange>> summaryTimeChanges(const Json& before,
                                                   const std::string& before_name, const Json& now,
                                                   const std::string& now_name) {
  struct Entry {
    double time = 0.0;
    Interval ci;
  };
  const auto entries = [](const Json& summary, const std::string& name,
                          std::vector<std::pair<std::string, Entry>>& list) -> Status {
    if (!summary.is_object() || !summary.contains("benchmarks") ||
        !summary.at("benchmarks").is_array()) {
      return Status(StatusCode::kInvalidArgument,
                    name + ": not a summary.json (no \"benchmarks\" array)");
    }
    const Json& benchmarks = summary.at("benchmarks");
    for (std::size_t i = 0; i < benchmarks.size(); ++i) {
      const Json& b = benchmarks[i];
      const std::string where = name + ": /benchmarks/" + std::to_string(i);
      if (!b.is_object() || !b.contains("name") || !b.at("name").is_string() ||
          !b.contains("real_time") || !b.at("real_time").is_number()) {
        return Status(StatusCode::kInvalidArgument, where + ": expected a name and a real_time");
      }
      Entry entry;
      entry.time = b.at("real_time").get<double>();
      entry.ci = {entry.time, entry.time};
      if (b.contains("ci95_us")) {
        const Json& ci = b.at("ci95_us");
        if (!ci.is_array() || ci.size() != 2 || !ci[0].is_number() || !ci[1].is_number())
          return Status(StatusCode::kInvalidArgument, where + "/ci95_us: expected [low, high]");
        entry.ci = {ci[0].get<double>(), ci[1].get<double>()};
      }
      list.emplace_back(b.at("name").get<std::string>(), entry);
    }
    return {};
  };
  std::vector<std::pair<std::string, Entry>> then;
  std::vector<std::pair<std::string, Entry>> current;
  if (Status s = entries(before, before_name, then); !s.ok()) return s;
  if (Status s = entries(now, now_name, current); !s.ok()) return s;
  const std::map<std::string, Entry> earlier(then.begin(), then.end());
  std::vector<TimeChange> changes;
  for (const auto& [name, entry] : current) {
    const auto found = earlier.find(name);
    if (found == earlier.end()) continue;
    TimeChange change;
    // The benchmark name is backend/scene/query[/setting]; it stands whole as the backend.
    change.backend = name;
    change.before_us = found->second.time;
    change.now_us = entry.time;
    change.before_ci95 = found->second.ci;
    change.now_ci95 = entry.ci;
    const std::optional<double> se_before = logStandardError(change.before_ci95);
    const std::optional<double> se_now = logStandardError(change.now_ci95);
    if (change.before_us > 0.0 && change.now_us > 0.0 && se_before && se_now) {
      const double ratio = change.now_us / change.before_us;
      const double half = kZ95 * std::hypot(*se_before, *se_now);
      change.ratio = Ratio{ratio, {ratio * std::exp(-half), ratio * std::exp(half)}};
    }
    change.change = changeOf(change.ratio);
    changes.push_back(std::move(change));
  }
  return changes;
}

std::string timeChangesText(const std::vector<TimeChange>& changes) {
  std::vector<std::vector<std::string>> rows;
  std::size_t counts[3] = {0, 0, 0};
  for (const TimeChange& c : changes) {
    ++counts[static_cast<int>(c.change)];
    rows.push_back({c.backend, c.setting, c.scene, c.query,
                    withInterval(c.before_us, c.before_ci95), withInterval(c.now_us, c.now_ci95),
                    c.ratio ? ratioWithInterval(*c.ratio) : "-", changeName(c.change)});
  }
  std::ostringstream out;
  out << formatTextTable(
      {"backend", "setting", "scene", "query", "before us", "now us", "now/before", "change"}, rows,
      4);
  out << changes.size() << " rows: " << counts[static_cast<int>(Change::kFaster)] << " faster, "
      << counts[static_cast<int>(Change::kSlower)] << " slower, "
      << counts[static_cast<int>(Change::kSame)]
      << " the same. Times: the mean over frames of each frame's median call with its 95% "
         "interval; a row is faster or slower only when the whole 95% interval of now/before "
         "lies beyond the "
      << formatNumber("%g", kEquivalenceBand * 100.0) << "% equivalence band (docs/STUDY.md).\n";
  return out.str();
}

Json timeChangesJson(const std::vector<TimeChange>& changes) {
  Json rows = Json::array();
  Json counts = {{"faster", 0}, {"slower", 0}, {"same", 0}};
  for (const TimeChange& c : changes) {
    counts[changeName(c.change)] = counts[changeName(c.change)].get<int>() + 1;
    rows.push_back({{"backend", c.backend},
                    {"setting", c.setting},
                    {"scene", c.scene},
                    {"query", c.query},
                    {"before_us", c.before_us},
                    {"now_us", c.now_us},
                    {"before_ci95_us", intervalJson(c.before_ci95)},
                    {"now_ci95_us", intervalJson(c.now_ci95)},
                    {"ratio", c.ratio ? Json(c.ratio->value) : Json()},
                    {"ratio_ci95", c.ratio ? intervalJson(c.ratio->ci95) : Json()},
                    {"change", changeName(c.change)}});
  }
  return {{"collidoscope_compare", 1},
          {"equivalence_band", kEquivalenceBand},
          {"counts", counts},
          {"rows", rows}};
}

}  // namespace collido::study
