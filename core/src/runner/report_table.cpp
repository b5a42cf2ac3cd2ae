#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <collido/runner/measurement_columns.h>
#include <collido/runner/runner.h>
#include <collido/runner/text_table.h>

namespace collido {

std::string formatRunTable(const RunReport& report) {
  std::vector<std::string> header = {"backend", "scene", "query"};
  for (const std::string& column : measurementHeaders())
    header.push_back(column);
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
    std::vector<std::string> row = {m.backend, m.scene, m.query};
    for (std::string& cell : measurementCells(m))
      row.push_back(std::move(cell));
    rows.push_back(std::move(row));
  }
  std::ostringstream out;
  out << formatTextTable(header, rows, 3) << measurementColumnsLegend("the --json report");
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
