#include <collido/study/selection_table.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include <collido/runner/measurement_json.h>
#include <collido/runner/text_table.h>
#include <collido/study/robustness.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;

/// One setting of a scene and query, with the bootstrap of its time.
struct Candidate {
  PickedSetting setting;
  TimeBootstrap time;
};

Candidate candidateOf(const std::string& backend, const QueryMeasurement& m) {
  Candidate c{PickedSetting{}, TimeBootstrap(m)};
  PickedSetting& s = c.setting;
  s.backend = backend;
  s.mean_us = c.time.estimate();
  s.ci95_us = c.time.ci95();
  s.memory_bytes = m.memory_bytes;
  s.triangles = m.triangles;
  s.wrong_frames = m.disagreements;
  s.frames = m.frames.size();
  if (queryKindInfo(m.kind).has(AnswerPart::kPairSet)) {
    s.recall = m.recall;
    s.precision = m.precision;
  }
  return c;
}

bool exact(const PickedSetting& s) {
  return s.wrong_frames == 0;
}

bool faster(const PickedSetting& a, const PickedSetting& b) {
  return a.mean_us < b.mean_us;
}

double perTriangle(const PickedSetting& s) {
  return s.triangles == 0 ? 0.0 : static_cast<double>(s.memory_bytes) / s.triangles;
}

bool smaller(const PickedSetting& a, const PickedSetting& b) {
  return perTriangle(a) < perTriangle(b) || (perTriangle(a) == perTriangle(b) && faster(a, b));
}

/// Time or memory: what a pick is best by.
enum class By { kTime, kMemory };

/// `theirs`' figure over `ours`', with its interval: time is sampled (the paired bootstrap's ratio,
/// computed once per pair into `ours`' versus list), memory is counted (its interval is the
/// ratio itself).
std::optional<Ratio> ratioOf(const Candidate& theirs, const Candidate& ours, By by) {
  if (by == By::kTime) {
    for (const auto& [backend, ratio] : ours.setting.versus) {
      if (backend == theirs.setting.backend) return ratio;
    }
    return std::nullopt;
  }
  if (perTriangle(ours.setting) <= 0.0) return std::nullopt;
  const double ratio = perTriangle(theirs.setting) / perTriangle(ours.setting);
  return Ratio{ratio, {ratio, ratio}};
}

/// Whether `winner` beats `other` beyond the equivalence band with 95% confidence. Without a
/// ratio (a time of 0 in some replicate), their intervals must not overlap.
bool clearlyBeats(const Candidate& winner, const Candidate& other, By by) {
  if (const std::optional<Ratio> ratio = ratioOf(other, winner, by))
    return differenceOf(ratio->ci95) == Difference::kClearlyMore;
  return by == By::kTime && other.setting.ci95_us.lo > winner.setting.ci95_us.hi;
}

// The best of `all` that `admit` lets in, the settings it does not clearly beat, and the best of
// another family.
template <typename Admit>
std::optional<Pick> bestOf(const std::vector<Candidate>& all, Admit admit, By by) {
  const auto better = [by](const Candidate& a, const Candidate& b) {
    return by == By::kTime ? faster(a.setting, b.setting) : smaller(a.setting, b.setting);
  };
  const Candidate* best = nullptr;
  for (const Candidate& c : all) {
    if (admit(c.setting) && (best == nullptr || better(c, *best))) best = &c;
  }
  if (best == nullptr) return std::nullopt;
  const Candidate* second = nullptr;
  std::vector<const Candidate*> tied;
  for (const Candidate& c : all) {
    if (!admit(c.setting) || &c == best) continue;
    if (!clearlyBeats(*best, c, by)) tied.push_back(&c);
    if (backendFamily(c.setting.backend) == backendFamily(best->setting.backend)) continue;
    if (second == nullptr || better(c, *second)) second = &c;
  }
  std::stable_sort(tied.begin(), tied.end(),
                   [&](const Candidate* a, const Candidate* b) { return better(*a, *b); });
  Pick pick{best->setting, std::nullopt, std::nullopt, {}};
  for (const Candidate* c : tied)
    pick.ties.push_back(c->setting.backend);
  if (second != nullptr) {
    pick.runner_up = second->setting;
    pick.runner_up_ratio = ratioOf(*second, *best, by);
  }
  return pick;
}

