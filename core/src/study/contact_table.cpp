#include <collido/study/contact_table.h>

#include <sstream>

#include <collido/runner/text_table.h>
#include <collido/runner/time_statistic.h>
#include <collido/study/robustness.h>

namespace collido::study {

std::string contactTable(const std::vector<CombinationResult>& results) {
  std::vector<std::vector<std::string>> rows;
  const auto figure = [](const std::optional<double>& value) {
    return value ? formatNumber("%.3g", *value) : std::string("-");
  };
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (!r.outcome.ok()) continue;
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok() || !m.contact) continue;
      const ContactScore& s = *m.contact;
      const double frames = m.frames.empty() ? 1.0 : static_cast<double>(m.frames.size());
      rows.push_back({c.backend, c.settingText(), c.scene_name, m.query,
                      withInterval(meanFrameTimeUs(m), TimeBootstrap(m).ci95()),
                      formatNumber("%.1f", static_cast<double>(s.contacts) / frames),
                      figure(s.position_error), figure(s.surface_error), figure(s.normal_error_deg),
                      figure(s.depth_error),
                      s.coverage ? formatNumber("%.1f", 100.0 * *s.coverage) + "%" : "-",
                      std::to_string(s.false_pairs), std::to_string(s.bad_normals + s.bad_depths),
                      std::to_string(m.disagreements)});
    }
  }
  if (rows.empty()) return "";
  std::ostringstream out;
  out << formatTextTable(
      {"backend", "setting", "scene", "query", "mean us [95% CI]", "contacts/frame", "point err",
       "surface err", "normal deg", "depth err", "coverage", "false pairs", "bad", "disagree"},
      rows, 4);
  out << "mean us: the " << kTimeStatisticText
      << ". Each contact is held to the exact contact of the triangle pair it names (or, naming "
         "none, of the nearest intersecting pair), as docs/DESIGN.md defines it: 'point err' is "
         "the largest distance of a contact point to that pair's exact intersection set, "
         "'surface err' to the farther of its two triangles, 'normal deg' the largest angle to "
         "the nearer face normal, 'depth err' the largest difference from the depth along that "
         "face; 'coverage' is the share of the exact intersection curve whose pairs some contact "
         "stands for; 'false pairs' name triangles that do not meet; 'bad' counts non-unit "
         "normals and negative depths; 'disagree' frames with the wrong contact verdict.\n";
  return out.str();
}

}  // namespace collido::study
