#include <collido/study/deform_table.h>

#include <sstream>

#include <collido/runner/text_table.h>
#include <collido/study/robustness.h>

namespace collido::study {

std::string deformTable(const std::vector<CombinationResult>& results) {
  std::vector<std::vector<std::string>> rows;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (!r.outcome.ok()) continue;
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok() || !m.update_median_us) continue;
      double update_total = 0.0;
      double both_total = 0.0;
      for (const FrameRecord& f : m.frames) {
        update_total += f.update_us.value_or(0.0);
        both_total += f.update_us.value_or(0.0) + f.median_us;
      }
      const double frames = static_cast<double>(m.frames.size());
      rows.push_back({c.backend, c.settingText(), c.scene_name, m.query,
                      std::to_string(m.frames.size()), formatNumber("%.1f", *m.update_median_us),
                      formatNumber("%.1f", update_total / frames),
                      formatNumber("%.1f", m.median_us), formatNumber("%.1f", both_total / frames),
                      m.update_rebuilds ? std::to_string(*m.update_rebuilds) : "-",
                      formatNumber("%.1f", static_cast<double>(m.memory_bytes) / 1024.0),
                      std::to_string(m.disagreements)});
    }
  }
  if (rows.empty()) return "";
  std::ostringstream out;
  out << formatTextTable(
      {"backend", "setting", "scene", "query", "frames", "update median us", "update mean us",
       "query median us", "update+query mean us", "rebuilds", "KiB", "disagree"},
      rows, 4);
  out << "Each frame every deforming object's model gets the frame's positions (update(), timed "
         "once), then the query is asked; 'disagree' counts frames whose answer differed from "
         "the oracle's on the deformed shapes; 'rebuilds' the structures (models or subtrees) the "
         "backend rebuilt instead of refitting, over all frames ('-': it does not count them); "
         "'KiB' the models of the queried objects, every active state's, as the backend counts "
         "them (what states share counted once).\n";
  return out.str();
}

}  // namespace collido::study