std::string wrongText(const PickedSetting& s) {
  return std::to_string(s.wrong_frames) + " of " + std::to_string(s.frames);
}

// What picking the fastest setting of all costs, when it is not the fastest exact one.
std::string costLine(const std::vector<Candidate>& all, const std::optional<Pick>& fastest_exact) {
  const Candidate* fastest = nullptr;
  for (const Candidate& c : all) {
    if (fastest == nullptr || faster(c.setting, fastest->setting)) fastest = &c;
  }
  if (fastest == nullptr || exact(fastest->setting)) return "";
  if (!fastest_exact) {
    const PickedSetting* fewest = &fastest->setting;
    for (const Candidate& c : all) {
      const PickedSetting& s = c.setting;
      if (s.wrong_frames < fewest->wrong_frames ||
          (s.wrong_frames == fewest->wrong_frames && faster(s, *fewest)))
        fewest = &s;
    }
    return "no setting is exact on every frame; the fewest wrong frames: " + fewest->backend +
           " (" + wrongText(*fewest) + ")";
  }
  const PickedSetting& chosen = fastest_exact->chosen;
  const auto exact_one = std::find_if(all.begin(), all.end(), [&](const Candidate& c) {
    return c.setting.backend == chosen.backend;
  });
  const std::optional<Ratio> ratio = ratioOf(*exact_one, *fastest, By::kTime);
  if (!ratio) return "";
  const PickedSetting& wrong = fastest->setting;
  return wrong.backend + " is " + ratioWithInterval(*ratio) + " faster than " + chosen.backend +
         " here but wrong on " + wrongText(wrong) + " frames";
}

// {"fcl:obb": [ratio, low, high], ...}: each other setting's time over this one's.
Json versusJson(const PickedSetting& s) {
  Json versus = Json::object();
  for (const auto& [backend, ratio] : s.versus)
    versus[backend] = ratio ? Json::array({ratio->value, ratio->ci95.lo, ratio->ci95.hi}) : Json();
  return versus;
}

Json settingJson(const PickedSetting& s) {
  return {{"backend", s.backend},
          {"mean_us", s.mean_us},
          {"ci95_us", intervalJson(s.ci95_us)},
          {"bytes_per_triangle", s.triangles == 0 ? Json() : Json(perTriangle(s))},
          {"wrong_frames", s.wrong_frames},
          {"frames", s.frames},
          {"recall", s.recall ? Json(*s.recall) : Json()},
          {"precision", s.precision ? Json(*s.precision) : Json()},
          {"versus", versusJson(s)},
          {"clearly_faster_than", s.clearly_faster_than}};
}

Json pickJson(const std::optional<Pick>& pick) {
  if (!pick) return nullptr;
  Json json = settingJson(pick->chosen);
  json["ties"] = pick->ties;
  json["runner_up"] = pick->runner_up ? settingJson(*pick->runner_up) : Json();
  json["runner_up_ratio"] = pick->runner_up_ratio ? Json(pick->runner_up_ratio->value) : Json();
  json["runner_up_ratio_ci95"] =
      pick->runner_up_ratio ? intervalJson(pick->runner_up_ratio->ci95) : Json();
  return json;
}

Json settingsJson(const std::vector<PickedSetting>& settings) {
  Json list = Json::array();
  for (const PickedSetting& s : settings)
    list.push_back(settingJson(s));
  return list;
}

