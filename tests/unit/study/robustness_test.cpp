// The robustness matrix from a hand-made result set: three stress cases of the touching
// category answered by an exact backend, a wrong one, one that does not answer all-pairs
// queries, and one whose worker crashed; an ordinary scene beside them stays out of it.
#include <collido/study/robustness.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/study/outputs.h>
#include <collido/study/report_html.h>

#include "study_test_data.h"
#include "support/test_paths.h"

namespace collido::study {
namespace {

Combination stressCombination(const std::string& backend, NeedsMode needs = NeedsMode::kDeclared) {
  Sweep sweep;
  sweep.needs = {needs};
  return planStudy({{"/scenes/stress/touching.json", "stress_touching", false, "touching"}},
                   {backend}, sweep)
      .front();
}

// One case's answer: the oracle's intersecting flag and pair count, the reported ones.
struct Answer {
  bool oracle = false;
  bool reported = false;
  std::size_t exact_pairs = 0;
  std::size_t reported_pairs = 0;
  std::size_t matched_pairs = 0;
};

QueryMeasurement measurement(const std::string& backend, std::size_t index, QueryKind kind,
                             const Answer& answer) {
  QueryMeasurement m;
  m.backend = backend;
  m.scene = "stress_touching";
  m.query = "touching/s0/" + std::to_string(index) + "/face_face " + queryKindName(kind);
  m.kind = kind;
  m.times_us = {1.0};
  FrameRecord f;
  f.oracle_intersecting = answer.oracle;
  f.reported_intersecting = answer.reported;
  if (kind == QueryKind::kAllPairs) {
    f.oracle_pairs = answer.exact_pairs;
    f.reported_pairs = answer.reported_pairs;
    f.matched_pairs = answer.matched_pairs;
  }
  m.frames = {f};
  summariseMeasurement(m);
  return m;
}

// Three cases: 4 true pairs, 2 true pairs, apart.
const Answer kTruth[3] = {{true, true, 4, 4, 4}, {true, true, 2, 2, 2}, {false, false, 0, 0, 0}};

CombinationResult answering(const Combination& c, const Answer (&booleans)[3],
                            const Answer (&pairs)[3], bool answers_pairs = true) {
  CombinationResult r;
  r.combination = c;
  for (std::size_t i = 0; i < 3; ++i) {
    if (answers_pairs) {
      r.measurements.push_back(measurement(c.backend, i, QueryKind::kAllPairs, pairs[i]));
    } else {
      QueryMeasurement skipped = measurement(c.backend, i, QueryKind::kAllPairs, pairs[i]);
      skipped.frames.clear();
      skipped.status = MeasurementStatus::skipped(c.backend + " does not answer all_pairs queries");
      r.measurements.push_back(skipped);
    }
    r.measurements.push_back(measurement(c.backend, i, QueryKind::kBoolean, booleans[i]));
  }
  return r;
}

// exact (declared and every needs), wrong, ode-like (no all-pairs), crashed, and an ordinary
// scene that has no category.
std::vector<CombinationResult> handMade() {
  // fcl:obb: case 0 reported apart (false negative; 3 of its 4 pairs in the all-pairs answer),
  // case 1 right but one pair too many, case 2 reported intersecting (false positive).
  const Answer wrong_booleans[3] = {{true, false}, {true, true}, {false, true}};
  const Answer wrong_pairs[3] = {
      {true, true, 4, 3, 3}, {true, true, 2, 3, 2}, {false, false, 0, 0, 0}};
  return {answering(stressCombination("obbtree"), kTruth, kTruth),
          answering(stressCombination("obbtree", NeedsMode::kEvery), kTruth, kTruth),
          answering(stressCombination("fcl:obb"), wrong_booleans, wrong_pairs),
          answering(stressCombination("ode"), kTruth, kTruth, /*answers_pairs=*/false),
          testdata::crashedResult(stressCombination("bullet")),
          testdata::okResult(testdata::combination("obbtree"))};
}

TEST(RobustnessMatrix, OneCellPerSettingAndCategory) {
  const std::vector<RobustnessCell> cells = robustnessMatrix(handMade());
  ASSERT_EQ(cells.size(), 5u);
  EXPECT_EQ(cells[0].setting, "obbtree");
  EXPECT_EQ(cells[1].setting, "obbtree needs=every");
  EXPECT_EQ(cells[2].setting, "fcl:obb");
  EXPECT_EQ(cells[3].setting, "ode");
  EXPECT_EQ(cells[4].setting, "bullet");
  for (const RobustnessCell& cell : cells) {
    EXPECT_EQ(cell.category, "touching");
    EXPECT_EQ(cell.cases, 3u) << cell.setting;
  }
}

TEST(RobustnessMatrix, ExactBackendHasZeroRatesNotEmptyOnes) {
  const RobustnessCell exact = robustnessMatrix(handMade())[0];
  EXPECT_EQ(exact.boolean.status(), AnswersStatus::kMeasured);
  EXPECT_EQ(exact.boolean.answered, 3u);
  EXPECT_EQ(exact.boolean.wrong, 0u);
  ASSERT_TRUE(exact.boolean.wrongRate());
  EXPECT_EQ(*exact.boolean.wrongRate(), 0.0);
  EXPECT_EQ(exact.all_pairs.true_pairs, 6u);
  EXPECT_EQ(exact.all_pairs.reported_pairs, 6u);
  EXPECT_EQ(exact.all_pairs.missed_pairs, 0u);
  EXPECT_EQ(exact.all_pairs.extra_pairs, 0u);
  EXPECT_EQ(*exact.all_pairs.missedShare(), 0.0);
  EXPECT_EQ(*exact.all_pairs.extraShare(), 0.0);
}

TEST(RobustnessMatrix, CountsWrongAnswersMissedAndExtraPairs) {
  const RobustnessCell wrong = robustnessMatrix(handMade())[2];
  EXPECT_EQ(wrong.boolean.answered, 3u);
  EXPECT_EQ(wrong.boolean.wrong, 2u);
  EXPECT_EQ(wrong.boolean.false_negatives, 1u);
  EXPECT_EQ(wrong.boolean.false_positives, 1u);
  EXPECT_DOUBLE_EQ(*wrong.boolean.wrongRate(), 2.0 / 3.0);
  EXPECT_EQ(wrong.all_pairs.answered, 3u);
  EXPECT_EQ(wrong.all_pairs.wrong, 2u);  // case 0 misses a pair, case 1 adds one
  EXPECT_EQ(wrong.all_pairs.true_pairs, 6u);
  EXPECT_EQ(wrong.all_pairs.reported_pairs, 6u);
  EXPECT_EQ(wrong.all_pairs.missed_pairs, 1u);
  EXPECT_EQ(wrong.all_pairs.extra_pairs, 1u);
  EXPECT_DOUBLE_EQ(*wrong.all_pairs.missedShare(), 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(*wrong.all_pairs.extraShare(), 1.0 / 6.0);
}

TEST(RobustnessMatrix, UnsupportedIsNeverZeroErrors) {
  const RobustnessCell ode = robustnessMatrix(handMade())[3];
  EXPECT_EQ(ode.boolean.status(), AnswersStatus::kMeasured);
  EXPECT_EQ(ode.all_pairs.status(), AnswersStatus::kUnsupported);
  EXPECT_EQ(ode.all_pairs.unsupported, 3u);
  EXPECT_EQ(ode.all_pairs.answered, 0u);
  EXPECT_FALSE(ode.all_pairs.wrongRate());
  EXPECT_FALSE(ode.all_pairs.missedShare());
  const nlohmann::ordered_json json = robustnessJson({ode});
  EXPECT_TRUE(json[0]["all_pairs"]["wrong_rate"].is_null());
  EXPECT_EQ(json[0]["all_pairs"]["status"], "unsupported");
}

TEST(RobustnessMatrix, CrashedWorkerCountsItsCasesAsUnanswered) {
  const RobustnessCell crashed = robustnessMatrix(handMade())[4];
  EXPECT_EQ(crashed.boolean.status(), AnswersStatus::kFailed);
  EXPECT_EQ(crashed.all_pairs.status(), AnswersStatus::kFailed);
  EXPECT_EQ(crashed.boolean.failed, 3u);
  EXPECT_FALSE(crashed.boolean.wrongRate());
  ASSERT_EQ(crashed.worker_failures.size(), 1u);
  EXPECT_EQ(crashed.worker_failures[0], "stress_touching: crashed (SIGSEGV)");
}

TEST(RobustnessMatrix, OrdinaryScenesAloneGiveNoMatrix) {
  EXPECT_TRUE(robustnessMatrix({testdata::okResult(testdata::combination("obbtree"))}).empty());
  EXPECT_EQ(robustnessText({}), "");
}

TEST(RobustnessMatrix, TextShowsRatesAndStatuses) {
  const std::string text = robustnessText(robustnessMatrix(handMade()));
  SCOPED_TRACE(text);
  EXPECT_NE(text.find("Wrong boolean answers"), std::string::npos);
  EXPECT_NE(text.find("Wrong all-pairs answers"), std::string::npos);
  EXPECT_NE(text.find("0.0% (0/3)"), std::string::npos);
  EXPECT_NE(text.find("66.7% (2/3)"), std::string::npos);
  EXPECT_NE(text.find("unsupported"), std::string::npos);
  EXPECT_NE(text.find("failed (3)"), std::string::npos);
  EXPECT_NE(text.find("0.1667"), std::string::npos);  // missed and extra shares of fcl:obb
  EXPECT_NE(text.find("bullet / stress_touching: crashed (SIGSEGV)"), std::string::npos);
  EXPECT_EQ(text.find("tori"), std::string::npos);
}

TEST(RobustnessMatrix, JsonHasEveryCount) {
  const nlohmann::ordered_json json = robustnessJson(robustnessMatrix(handMade()));
  ASSERT_EQ(json.size(), 5u);
  const auto& wrong = json[2];
  EXPECT_EQ(wrong["backend"], "fcl:obb");
  EXPECT_EQ(wrong["category"], "touching");
  EXPECT_EQ(wrong["cases"], 3);
  EXPECT_EQ(wrong["boolean"]["wrong"], 2);
  EXPECT_EQ(wrong["boolean"]["false_negatives"], 1);
  EXPECT_EQ(wrong["all_pairs"]["missed_pairs"], 1);
  EXPECT_EQ(wrong["all_pairs"]["extra_pairs"], 1);
  EXPECT_DOUBLE_EQ(wrong["all_pairs"]["missed_share"].get<double>(), 1.0 / 6.0);
  EXPECT_FALSE(wrong["boolean"].contains("missed_pairs"));
  EXPECT_EQ(json[4]["worker_failures"].size(), 1u);
}

TEST(RobustnessMatrix, InEveryStudyOutput) {
  const std::vector<CombinationResult> results = handMade();
  const std::string table = studyTable(results);
  EXPECT_NE(table.find("Robustness matrix"), std::string::npos) << table;
  EXPECT_NE(table.find("boolean, 3 cases"), std::string::npos) << table;
  EXPECT_EQ(table.find("touching/s0/"), std::string::npos) << table;
  const nlohmann::json summary = nlohmann::json::parse(benchmarkJson(results));
  ASSERT_TRUE(summary.contains("robustness_matrix"));
  EXPECT_EQ(summary["robustness_matrix"].size(), 5u);
  EXPECT_TRUE(summary.contains("benchmarks"));
  const nlohmann::json report = reportData(results, {}, "test");
  ASSERT_TRUE(report.contains("robustness"));
  EXPECT_EQ(report["robustness"].size(), 5u);

  const std::string folder = test::makeTempDirectory("robustness_outputs");
  ASSERT_TRUE(writeStudyOutputs(folder, results).ok());
  std::ifstream in(std::filesystem::path(folder) / "robustness.txt");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("Every count"), std::string::npos) << text.str();
}

// The tables show a stress combination as one row per query kind over all its cases.
TEST(TableMeasurements, OneMeasurementPerKindForStressScenes) {
  const std::vector<CombinationResult> results = handMade();
  const std::vector<QueryMeasurement> wrong = tableMeasurements(results[2]);
  ASSERT_EQ(wrong.size(), 2u);
  EXPECT_EQ(wrong[0].query, "all_pairs, 3 cases");
  EXPECT_EQ(wrong[1].query, "boolean, 3 cases");
  EXPECT_EQ(wrong[1].kind, QueryKind::kBoolean);
  EXPECT_TRUE(wrong[1].ok());
  ASSERT_EQ(wrong[1].frames.size(), 3u);
  EXPECT_EQ(wrong[1].frames[2].frame, 2u);
  EXPECT_EQ(wrong[1].times_us.size(), 3u);
  EXPECT_EQ(wrong[1].disagreements, 2u);
  EXPECT_EQ(wrong[1].false_negatives, 1u);
  EXPECT_EQ(wrong[1].false_positives, 1u);
  EXPECT_DOUBLE_EQ(wrong[0].recall, 5.0 / 6.0);

  const std::vector<QueryMeasurement> ode = tableMeasurements(results[3]);
  ASSERT_EQ(ode.size(), 2u);
  EXPECT_TRUE(ode[0].status.skipped()) << ode[0].status;
  EXPECT_TRUE(ode[1].ok());

  CombinationResult one_failed = results[0];
  one_failed.measurements[1].status = MeasurementStatus::failed("frame 0: engine failure");
  const std::vector<QueryMeasurement> failed = tableMeasurements(one_failed);
  EXPECT_EQ(failed[1].status.text().rfind("failed: 1 of 3 cases", 0), 0u) << failed[1].status;

  // Ordinary scenes are shown query by query, as measured.
  const CombinationResult ordinary = testdata::okResult(testdata::combination("obbtree"));
  EXPECT_EQ(tableMeasurements(ordinary).size(), ordinary.measurements.size());
  EXPECT_EQ(tableMeasurements(ordinary)[0].query, ordinary.measurements[0].query);
}

TEST(RobustnessMatrix, StudiesWithoutStressScenesSaySo) {
  const std::vector<CombinationResult> ordinary = {
      testdata::okResult(testdata::combination("obbtree"))};
  EXPECT_FALSE(nlohmann::json::parse(benchmarkJson(ordinary)).contains("robustness_matrix"));
  EXPECT_EQ(studyTable(ordinary).find("Robustness matrix"), std::string::npos);
  EXPECT_EQ(robustnessReport(ordinary), "");  // and writeStudyOutputs writes no robustness.txt
}

TEST(RobustnessMatrix, CategoryTravelsWithTheCombination) {
  const Combination c = stressCombination("obbtree");
  EXPECT_EQ(c.category, "touching");
  const Result<Combination> back = combinationFromJson(combinationToJson(c));
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back.value().category, "touching");
  EXPECT_EQ(back.value().id, c.id);
  // Ordinary scenes write no category, and results from before the stress suite read as such.
  const nlohmann::json ordinary = combinationToJson(testdata::combination("obbtree"));
  EXPECT_FALSE(ordinary.contains("category"));
  ASSERT_TRUE(combinationFromJson(ordinary).ok());
  EXPECT_EQ(combinationFromJson(ordinary).value().category, "");
}

}  // namespace
}  // namespace collido::study

