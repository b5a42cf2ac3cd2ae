// The study's outputs: per-frame JSON lines, the Google Benchmark summary and the table.
#include <collido/study/outputs.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/runner/measurement_columns.h>
#include <collido/study/report_html.h>

#include "study_test_data.h"
#include "support/test_paths.h"

namespace collido::study {
namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

/// ok (obbtree, declared), ok (obbtree, every), crashed (fcl:obb), failed (bullet, exit 3).
std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<CombinationResult> mixedResults() {
  CombinationResult failed = testdata::crashedResult(testdata::combination("bullet"));
  failed.outcome.status = WorkerStatus::kFailed;
  failed.outcome.signal = 0;
  failed.outcome.signal_name.clear();
  failed.outcome.exit_code = 3;
  return {testdata::okResult(testdata::combination("obbtree")),
          testdata::okResult(testdata::combination("obbtree", NeedsMode::kEvery)),
          testdata::crashedResult(testdata::combination("fcl:obb")), failed};
}

TEST(RecordsJsonLines, OneValidLinePerFrame) {
  const std::vector<CombinationResult> results = mixedResults();
  const std::string text = recordsJsonLines(results);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const std::vector<std::string> lines = linesOf(text);
  // Per finished combination: 3 all-pairs frames + 2 boolean frames; none for the skipped
  // query or the workers that died.
  ASSERT_EQ(lines.size(), 2u * 5u);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    SCOPED_TRACE(lines[i]);
    const nlohmann::json line = nlohmann::json::parse(lines[i]);
    ASSERT_TRUE(line.is_object());
    const CombinationResult& r = results[i / 5];
    EXPECT_EQ(line.at("combination"), r.combination.id);
    EXPECT_EQ(line.at("backend"), "obbtree");
    EXPECT_EQ(line.at("scene"), "tori");
    EXPECT_EQ(line.at("needs"), needsModeName(r.combination.needs));
    EXPECT_EQ(line.at("resolution"), 1.0);
    EXPECT_EQ(line.at("limit"), 0);
    for (const char* key :
         {"frame", "median_us", "oracle_intersecting", "reported_intersecting",
          "finest_intersecting", "oracle_pairs", "reported_pairs", "matched_pairs", "invalid_pairs",
          "truncated", "disagrees", "bv_tests", "primitive_tests"}) {
      EXPECT_TRUE(line.contains(key)) << key;
    }
  }
  const nlohmann::json wrong = nlohmann::json::parse(lines[1]);
  EXPECT_EQ(wrong.at("query"), "all_pairs");
  EXPECT_EQ(wrong.at("kind"), "all_pairs");
  EXPECT_EQ(wrong.at("frame"), 1);
  EXPECT_EQ(wrong.at("disagrees"), true);
  EXPECT_EQ(wrong.at("oracle_pairs"), 4);
  EXPECT_EQ(wrong.at("median_us"), 20.0);
  EXPECT_EQ(wrong.at("bv_tests"), 101);
  const nlohmann::json boolean = nlohmann::json::parse(lines[3]);
  EXPECT_EQ(boolean.at("kind"), "boolean");
  EXPECT_EQ(boolean.at("disagrees"), false);
  EXPECT_TRUE(boolean.at("bv_tests").is_null());  // not counted by this backend
  EXPECT_TRUE(boolean.at("finest_intersecting").is_null());
  EXPECT_EQ(recordsJsonLines({}), "");
}

