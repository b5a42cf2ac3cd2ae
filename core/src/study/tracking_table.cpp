#include <collido/study/tracking_table.h>

#include <map>
#include <optional>
#include <sstream>
#include <utility>

#include <collido/runner/text_table.h>
#include <collido/study/robustness.h>

namespace collido::study {

std::string trackingTable(const std::vector<CombinationResult>& results) {
  struct Row {
    std::size_t frames = 0;
    std::size_t truth_contacts = 0;
    std::size_t recovered_contacts = 0;
    std::size_t false_contacts = 0;
    std::size_t missed_contacts = 0;
    std::optional<std::size_t> possible;
    std::optional<std::size_t> outside;
    std::vector<std::string> wrong;  // backends disagreeing with the oracle, with their counts
  };
  std::map<std::pair<std::string, std::string>, Row> rows;
  for (const CombinationResult& r : results) {
    if (!r.outcome.ok()) continue;
    for (const QueryMeasurement& m : tableMeasurements(r)) {
      if (!m.ok() || !m.tracking_false_contacts) continue;
      const auto key = std::make_pair(m.scene, m.query);
      const bool first = rows.count(key) == 0;
      Row& row = rows[key];
      if (first) {
        row.frames = m.frames.size();
        for (const FrameRecord& f : m.frames) {
          row.truth_contacts += f.truth_intersecting.value_or(false) ? 1 : 0;
          row.recovered_contacts += f.oracle_intersecting ? 1 : 0;
        }
        row.false_contacts = *m.tracking_false_contacts;
        row.missed_contacts = m.tracking_missed_contacts.value_or(0);
        row.possible = m.tracking_possible_contacts;
        row.outside = m.tracking_missed_within_margin;
      }
      if (m.disagreements > 0) {
        // The setting too: the same backend built for every need is another combination.
        const std::string setting = r.combination.settingText();
        row.wrong.push_back(r.combination.backend + (setting.empty() ? "" : " " + setting) + " " +
                            std::to_string(m.disagreements));
      }
    }
  }
  if (rows.empty()) return "";
  std::vector<std::vector<std::string>> cells;
  for (const auto& [key, row] : rows) {
    std::string wrong;
    for (const std::string& w : row.wrong)
      wrong += (wrong.empty() ? "" : ", ") + w;
    cells.push_back(
        {key.first, key.second, std::to_string(row.frames), std::to_string(row.truth_contacts),
         std::to_string(row.recovered_contacts), std::to_string(row.false_contacts),
         std::to_string(row.missed_contacts), row.possible ? std::to_string(*row.possible) : "-",
         row.outside ? std::to_string(*row.outside) : "-", wrong.empty() ? "none" : wrong});
  }
  std::ostringstream out;
  out << formatTextTable({"scene", "query", "frames", "contact (true poses)", "contact (recovered)",
                          "false contacts", "missed contacts", "possible contact (3 sigma)",
                          "true contact outside it", "backends wrong on recovered poses (frames)"},
                         cells, 2);
  out << "The recovered poses (from tracked markers) drive every backend and the oracle; "
         "'false' and 'missed' contacts are frames where the exact answer on them differs from "
         "the exact answer on the true poses: the collision error tracking causes, whatever the "
         "backend. 'Possible contact' counts frames where the objects come within 3 times their "
         "predicted pose spread at the recovered poses (the answer within tracking error; '-' "
         "where the spread is unknown), and 'outside it' the true contacts even that missed.\n";
  return out.str();
}

}  // namespace collido::study
