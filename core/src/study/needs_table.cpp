#include <collido/study/needs_table.h>

#include <map>
#include <sstream>

#include <collido/runner/text_table.h>
#include <collido/runner/time_statistic.h>
#include <collido/study/robustness.h>

namespace collido::study {
namespace {

// Combinations that differ in their needs mode only share this key.
std::string settingKey(const Combination& c) {
  return c.scene_name + "|" + c.backend + "|" + std::to_string(c.resolution) + "|" +
         std::to_string(c.limit);
}

const QueryMeasurement* findQuery(const std::vector<QueryMeasurement>& measurements,
                                  const std::string& query) {
  for (const QueryMeasurement& m : measurements) {
    if (m.query == query && m.ok()) return &m;
  }
  return nullptr;
}

// "240 (67%)": what declaring saved of building for every kind.
std::string savedText(double every, double declared, const char* pattern) {
  if (every <= 0.0) return "-";
  return formatNumber(pattern, every - declared) + " (" +
         formatNumber("%.0f", 100.0 * (every - declared) / every) + "%)";
}

double perTriangle(const QueryMeasurement& m) {
  return m.triangles == 0 ? 0.0
                          : static_cast<double>(m.memory_bytes) / static_cast<double>(m.triangles);
}

}  // namespace

std::string needsTable(const std::vector<CombinationResult>& results) {
  std::map<std::string, std::vector<QueryMeasurement>> declared;
  std::map<std::string, std::vector<QueryMeasurement>> changed;
  for (const CombinationResult& r : results) {
    if (!r.outcome.ok()) continue;
    if (r.combination.needs == NeedsMode::kDeclared)
      declared[settingKey(r.combination)] = tableMeasurements(r);
    if (r.combination.needs == NeedsMode::kChanged)
      changed[settingKey(r.combination)] = tableMeasurements(r);
  }
  std::vector<std::vector<std::string>> rows;
  for (const CombinationResult& every : results) {
    const Combination& c = every.combination;
    if (!every.outcome.ok() || c.needs != NeedsMode::kEvery) continue;
    const auto found_declared = declared.find(settingKey(c));
    const auto found_changed = changed.find(settingKey(c));
    for (const QueryMeasurement& e : tableMeasurements(every)) {
      if (!e.ok()) continue;
      const QueryMeasurement* d =
          found_declared == declared.end() ? nullptr : findQuery(found_declared->second, e.query);
      const QueryMeasurement* h =
          found_changed == changed.end() ? nullptr : findQuery(found_changed->second, e.query);
      // "changed" builds as "declared" does: either gives the build figures.
      const QueryMeasurement* built = d != nullptr ? d : h;
      if (built == nullptr) continue;
      const auto median = [](const QueryMeasurement* m) {
        return m == nullptr ? std::string("-")
                            : withInterval(meanFrameTimeUs(*m), TimeBootstrap(*m).ci95());
      };
      rows.push_back(
          {c.backend, c.scene_name, e.query, bytesPerTriangleText(e.memory_bytes, e.triangles),
           bytesPerTriangleText(built->memory_bytes, built->triangles),
           savedText(perTriangle(e), perTriangle(*built), "%.0f"), formatNumber("%.2f", e.build_ms),
           formatNumber("%.2f", built->build_ms), savedText(e.build_ms, built->build_ms, "%.2f"),
           median(&e), median(d), median(h),
           h == nullptr
               ? std::string("-")
               : std::to_string(h->unasked_frames) + "/" + std::to_string(h->frames.size()),
           h == nullptr
               ? std::string("-")
               : std::to_string(h->reused_pairs) + " / " + std::to_string(h->skipped_pairs),
           h == nullptr ? std::string("-") : std::to_string(h->disagreements)});
    }
  }
  if (rows.empty()) return "";
  std::ostringstream out;
  out << formatTextTable(
      {"backend", "scene", "query", "B/tri every", "B/tri declared", "B/tri saved",
       "build ms every", "build ms declared", "build ms saved", "mean us every", "mean us declared",
       "mean us changed", "frames unasked", "pairs reused / culled", "disagree changed"},
      rows, 3);
  out << "mean us: the " << kTimeStatisticText
      << ". 'every' builds each object for every query kind the backend answers and asks every "
         "pair in every frame (the cold figure); 'declared' builds for the scene's queries only; "
         "'changed' builds as declared and reuses a pair's answer of the frame before when "
         "neither object moved, changed state or deformed, and does not ask a two-object collision "
         "query whose pair the shared broad phase proves apart. 'frames unasked' counts the frames "
         "'changed' answered without asking the backend anything, 'pairs reused / culled' the "
         "object pairs over all frames it answered from the frame before or left unasked as "
         "apart; every such answer is still checked against the exact reference ('disagree "
         "changed').\n";
  return out.str();
}

}  // namespace collido::study