TEST(BenchmarkJson, GoogleBenchmarkFormat) {
  const std::vector<CombinationResult> results = mixedResults();
  const nlohmann::json summary = nlohmann::json::parse(benchmarkJson(results));
  ASSERT_TRUE(summary.contains("context"));
  ASSERT_TRUE(summary.contains("benchmarks"));
  const nlohmann::json& context = summary.at("context");
  for (const char* key : {"date", "host_name", "executable", "num_cpus", "library_build_type"})
    EXPECT_TRUE(context.contains(key)) << key;
  const nlohmann::json& benchmarks = summary.at("benchmarks");
  ASSERT_TRUE(benchmarks.is_array());
  // Two answered queries per finished combination; the skipped one and dead workers are absent.
  ASSERT_EQ(benchmarks.size(), 4u);
  for (const nlohmann::json& b : benchmarks) {
    SCOPED_TRACE(b.dump());
    for (const char* key : {"name", "run_name", "iterations", "real_time", "cpu_time"})
      EXPECT_TRUE(b.contains(key)) << key;
    EXPECT_EQ(b.at("time_unit"), "us");
    EXPECT_EQ(b.at("run_type"), "iteration");
    EXPECT_EQ(b.at("name"), b.at("run_name"));
    EXPECT_EQ(b.at("peak_rss_bytes"), 48u * 1024u * 1024u);
  }
  EXPECT_EQ(benchmarks[0].at("name"), "obbtree/tori/all_pairs");
  // real_time is the study's statistic, the mean of the frames' medians, with its interval.
  EXPECT_DOUBLE_EQ(benchmarks[0].at("real_time").get<double>(), 70.0 / 3.0);
  const nlohmann::json& ci = benchmarks[0].at("ci95_us");
  ASSERT_EQ(ci.size(), 2u);
  EXPECT_LT(ci.at(0).get<double>(), 70.0 / 3.0);
  EXPECT_GT(ci.at(1).get<double>(), 70.0 / 3.0);
  EXPECT_NE(context.at("time_statistic").get<std::string>().find("95%"), std::string::npos);
  EXPECT_EQ(benchmarks[0].at("iterations"), 3);
  EXPECT_EQ(benchmarks[0].at("max_us"), 40.0);
  EXPECT_EQ(benchmarks[0].at("disagreements"), 1);
  EXPECT_EQ(benchmarks[0].at("false_negatives"), 1);
  EXPECT_EQ(benchmarks[0].at("finest_disagreements"), 1);
  EXPECT_DOUBLE_EQ(benchmarks[0].at("recall").get<double>(), 0.6);
  EXPECT_DOUBLE_EQ(benchmarks[0].at("bytes_per_triangle").get<double>(), 300.0);
  EXPECT_DOUBLE_EQ(benchmarks[0].at("heap_bytes_per_triangle").get<double>(), 310.0);
  EXPECT_DOUBLE_EQ(benchmarks[0].at("bv_tests").get<double>(), 101.0);  // per query
  EXPECT_EQ(benchmarks[1].at("name"), "obbtree/tori/boolean");
  EXPECT_FALSE(benchmarks[1].contains("bv_tests"));
  EXPECT_FALSE(benchmarks[1].contains("finest_disagreements"));
  EXPECT_EQ(benchmarks[2].at("name"), "obbtree/tori/all_pairs/needs=every");
  // Names are unique, so dashboards tell the rows apart.
  std::set<std::string> names;
  for (const nlohmann::json& b : benchmarks)
    names.insert(b.at("name").get<std::string>());
  EXPECT_EQ(names.size(), benchmarks.size());

  const nlohmann::json empty = nlohmann::json::parse(benchmarkJson({}));
  EXPECT_TRUE(empty.at("benchmarks").empty());
}

TEST(StudyTable, RowsSavingsAndFailures) {
  const std::string table = studyTable(mixedResults());
  for (const char* column : {"backend", "setting", "mean us [95% CI]", "disagree", "coarse err",
                             "B/tri heap", "RSS MiB"})
    EXPECT_NE(table.find(column), std::string::npos) << column;
  EXPECT_NE(table.find("needs=every"), std::string::npos) << table;
  EXPECT_NE(table.find("skipped"), std::string::npos) << table;
  // The declared/every pair of obbtree on tori gives the savings section.
  EXPECT_NE(table.find("What the scene's needs save"), std::string::npos) << table;
  // Both dead workers are in the failures, with their signal or exit code.
  const std::size_t failures = table.find("\nFailures:\n");
  ASSERT_NE(failures, std::string::npos) << table;
  const std::string tail = table.substr(failures);
  EXPECT_NE(tail.find("tori · fcl:obb: worker crashed (SIGSEGV)"), std::string::npos) << tail;
  EXPECT_NE(tail.find("tori · bullet: worker failed (exit 3)"), std::string::npos) << tail;
  EXPECT_EQ(tail.find("obbtree"), std::string::npos) << tail;
}

// collido run's table and the study's show a measurement through the same declared columns.
TEST(StudyTable, SharesItsColumnsWithTheRunTable) {
  const CombinationResult r = testdata::okResult(testdata::combination("obbtree"));
  const QueryMeasurement& m = r.measurements.front();
  RunReport report;
  report.measurements = {m};
  const std::string run = formatRunTable(report);
  const std::string study = studyTable({r});
  std::string cells;
  for (const std::string& cell : measurementCells(m))
    cells += (cells.empty() ? "" : " ") + cell;
  for (const std::string& table : {run, study}) {
    SCOPED_TRACE(table);
    EXPECT_NE(table.find("mean us [95% CI]"), std::string::npos);
    std::string squeezed;  // the row with its padding squeezed to single spaces
    for (const char c : table) {
      if (c != ' ' || squeezed.empty() || squeezed.back() != ' ') squeezed += c;
    }
    EXPECT_NE(squeezed.find(cells), std::string::npos) << cells;
  }
}