namespace collido::study {
namespace {

// The distance category's answers are held to the exact distance at contact scale: 0 for
// meshes apart, a positive distance for touching ones and a relative error above 1e-6 are
// wrong, though the runner's general check (rounding of the coordinates) lets them pass.
TEST(RobustnessMatrix, DistanceAnswersAreHeldToTheExactDistance) {
  Sweep sweep;
  const Combination c =
      planStudy({{"/scenes/stress/distance.json", "stress_distance", false, "distance"}},
                {"fcl:rss"}, sweep)
          .front();
  CombinationResult r;
  r.combination = c;
  // (exact, reported): right, right (touching), 0 for apart, positive for touching, 1e-5 off.
  const std::pair<double, double> answers[] = {
      {1e-9, 1e-9 * (1.0 + 1e-9)}, {0.0, 0.0}, {2e-16, 0.0}, {0.0, 1e-17}, {1e-3, 1.00001e-3}};
  std::size_t index = 0;
  for (const auto& [exact, reported] : answers) {
    QueryMeasurement m;
    m.backend = c.backend;
    m.scene = "stress_distance";
    m.query = "distance/s0/" + std::to_string(index++) + "/cubes distance";
    m.kind = QueryKind::kDistance;
    m.times_us = {1.0};
    FrameRecord f;
    f.oracle_distance = exact;
    f.reported_distance = reported;
    f.distance_below = 1e-10;  // the runner's rounding allowance: every answer passes it
    f.distance_above = 1e-10;
    m.frames = {f};
    summariseMeasurement(m);
    r.measurements.push_back(m);
  }
  const std::vector<RobustnessCell> cells = robustnessMatrix({r});
  ASSERT_EQ(cells.size(), 1u);
  const RobustnessAnswers& d = cells[0].distance;
  EXPECT_EQ(d.answered, 5u);
  EXPECT_EQ(d.wrong, 3u);
  EXPECT_EQ(d.false_positives, 1u);  // 0 for meshes apart
  EXPECT_EQ(d.false_negatives, 1u);  // positive for touching ones
  EXPECT_EQ(cells[0].all_pairs.status(), AnswersStatus::kNone);
  const std::string text = robustnessText(cells);
  EXPECT_NE(text.find("Wrong distance answers"), std::string::npos) << text;
  EXPECT_NE(text.find("60.0% (3/5)"), std::string::npos) << text;
  EXPECT_EQ(robustnessJson(cells)[0]["distance"]["wrong"], 3);
}

}  // namespace
}  // namespace collido::study
