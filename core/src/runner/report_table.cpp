#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <collido/runner/runner.h>
#include <collido/runner/text_table.h>

namespace collido {

std::string formatRunTable(const RunReport& report) {
  const std::vector<std::string> header = {
      "backend", "scene",  "query",     "frames",   "median us", "p90 us", "FN",
      "FP",      "recall", "precision", "disagree", "build ms",  "B/tri",  "B/tri heap"};
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> notes;
  std::vector<std::string> tracking;
  std::vector<std::string> distances;
  std::vector<std::string> contacts;
  std::set<std::string> tracked;  // (scene, query): every backend has the same figure
  for (const QueryMeasurement& m : report.measurements) {
    if (m.tracking_false_contacts && tracked.insert(m.scene + " / " + m.query).second) {
      tracking.push_back(m.scene + " / " + m.query + ": on the poses recovered from markers the " +
                         "exact answer has " + std::to_string(*m.tracking_false_contacts) +
                         " false and " + std::to_string(m.tracking_missed_contacts.value_or(0)) +
                         " missed contact frame(s) against the true poses" +
                         (m.tracking_possible_contacts
                              ? "; within tracking error (3 sigma) contact is possible in " +
                                    std::to_string(*m.tracking_possible_contacts) +
                                    " frame(s), and " +
                                    std::to_string(m.tracking_missed_within_margin.value_or(0)) +
                                    " true contact frame(s) fall outside that"
                              : std::string()));
    }
    if (!m.ok()) {
      notes.push_back(m.backend + " / " + m.scene + " / " + m.query + ": " + m.status.text());
      rows.push_back({m.backend, m.scene, m.query, m.status.skipped() ? "skipped" : "failed"});
      continue;
    }
    if (m.max_distance_error) {
      distances.push_back(
          m.backend + " / " + m.scene + " / " + m.query + ": largest error " +
          formatNumber("%.3g", *m.max_distance_error) +
          (m.max_relative_distance_error
               ? " (" + formatNumber("%.3g", *m.max_relative_distance_error) + " of the distance)"
               : std::string()));
    }
    if (m.contact)
      contacts.push_back(m.backend + " / " + m.scene + " / " + m.query + ": " +
                         contactScoreText(*m.contact));
    const bool pairs = m.kind == QueryKind::kAllPairs;
    rows.push_back({m.backend, m.scene, m.query, std::to_string(m.frames.size()),
                    formatNumber("%.1f", m.median_us), formatNumber("%.1f", m.p90_us),
                    std::to_string(m.false_negatives), std::to_string(m.false_positives),
                    pairs ? formatNumber("%.4f", m.recall) : "-",
                    pairs ? formatNumber("%.4f", m.precision) : "-",
                    std::to_string(m.disagreements), formatNumber("%.2f", m.build_ms),
                    bytesPerTriangleText(m.memory_bytes, m.triangles),
                    m.heap_bytes ? bytesPerTriangleText(*m.heap_bytes, m.triangles) : "n/a"});
  }
  std::ostringstream out;
  out << formatTextTable(header, rows, 3);
  for (const std::string& note : notes)
    out << "note: " << note << "\n";
  for (const std::string& line : tracking)
    out << "tracking: " << line << "\n";
  for (const std::string& line : distances)
    out << "distance: " << line << "\n";
  for (const std::string& line : contacts)
    out << "contacts: " << line << "\n";
  for (const std::string& problem : report.problems)
    out << "problem: " << problem << "\n";
  return out.str();
}

}  // namespace collido
