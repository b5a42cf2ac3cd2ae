#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <collido/runner/runner.h>

namespace collido {
namespace {

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), pattern, value);
  return buffer;
}

std::string bytesPerTriangle(std::size_t bytes, std::size_t triangles) {
  if (triangles == 0) return "-";
  return format("%.0f", static_cast<double>(bytes) / static_cast<double>(triangles));
}

}  // namespace

std::string formatRunTable(const RunReport& report) {
  const std::vector<std::string> header = {
      "backend", "scene",  "query",     "frames",   "median us", "p90 us", "FN",
      "FP",      "recall", "precision", "disagree", "build ms",  "B/tri",  "B/tri heap"};
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> notes;
  for (const QueryMeasurement& m : report.measurements) {
    if (!m.ok()) {
      notes.push_back(m.backend + " / " + m.scene + " / " + m.query + ": " + m.status);
      rows.push_back({m.backend, m.scene, m.query, m.status.substr(0, m.status.find(':')), "", "",
                      "", "", "", "", "", "", "", ""});
      continue;
    }
    const bool pairs = m.kind == QueryKind::kAllPairs;
    rows.push_back({m.backend, m.scene, m.query, std::to_string(m.frames.size()),
                    format("%.1f", m.median_us), format("%.1f", m.p90_us),
                    std::to_string(m.false_negatives), std::to_string(m.false_positives),
                    pairs ? format("%.4f", m.recall) : "-",
                    pairs ? format("%.4f", m.precision) : "-", std::to_string(m.disagreements),
                    format("%.2f", m.build_ms), bytesPerTriangle(m.memory_bytes, m.triangles),
                    m.heap_bytes ? bytesPerTriangle(*m.heap_bytes, m.triangles) : "n/a"});
  }
  std::vector<std::size_t> width(header.size());
  for (std::size_t c = 0; c < header.size(); ++c) {
    width[c] = header[c].size();
    for (const auto& row : rows)
      width[c] = std::max(width[c], row[c].size());
  }
  std::ostringstream out;
  const auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const bool numeric = c >= 3;
      const std::string pad(width[c] - cells[c].size(), ' ');
      out << (c == 0 ? "" : "  ") << (numeric ? pad + cells[c] : cells[c] + pad);
    }
    out << "\n";
  };
  line(header);
  std::size_t total = 0;
  for (std::size_t w : width)
    total += w + 2;
  out << std::string(total - 2, '-') << "\n";
  for (const auto& row : rows)
    line(row);
  for (const std::string& note : notes)
    out << "note: " << note << "\n";
  for (const std::string& problem : report.problems)
    out << "problem: " << problem << "\n";
  return out.str();
}

}  // namespace collido