TEST(StudyTable, NoSavingsWithoutAPairAndNoFailuresWhenAllFinish) {
  const std::string table = studyTable({testdata::okResult(testdata::combination("obbtree"))});
  EXPECT_EQ(table.find("What the scene's needs save"), std::string::npos) << table;
  EXPECT_EQ(table.find("Failures"), std::string::npos) << table;
  EXPECT_NE(table.find("obbtree"), std::string::npos) << table;
}

TEST(StudyTable, FailedQueriesAreListedAsFailures) {
  CombinationResult r = testdata::okResult(testdata::combination("ode"));
  r.measurements[1].status = MeasurementStatus::failed("frame 0: engine failure: out of cheese");
  const std::string table = studyTable({r});
  const std::size_t failures = table.find("\nFailures:\n");
  ASSERT_NE(failures, std::string::npos) << table;
  EXPECT_NE(
      table.find("tori · ode / boolean: failed: frame 0: engine failure: out of cheese", failures),
      std::string::npos)
      << table;
}

TEST(WriteStudyOutputs, WritesTheFiveFiles) {
  const std::string dir = test::makeTempDirectory("outputs");
  const std::vector<CombinationResult> results = mixedResults();
  ASSERT_TRUE(writeStudyOutputs(dir, results).ok());
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"records.jsonl", "sections.json", "summary.json",
                                             "table.txt", "times.json"}));
  std::ifstream table(dir + "/table.txt");
  std::stringstream text;
  text << table.rdbuf();
  EXPECT_EQ(text.str(), studyTable(results));
  const Status missing = writeStudyOutputs(dir + "/missing", results);
  EXPECT_FALSE(missing.ok());
}

// The settings the plan left out come from plan.json, once, after the table of every setting;
// a plan written before they were left out (no such key) has none.
TEST(WriteStudyOutputs, ListsWhatThePlanLeftOutOnce) {
  const std::string dir = test::makeTempDirectory("outputs_not_applicable");
  const ResultStore store(dir);
  const std::vector<CombinationResult> results = mixedResults();
  const std::vector<NotApplicable> left_out = {
      {"ode", "tori", QueryKind::kDistance, {QueryKindSet(5), true}},
      {"ode", "clearance", QueryKind::kDistance, {QueryKindSet(5), true}}};
  const FieldSides field{"fcl", "bullet"};
  ASSERT_TRUE(store.writePlan({results[0].combination}, left_out, RunOrder{}, field).ok());
  Result<std::vector<NotApplicable>> stored = store.readNotApplicable();
  ASSERT_TRUE(stored.ok()) << stored.status().message();
  EXPECT_EQ(stored.value().size(), 2u);
  ASSERT_TRUE(writeStudyOutputs(dir, results).ok());
  std::ifstream file(dir + "/table.txt");
  std::stringstream text;
  text << file.rdbuf();
  const std::string table = text.str();
  EXPECT_EQ(table, studyTable(results, left_out, field));
  ASSERT_TRUE(store.readFieldSides().ok());
  EXPECT_EQ(store.readFieldSides().value().ours, "fcl");
  const std::size_t section = table.find("\nNot applicable, so not planned");
  ASSERT_NE(section, std::string::npos) << table;
  EXPECT_LT(section, table.find("\nFailures:"));
  EXPECT_NE(
      table.find("ode      boolean, contacts  tori (distance), clearance (distance)", section),
      std::string::npos)
      << table;

  test::writeFile(dir + "/plan.json", "{\"collidoscope_plan\": 1, \"combinations\": []}");
  stored = store.readNotApplicable();
  ASSERT_TRUE(stored.ok());
  EXPECT_TRUE(stored.value().empty());
  EXPECT_EQ(store.readFieldSides().value().ours, "obbtree");
  test::writeFile(dir + "/plan.json",
                  "{\"combinations\": [], \"not_applicable\": [{\"backend\": 3}]}");
  EXPECT_NE(store.readNotApplicable().status().message().find(dir + "/plan.json"),
            std::string::npos);
}