std::string sceneText(const SceneQueryPicks& p) {
  return p.resolution == 1.0 ? p.scene : p.scene + " r=" + formatNumber("%g", p.resolution);
}

// "obbtree ≈ fcl:obb, bullet": a pick and its ties.
std::string pickText(const Pick& pick) {
  std::string text = pick.chosen.backend;
  for (const std::string& tie : pick.ties)
    text += (&tie == &pick.ties.front() ? " ≈ " : ", ") + tie;
  return text;
}

}  // namespace

std::string backendFamily(const std::string& backend) {
  return backend.substr(0, backend.find_first_of(":["));
}

std::vector<SceneQueryPicks> whatToPick(const std::vector<CombinationResult>& results,
                                        const PickBudget& budget) {
  using Key = std::tuple<std::string, double, std::string>;
  std::map<Key, std::vector<Candidate>> groups;
  std::vector<Key> order;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (!r.outcome.ok() || !c.category.empty() || c.needs != NeedsMode::kDeclared || c.limit != 0)
      continue;
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      // Queries over a step have their own picks, which tell certified answers from discrete
      // ones (continuous_table.h).
      if (!m.ok() || m.frames.empty() || queryKindInfo(m.kind).over_a_step) continue;
      const Key key{c.scene_name, c.resolution, m.query};
      if (groups.find(key) == groups.end()) order.push_back(key);
      groups[key].push_back(candidateOf(c.backend, m));
    }
  }
  std::vector<SceneQueryPicks> picks;
  for (const Key& key : order) {
    std::vector<Candidate>& all = groups[key];
    // Every pair's time ratio once: ties, picks and the cost line read them from `versus`.
    for (Candidate& c : all) {
      for (const Candidate& other : all) {
        if (&other != &c)
          c.setting.versus.emplace_back(other.setting.backend, timeRatio(other.time, c.time));
      }
    }
    for (Candidate& c : all) {
      for (const Candidate& other : all) {
        if (&other != &c && clearlyBeats(c, other, By::kTime))
          c.setting.clearly_faster_than.push_back(other.setting.backend);
      }
    }
    SceneQueryPicks p;
    std::tie(p.scene, p.resolution, p.query) = key;
    for (const Candidate& c : all)
      p.settings.push_back(c.setting);
    p.fastest_exact = bestOf(all, exact, By::kTime);
    p.fastest_within = bestOf(
        all,
        [&](const PickedSetting& s) {
          return static_cast<double>(s.wrong_frames) <=
                 budget.wrong_frame_share * static_cast<double>(s.frames);
        },
        By::kTime);
    p.smallest_exact = bestOf(all, exact, By::kMemory);
    std::vector<std::string> families;
    for (const Candidate& c : all) {
      const std::string family = backendFamily(c.setting.backend);
      if (std::find(families.begin(), families.end(), family) != families.end()) continue;
      families.push_back(family);
      p.fastest_per_family.push_back(
          bestOf(
              all,
              [&](const PickedSetting& other) { return backendFamily(other.backend) == family; },
              By::kTime)
              ->chosen);
    }
    p.cost = costLine(all, p.fastest_exact);
    picks.push_back(std::move(p));
  }
  return picks;
}

