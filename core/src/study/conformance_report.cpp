// collido conformance's view of the kit's report: its checks read from GoogleTest's JSON, and the
// table printed from them with the runner's table formatter.
#include <collido/study/conformance_report.h>

#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/runner/text_table.h>

namespace collido::study {
namespace {

// A failure message without GoogleTest's "file:line" and "Failed" lines, one string per line.
std::vector<std::string> messageLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const bool location = line.rfind('/', 0) == 0 && line.find(' ') == std::string::npos;
    if (!line.empty() && !location && line != "Failed") out.push_back(line);
  }
  if (out.empty()) out.push_back(text);
  return out;
}

ConformanceRow rowOf(const std::string& suite, const nlohmann::json& test) {
  ConformanceRow row;
  const std::size_t slash = suite.find('/');
  row.check =
      (slash == std::string::npos ? suite : suite.substr(slash + 1)) + "." + test.value("name", "");
  if (test.contains("failures")) {
    row.result = "FAIL";
    // Every failure of the check (a scene reports each query that failed), in full.
    for (const auto& failure : test["failures"]) {
      for (const std::string& line : messageLines(failure.value("failure", ""))) {
        if (row.detail.empty()) {
          row.detail = line;
        } else {
          row.more.push_back(line);
        }
      }
    }
  } else {
    row.result = test.value("result", "") == "SKIPPED" ? "skip" : "pass";
    row.detail = test.value("detail", "");
  }
  return row;
}

}  // namespace

std::vector<ConformanceRow> readConformanceReport(const std::string& path) {
  std::vector<ConformanceRow> rows;
  const Result<nlohmann::json> read = io::readJsonFile(path);
  if (!read.ok() || !read.value().is_object()) return rows;
  for (const auto& suite : read.value().value("testsuites", nlohmann::json::array())) {
    for (const auto& test : suite.value("testsuite", nlohmann::json::array()))
      rows.push_back(rowOf(suite.value("name", ""), test));
  }
  return rows;
}

std::string conformanceTable(const std::vector<ConformanceRow>& rows) {
  std::vector<std::vector<std::string>> cells;
  std::map<std::string, int> totals;
  for (const ConformanceRow& r : rows) {
    ++totals[r.result];
    cells.push_back({r.check, r.result, r.detail});
    for (const std::string& line : r.more)
      cells.push_back({"", "", line});
  }
  // No numeric column: every column left-aligned.
  return formatTextTable({"check", "result", "detail"}, cells, 3) + "\n" +
         std::to_string(totals["pass"]) + " passed, " + std::to_string(totals["skip"]) +
         " skipped, " + std::to_string(totals["FAIL"]) + " failed";
}

}  // namespace collido::study