// sections.json keys table.txt's summary sections, so that a tool finds the field section
// whatever the study's field sides name it.
TEST(WriteStudyOutputs, SectionsAreKeyedAndPrintedInTheTable) {
  const std::string dir = test::makeTempDirectory("outputs_sections");
  const std::vector<CombinationResult> results = {
      testdata::okResult(testdata::combination("obbtree")),
      testdata::okResult(testdata::combination("fcl:obb"))};
  const FieldSides field{"fcl", "obbtree"};
  ASSERT_TRUE(ResultStore(dir).writePlan({results[0].combination}, {}, RunOrder{}, field).ok());
  ASSERT_TRUE(writeStudyOutputs(dir, results).ok());
  const std::string table = readFile(dir + "/table.txt");
  const nlohmann::json json = nlohmann::json::parse(readFile(dir + "/sections.json"));
  std::map<std::string, nlohmann::json> by_key;
  for (const nlohmann::json& section : json.at("sections")) {
    by_key[section.at("key").get<std::string>()] = section;
    const std::string printed =
        section.at("heading").get<std::string>() + ":\n" + section.at("text").get<std::string>();
    EXPECT_NE(table.find(printed), std::string::npos) << printed;
  }
  ASSERT_EQ(by_key.count("field"), 1u) << json.dump(1);
  EXPECT_EQ(by_key["field"].at("title"), "fcl against the field");
  ASSERT_EQ(by_key.count("what_to_pick"), 1u);
  EXPECT_EQ(by_key["what_to_pick"].at("title"), "What to pick");
  EXPECT_EQ(table.rfind("What to pick (per scene and query):\n", 0), 0u) << table;
}

TEST(ReportData, ListsWhatThePlanLeftOutWithWhy) {
  const nlohmann::json data =
      reportData(mixedResults(), {}, "t",
                 {{"ode", "clearance", QueryKind::kDistance, {QueryKindSet(5), true}}});
  ASSERT_EQ(data.at("not_applicable").size(), 1u);
  EXPECT_EQ(data["not_applicable"][0]["backend"], "ode");
  EXPECT_EQ(data["not_applicable"][0]["scene"], "clearance");
  EXPECT_EQ(data["not_applicable"][0]["why"], "answers boolean, contacts; the scene asks distance");
  EXPECT_TRUE(reportData(mixedResults(), {}, "t").at("not_applicable").empty());
}

}  // namespace
}  // namespace collido::study

namespace collido::study {
namespace {

// The dashboard's script is the files web/report/scripts.json lists, joined in its order; a name
// that reaches outside the folder, or a manifest that is not a list, is refused naming the file.
TEST(ReportPage, ScriptIsTheManifestsFilesInOrderAndNothingOutside) {
  const std::string web = test::makeTempDirectory("report_web");
  std::filesystem::create_directories(web + "/report");
  test::writeFile(web + "/report/template.html",
                  "<title>@TITLE@</title><style>@CSS@</style><script>@VEGA@@VEGA_LITE@"
                  "@VEGA_EMBED@</script><script>@REPORT_JS@</script><pre>@DATA@</pre>");
  test::writeFile(web + "/report/report.css", "body {}");
  for (const char* library : {"vega/build/vega.min.js", "vega-lite/build/vega-lite.min.js",
                              "vega-embed/build/vega-embed.min.js"}) {
    const std::filesystem::path file = std::filesystem::path(web) / "node_modules" / library;
    std::filesystem::create_directories(file.parent_path());
    test::writeFile(file.string(), "/* library */");
  }
  test::writeFile(web + "/report/first.js", "const First = 1;");
  test::writeFile(web + "/report/second.js", "const Second = First + 1;");
  test::writeFile(web + "/report/scripts.json", R"(["first.js", "second.js"])");
  const Result<std::string> page = renderReport(nlohmann::json{{"title", "t"}}, web);
  ASSERT_TRUE(page.ok()) << page.status().toString();
  const std::size_t first = page.value().find("const First = 1;");
  const std::size_t second = page.value().find("const Second = First + 1;");
  ASSERT_NE(first, std::string::npos);
  ASSERT_NE(second, std::string::npos);
  EXPECT_LT(first, second);

  for (const char* manifest : {R"(["first.js", "../report.css"])", R"(["first.js", 3])",
                               R"({"scripts": ["first.js"]})", "[]"}) {
    test::writeFile(web + "/report/scripts.json", manifest);
    const Result<std::string> refused = renderReport(nlohmann::json{{"title", "t"}}, web);
    ASSERT_FALSE(refused.ok()) << manifest;
    EXPECT_NE(refused.status().message().find("scripts.json"), std::string::npos)
        << refused.status().message();
  }
  test::writeFile(web + "/report/scripts.json", R"(["first.js", "missing.js"])");
  const Result<std::string> missing = renderReport(nlohmann::json{{"title", "t"}}, web);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find("missing.js"), std::string::npos)
      << missing.status().message();
}

}  // namespace
}  // namespace collido::study
