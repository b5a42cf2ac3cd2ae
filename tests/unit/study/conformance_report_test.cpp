// collido conformance's report: the kit's GoogleTest JSON read into checks, and the table printed
// through the runner's text table (a header, a rule, aligned columns), every failure line kept.
#include <collido/study/conformance_report.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace collido::study {
namespace {

constexpr const char* kReport = R"({"testsuites": [
  {"name": "Backends/PluginConformance", "testsuite": [
    {"name": "AnswersTheBundledScenes/obbtree", "result": "COMPLETED", "detail": "12 scenes"},
    {"name": "RefusesNaN/obbtree", "result": "SKIPPED", "detail": "no distance"},
    {"name": "AnswersExactly/wrong", "result": "COMPLETED", "failures": [
      {"failure": "/src/kit.cpp:10\nlinked/pairs: measured 3, exact 2\nview: collido view x.json"},
      {"failure": "Failed\nlinked/hit: measured true, exact false"}]}]}]})";

TEST(ConformanceReport, ReadsChecksAndEveryFailureLine) {
  const std::string path = test::makeTempDirectory("conformance_report") + "/report.json";
  test::writeFile(path, kReport);
  const std::vector<ConformanceRow> rows = readConformanceReport(path);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].check, "PluginConformance.AnswersTheBundledScenes/obbtree");
  EXPECT_EQ(rows[0].result, "pass");
  EXPECT_EQ(rows[0].detail, "12 scenes");
  EXPECT_EQ(rows[1].result, "skip");
  EXPECT_EQ(rows[2].result, "FAIL");
  EXPECT_EQ(rows[2].detail, "linked/pairs: measured 3, exact 2");
  EXPECT_EQ(rows[2].more, (std::vector<std::string>{"view: collido view x.json",
                                                    "linked/hit: measured true, exact false"}));

  test::writeFile(path, "{\"testsuites\": [");  // the kit died while writing it
  EXPECT_TRUE(readConformanceReport(path).empty());
  EXPECT_TRUE(readConformanceReport(path + ".missing").empty());
}

TEST(ConformanceReport, TableIsTheRunnersWithFailureLinesUnderTheirDetail) {
  const std::string path = test::makeTempDirectory("conformance_table") + "/report.json";
  test::writeFile(path, kReport);
  const std::string table = conformanceTable(readConformanceReport(path));
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end; (end = table.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(table.substr(start, end - start));
  lines.push_back(table.substr(start));
  ASSERT_GE(lines.size(), 7u) << table;
  EXPECT_EQ(lines[0].rfind("check", 0), 0u) << table;
  EXPECT_EQ(lines[1].find_first_not_of('-'), std::string::npos) << table;  // the rule
  // Every detail, the failures' further lines included, starts in the same column.
  const std::size_t detail = lines[0].find("detail");
  ASSERT_NE(detail, std::string::npos);
  EXPECT_EQ(lines[2].find("12 scenes"), detail) << table;
  EXPECT_EQ(lines[4].find("linked/pairs"), detail) << table;
  EXPECT_EQ(lines[5].find("view: collido"), detail) << table;
  EXPECT_EQ(lines[6].find("linked/hit"), detail) << table;
  EXPECT_EQ(lines.back(), "1 passed, 1 skipped, 1 failed") << table;
}

}  // namespace
}  // namespace collido::study
