#include <collido/study/selection_table.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include <collido/runner/text_table.h>
#include <collido/study/robustness.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;

PickedSetting settingOf(const std::string& backend, const QueryMeasurement& m) {
  PickedSetting s;
  s.backend = backend;
  s.mean_us = meanFrameMedianUs(m);
  s.memory_bytes = m.memory_bytes;
  s.triangles = m.triangles;
  s.wrong_frames = m.disagreements;
  s.frames = m.frames.size();
  if (m.kind == QueryKind::kAllPairs) {
    s.recall = m.recall;
    s.precision = m.precision;
  }
  return s;
}

bool exact(const PickedSetting& s) {
  return s.wrong_frames == 0;
}

// The best of `settings` that `admit` lets in by `better`, and the best of another family.
template <typename Admit, typename Better>
std::optional<Pick> bestOf(const std::vector<PickedSetting>& settings, Admit admit, Better better) {
  const PickedSetting* best = nullptr;
  for (const PickedSetting& s : settings) {
    if (admit(s) && (best == nullptr || better(s, *best))) best = &s;
  }
  if (best == nullptr) return std::nullopt;
  const PickedSetting* second = nullptr;
  for (const PickedSetting& s : settings) {
    if (!admit(s) || backendFamily(s.backend) == backendFamily(best->backend)) continue;
    if (second == nullptr || better(s, *second)) second = &s;
  }
  Pick pick{*best, std::nullopt};
  if (second != nullptr) pick.runner_up = *second;
  return pick;
}

bool faster(const PickedSetting& a, const PickedSetting& b) {
  return a.mean_us < b.mean_us;
}

bool smaller(const PickedSetting& a, const PickedSetting& b) {
  const double per_a = a.triangles == 0 ? 0.0 : static_cast<double>(a.memory_bytes) / a.triangles;
  const double per_b = b.triangles == 0 ? 0.0 : static_cast<double>(b.memory_bytes) / b.triangles;
  return per_a < per_b || (per_a == per_b && faster(a, b));
}

std::string wrongText(const PickedSetting& s) {
  return std::to_string(s.wrong_frames) + " of " + std::to_string(s.frames);
}

std::string ratioText(double ratio) {
  return formatNumber("%.2f", ratio) + "x";
}

// What picking the fastest setting of all costs, when it is not the fastest exact one.
std::string costLine(const std::vector<PickedSetting>& settings,
                     const std::optional<Pick>& fastest_exact) {
  const PickedSetting* fastest = nullptr;
  for (const PickedSetting& s : settings) {
    if (fastest == nullptr || faster(s, *fastest)) fastest = &s;
  }
  if (fastest == nullptr || exact(*fastest)) return "";
  if (!fastest_exact) {
    const PickedSetting* fewest = fastest;
    for (const PickedSetting& s : settings) {
      if (s.wrong_frames < fewest->wrong_frames ||
          (s.wrong_frames == fewest->wrong_frames && faster(s, *fewest)))
        fewest = &s;
    }
    return "no setting is exact on every frame; the fewest wrong frames: " + fewest->backend +
           " (" + wrongText(*fewest) + ")";
  }
  const PickedSetting& chosen = fastest_exact->chosen;
  if (fastest->mean_us <= 0.0) return "";
  return fastest->backend + " is " + ratioText(chosen.mean_us / fastest->mean_us) +
         " faster than " + chosen.backend + " here but wrong on " + wrongText(*fastest) + " frames";
}

Json settingJson(const PickedSetting& s) {
  return {{"backend", s.backend},
          {"mean_us", s.mean_us},
          {"bytes_per_triangle",
           s.triangles == 0 ? Json() : Json(static_cast<double>(s.memory_bytes) / s.triangles)},
          {"wrong_frames", s.wrong_frames},
          {"frames", s.frames},
          {"recall", s.recall ? Json(*s.recall) : Json()},
          {"precision", s.precision ? Json(*s.precision) : Json()}};
}

Json pickJson(const std::optional<Pick>& pick, bool by_memory) {
  if (!pick) return nullptr;
  Json json = settingJson(pick->chosen);
  json["runner_up"] = pick->runner_up ? settingJson(*pick->runner_up) : Json();
  if (pick->runner_up) {
    const double ours =
        by_memory ? static_cast<double>(pick->chosen.memory_bytes) : pick->chosen.mean_us;
    const double theirs =
        by_memory ? static_cast<double>(pick->runner_up->memory_bytes) : pick->runner_up->mean_us;
    json["runner_up_ratio"] = ours > 0.0 ? Json(theirs / ours) : Json();
  }
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

}  // namespace