std::string whatToPickText(const std::vector<SceneQueryPicks>& picks, const PickBudget& budget) {
  if (picks.empty()) return "";
  const std::string within =
      "within " + formatNumber("%g", budget.wrong_frame_share * 100.0) + "% wrong";
  const std::vector<std::string> header = {
      "scene", "query", "fastest exact",  "us",    "vs next", within,
      "us",    "wrong", "smallest exact", "B/tri", "vs next"};
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> costs;
  std::vector<std::string> per_family;
  for (const SceneQueryPicks& p : picks) {
    std::string line = sceneText(p) + " / " + p.query + ":";
    for (const PickedSetting& s : p.fastest_per_family) {
      line += (&s == &p.fastest_per_family.front() ? " " : ", ") + s.backend + " " +
              withInterval(s.mean_us, s.ci95_us) + " us";
      if (s.wrong_frames != 0) line += " (wrong on " + wrongText(s) + ")";
    }
    per_family.push_back(line);
    std::vector<std::string> row = {sceneText(p), p.query};
    if (p.fastest_exact) {
      const Pick& f = *p.fastest_exact;
      row.push_back(pickText(f));
      row.push_back(withInterval(f.chosen.mean_us, f.chosen.ci95_us));
      row.push_back(f.runner_up_ratio ? ratioWithInterval(*f.runner_up_ratio) : "-");
    } else {
      row.insert(row.end(), {"none exact", "-", "-"});
    }
    if (p.fastest_within) {
      row.push_back(pickText(*p.fastest_within));
      row.push_back(
          withInterval(p.fastest_within->chosen.mean_us, p.fastest_within->chosen.ci95_us));
      row.push_back(wrongText(p.fastest_within->chosen));
    } else {
      row.insert(row.end(), {"none", "-", "-"});
    }
    if (p.smallest_exact) {
      const Pick& s = *p.smallest_exact;
      row.push_back(pickText(s));
      row.push_back(bytesPerTriangleText(s.chosen.memory_bytes, s.chosen.triangles));
      row.push_back(s.runner_up_ratio ? ratioWithInterval(*s.runner_up_ratio) : "-");
    } else {
      row.insert(row.end(), {"none exact", "-", "-"});
    }
    rows.push_back(row);
    if (!p.cost.empty()) costs.push_back(sceneText(p) + " / " + p.query + ": " + p.cost);
  }
  std::ostringstream out;
  out << formatTextTable(header, rows, 3);
  out << "Per scene and query, among the settings that answered every frame (built as declared, "
         "no answer cap): the fastest with no wrong frame, the fastest with at most "
      << formatNumber("%g", budget.wrong_frame_share * 100.0)
      << "% of its frames wrong, and the exact one with the least model memory. Times are the "
         "mean over frames of each frame's median call (us per query) with its 95% bootstrap "
         "interval [low, high]; 'vs next' = the best other backend family's time (or memory) "
         "over the pick's, its interval paired by frame. A pick is a clear win only over the "
         "settings it beats by more than "
      << formatNumber("%g", kEquivalenceBand * 100.0)
      << "% with 95% confidence; 'a ≈ b, c' names the settings it ties with, fastest (or "
         "smallest) first (docs/STUDY.md, \"Times and their intervals\").\n";
  if (!costs.empty()) {
    out << "What the fastest setting of all costs where it is not exact:\n";
    for (const std::string& line : costs)
      out << "  " << line << "\n";
  }
  out << "The fastest setting of each backend family:\n";
  for (const std::string& line : per_family)
    out << "  " << line << "\n";
  return out.str();
}

Json whatToPickJson(const std::vector<SceneQueryPicks>& picks, const PickBudget& budget) {
  Json rows = Json::array();
  for (const SceneQueryPicks& p : picks) {
    Json families = Json::array();
    for (const PickedSetting& s : p.fastest_per_family)
      families.push_back(settingJson(s));
    rows.push_back({{"scene", p.scene},
                    {"resolution", p.resolution},
                    {"query", p.query},
                    {"fastest_exact", pickJson(p.fastest_exact)},
                    {"fastest_within_budget", pickJson(p.fastest_within)},
                    {"smallest_exact", pickJson(p.smallest_exact)},
                    {"fastest_per_family", families},
                    {"settings", settingsJson(p.settings)},
                    {"cost", p.cost.empty() ? Json() : Json(p.cost)}});
  }
  return {{"budget", {{"wrong_frame_share", budget.wrong_frame_share}}},
          {"statistic", kTimeStatisticText},
          {"equivalence_band", kEquivalenceBand},
          {"picks", rows}};
}

}  // namespace collido::study
