#include <collido/study/deform_table.h>

#include <sstream>

#include <collido/runner/text_table.h>
#include <collido/runner/time_statistic.h>
#include <collido/study/robustness.h>

namespace collido::study {

std::string deformTable(const std::vector<CombinationResult>& results) {
  std::vector<std::vector<std::string>> rows;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (!r.outcome.ok()) continue;
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok() || !m.update_median_us) continue;
      // Per frame: the update's one call, and that plus the query's median call.
      std::vector<std::vector<double>> updates;
      std::vector<std::vector<double>> both;
      for (const FrameRecord& f : m.frames) {
        updates.push_back({f.update_us.value_or(0.0)});
        both.push_back({f.update_us.value_or(0.0) + f.median_us});
      }
      const TimeBootstrap update(updates);
      const TimeBootstrap update_and_query(both);
      rows.push_back({c.backend, c.settingText(), c.scene_name, m.query,
                      std::to_string(m.frames.size()),
                      withInterval(update.estimate(), update.ci95()),
                      withInterval(meanFrameTimeUs(m), TimeBootstrap(m).ci95()),
                      withInterval(update_and_query.estimate(), update_and_query.ci95()),
                      m.update_rebuilds ? std::to_string(*m.update_rebuilds) : "-",
                      formatNumber("%.1f", static_cast<double>(m.memory_bytes) / 1024.0),
                      std::to_string(m.disagreements)});
    }
  }
  if (rows.empty()) return "";
  std::ostringstream out;
  out << formatTextTable({"backend", "setting", "scene", "query", "frames", "update mean us",
                          "query mean us", "update+query mean us", "rebuilds", "KiB", "disagree"},
                         rows, 4);
  out << "Each frame every deforming object's model gets the frame's positions (update(), timed "
         "once), then the query is asked. Each time is the mean over frames (the query's: of each "
         "frame's median call) with its 95% bootstrap interval [low, high]; 'disagree' counts "
         "frames whose answer differed from "
         "the oracle's on the deformed shapes; 'rebuilds' the structures (models or subtrees) the "
         "backend rebuilt instead of refitting, over all frames ('-': it does not count them); "
         "'KiB' the models of the queried objects, every active state's, as the backend counts "
         "them (what states share counted once).\n";
  return out.str();
}

}  // namespace collido::study