std::string backendFamily(const std::string& backend) {
  return backend.substr(0, backend.find_first_of(":["));
}

double meanFrameMedianUs(const QueryMeasurement& m) {
  if (m.frames.empty()) return 0.0;
  double total = 0.0;
  for (const FrameRecord& f : m.frames)
    total += f.median_us;
  return total / static_cast<double>(m.frames.size());
}

std::vector<SceneQueryPicks> whatToPick(const std::vector<CombinationResult>& results,
                                        const PickBudget& budget) {
  using Key = std::tuple<std::string, double, std::string>;
  std::map<Key, std::vector<PickedSetting>> groups;
  std::vector<Key> order;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (!r.outcome.ok() || !c.category.empty() || c.needs != NeedsMode::kDeclared || c.limit != 0)
      continue;
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok() || m.frames.empty()) continue;
      const Key key{c.scene_name, c.resolution, m.query};
      if (groups.find(key) == groups.end()) order.push_back(key);
      groups[key].push_back(settingOf(c.backend, m));
    }
  }
  std::vector<SceneQueryPicks> picks;
  for (const Key& key : order) {
    const std::vector<PickedSetting>& settings = groups[key];
    SceneQueryPicks p;
    std::tie(p.scene, p.resolution, p.query) = key;
    p.settings = settings;
    p.fastest_exact = bestOf(settings, exact, faster);
    p.fastest_within = bestOf(
        settings,
        [&](const PickedSetting& s) {
          return static_cast<double>(s.wrong_frames) <=
                 budget.wrong_frame_share * static_cast<double>(s.frames);
        },
        faster);
    p.smallest_exact = bestOf(settings, exact, smaller);
    std::vector<std::string> families;
    for (const PickedSetting& s : settings) {
      const std::string family = backendFamily(s.backend);
      if (std::find(families.begin(), families.end(), family) != families.end()) continue;
      families.push_back(family);
      p.fastest_per_family.push_back(
          bestOf(
              settings,
              [&](const PickedSetting& other) { return backendFamily(other.backend) == family; },
              faster)
              ->chosen);
    }
    p.cost = costLine(settings, p.fastest_exact);
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
              formatNumber("%.1f", s.mean_us) + " us";
      if (s.wrong_frames != 0) line += " (wrong on " + wrongText(s) + ")";
    }
    per_family.push_back(line);
    std::vector<std::string> row = {sceneText(p), p.query};
    if (p.fastest_exact) {
      const Pick& f = *p.fastest_exact;
      row.push_back(f.chosen.backend);
      row.push_back(formatNumber("%.1f", f.chosen.mean_us));
      row.push_back(f.runner_up && f.chosen.mean_us > 0.0
                        ? ratioText(f.runner_up->mean_us / f.chosen.mean_us)
                        : "-");
    } else {
      row.insert(row.end(), {"none exact", "-", "-"});
    }
    if (p.fastest_within) {
      row.push_back(p.fastest_within->chosen.backend);
      row.push_back(formatNumber("%.1f", p.fastest_within->chosen.mean_us));
      row.push_back(wrongText(p.fastest_within->chosen));
    } else {
      row.insert(row.end(), {"none", "-", "-"});
    }
    if (p.smallest_exact) {
      const Pick& s = *p.smallest_exact;
      row.push_back(s.chosen.backend);
      row.push_back(bytesPerTriangleText(s.chosen.memory_bytes, s.chosen.triangles));
      row.push_back(s.runner_up && s.chosen.memory_bytes > 0
                        ? ratioText(static_cast<double>(s.runner_up->memory_bytes) /
                                    static_cast<double>(s.chosen.memory_bytes))
                        : "-");
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
         "mean over frames of each frame's median (us per query); 'vs next' = the best other "
         "backend family's time (or memory) over the pick's.\n";
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
                    {"fastest_exact", pickJson(p.fastest_exact, false)},
                    {"fastest_within_budget", pickJson(p.fastest_within, false)},
                    {"smallest_exact", pickJson(p.smallest_exact, true)},
                    {"fastest_per_family", families},
                    {"settings", settingsJson(p.settings)},
                    {"cost", p.cost.empty() ? Json() : Json(p.cost)}});
  }
  return {{"budget", {{"wrong_frame_share", budget.wrong_frame_share}}}, {"picks", rows}};
}

}  // namespace collido::study
