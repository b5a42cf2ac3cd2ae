// `collido compare`'s verdicts on fixed samples, whose answers are known: a change is called only
// when the whole 95% interval of now/before lies beyond the equivalence band. The command itself
// runs end to end in study.cli.*, on what timing cannot change.
#include <collido/study/time_changes.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "study_test_data.h"

namespace collido::study {
namespace {

/// Calls per frame of a measurement whose frames cost 10, 40, 160 and 640 us, with three calls
/// each a little apart (the same spread in every study, so that a scaled study's ratio is exact).
std::vector<std::vector<double>> steadyCalls(double scale) {
  std::vector<std::vector<double>> calls;
  for (double cost : {10.0, 40.0, 160.0, 640.0})
    calls.push_back({cost * scale * 0.99, cost * scale, cost * scale * 1.02});
  return calls;
}

/// A finished combination of `backend` on the scene "tori" with one all-pairs query timed as
/// `calls` (each frame's calls).
CombinationResult timedResult(const std::string& backend,
                              const std::vector<std::vector<double>>& calls) {
  CombinationResult r;
  r.combination = testdata::combination(backend);
  QueryMeasurement m = testdata::named(backend, "tori", "all_pairs", QueryKind::kAllPairs);
  for (std::size_t f = 0; f < calls.size(); ++f) {
    FrameRecord record;
    record.frame = f;
    record.median_us = calls[f][1];  // the middle one of three
    m.frames.push_back(record);
    m.times_us.insert(m.times_us.end(), calls[f].begin(), calls[f].end());
  }
  summariseMeasurement(m);
  r.measurements.push_back(m);
  return r;
}

Change changeOf(const std::vector<std::vector<double>>& before,
                const std::vector<std::vector<double>>& now) {
  const std::vector<TimeChange> changes =
      timeChanges({timedResult("obbtree", before)}, {timedResult("obbtree", now)});
  EXPECT_EQ(changes.size(), 1u);
  return changes.empty() ? Change::kSame : changes[0].change;
}

TEST(TimeChanges, IdenticalStudiesAreTheSameWithRatioOne) {
  const std::vector<TimeChange> changes = timeChanges({timedResult("obbtree", steadyCalls(1.0))},
                                                      {timedResult("obbtree", steadyCalls(1.0))});
  ASSERT_EQ(changes.size(), 1u);
  const TimeChange& c = changes[0];
  EXPECT_EQ(c.backend, "obbtree");
  EXPECT_EQ(c.scene, "tori");
  EXPECT_EQ(c.query, "all_pairs");
  EXPECT_EQ(c.change, Change::kSame);
  ASSERT_TRUE(c.ratio);
  EXPECT_DOUBLE_EQ(c.ratio->value, 1.0);
  EXPECT_DOUBLE_EQ(c.ratio->ci95.lo, 1.0);
  EXPECT_DOUBLE_EQ(c.ratio->ci95.hi, 1.0);
  EXPECT_DOUBLE_EQ(c.before_us, c.now_us);
}

TEST(TimeChanges, AStudyScaledOnEveryFrameIsCalledByTheBand) {
  // Paired by frame, a uniform scale leaves only the calls' own spread (1% and 2% here): the
  // interval hugs the scale, and the band decides.
  EXPECT_EQ(changeOf(steadyCalls(1.0), steadyCalls(1.25)), Change::kSlower);
  EXPECT_EQ(changeOf(steadyCalls(1.0), steadyCalls(0.5)), Change::kFaster);
  EXPECT_EQ(changeOf(steadyCalls(1.0), steadyCalls(1.05)), Change::kSame);
  EXPECT_EQ(changeOf(steadyCalls(1.0), steadyCalls(1.0 / 1.05)), Change::kSame);
  const std::vector<TimeChange> slower = timeChanges({timedResult("obbtree", steadyCalls(1.0))},
                                                     {timedResult("obbtree", steadyCalls(1.25))});
  ASSERT_TRUE(slower[0].ratio);
  EXPECT_NEAR(slower[0].ratio->value, 1.25, 1e-12);
  EXPECT_GT(slower[0].ratio->ci95.lo, 1.2);
  EXPECT_LT(slower[0].ratio->ci95.hi, 1.3);
}

TEST(TimeChanges, ASlowdownOnSomeFramesOnlyIsNoVerdict) {
  // The two costliest frames 25% dearer and the two cheapest 10% cheaper: the frames' ratios
  // straddle the band, so the resampled ratio cannot lie wholly beyond it.
  std::vector<std::vector<double>> now = steadyCalls(1.0);
  for (std::size_t f = 0; f < now.size(); ++f) {
    for (double& call : now[f])
      call *= f < 2 ? 0.9 : 1.25;
  }
  const std::vector<TimeChange> changes =
      timeChanges({timedResult("obbtree", steadyCalls(1.0))}, {timedResult("obbtree", now)});
  ASSERT_EQ(changes.size(), 1u);
  ASSERT_TRUE(changes[0].ratio);
  EXPECT_LT(changes[0].ratio->ci95.lo, 1.1);
  EXPECT_GT(changes[0].ratio->ci95.hi, 1.1);
  EXPECT_EQ(changes[0].change, Change::kSame);
}

TEST(TimeChanges, OnlyRowsBothStudiesAnsweredAreCompared) {
  CombinationResult failed = timedResult("fcl:obb", steadyCalls(1.0));
  failed.outcome.status = WorkerStatus::kCrashed;
  CombinationResult stress = timedResult("bullet", steadyCalls(1.0));
  stress.combination.category = "near_parallel";
  const std::vector<TimeChange> changes = timeChanges(
      {timedResult("obbtree", steadyCalls(1.0)), timedResult("fcl:obb", steadyCalls(1.0)),
       timedResult("bullet", steadyCalls(1.0))},
      {timedResult("obbtree", steadyCalls(2.0)), failed, stress,
       timedResult("embree", steadyCalls(1.0))});
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].backend, "obbtree");
  EXPECT_EQ(changes[0].change, Change::kSlower);
}

TEST(TimeChanges, SummariesCombineTheirIntervalsUnpaired) {
  const auto summary = [](double time, double lo, double hi) {
    return nlohmann::json{
        {"benchmarks",
         {{{"name", "obbtree/tori/all_pairs"}, {"real_time", time}, {"ci95_us", {lo, hi}}}}}};
  };
  const auto change = [&](double time, double lo, double hi) {
    Result<std::vector<TimeChange>> changes =
        summaryTimeChanges(summary(100, 98, 102), "before.json", summary(time, lo, hi), "now.json");
    EXPECT_TRUE(changes.ok());
    EXPECT_EQ(changes.value().size(), 1u);
    return changes.value().at(0);
  };
  // Narrow intervals, 25% apart: slower; 3% apart: the same; wide intervals 25% apart: the same.
  EXPECT_EQ(change(125, 123, 127).change, Change::kSlower);
  EXPECT_EQ(change(103, 101, 105).change, Change::kSame);
  EXPECT_EQ(change(125, 80, 190).change, Change::kSame);
  EXPECT_EQ(change(50, 49, 51).change, Change::kFaster);
  const TimeChange same = change(100, 98, 102);
  ASSERT_TRUE(same.ratio);
  EXPECT_DOUBLE_EQ(same.ratio->value, 1.0);
  EXPECT_LT(same.ratio->ci95.lo, 1.0);
  EXPECT_GT(same.ratio->ci95.hi, 1.0);
}

TEST(TimeChanges, ASummaryThatIsNotOneIsRefusedByName) {
  const nlohmann::json good = {{"benchmarks", nlohmann::json::array()}};
  Result<std::vector<TimeChange>> none = summaryTimeChanges({{"rows", 1}}, "old.json", good, "new");
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.status().message().find("old.json: not a summary.json"), std::string::npos)
      << none.status().message();
  const nlohmann::json bad_interval = {
      {"benchmarks", {{{"name", "x"}, {"real_time", 1.0}, {"ci95_us", {1.0}}}}}};
  Result<std::vector<TimeChange>> bad =
      summaryTimeChanges(good, "old.json", bad_interval, "new.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("new.json: /benchmarks/0/ci95_us"), std::string::npos)
      << bad.status().message();
}

TEST(TimeChanges, TextAndJsonCountEachVerdict) {
  const std::vector<TimeChange> changes = timeChanges(
      {timedResult("obbtree", steadyCalls(1.0)), timedResult("fcl:obb", steadyCalls(1.0)),
       timedResult("bullet", steadyCalls(1.0))},
      {timedResult("obbtree", steadyCalls(0.5)), timedResult("fcl:obb", steadyCalls(1.0)),
       timedResult("bullet", steadyCalls(3.0))});
  ASSERT_EQ(changes.size(), 3u);
  const std::string text = timeChangesText(changes);
  EXPECT_NE(text.find("3 rows: 1 faster, 1 slower, 1 the same."), std::string::npos) << text;
  const nlohmann::json json = timeChangesJson(changes);
  EXPECT_EQ(json.at("counts"), (nlohmann::json{{"faster", 1}, {"same", 1}, {"slower", 1}}));
  EXPECT_DOUBLE_EQ(json.at("equivalence_band").get<double>(), kEquivalenceBand);
  ASSERT_EQ(json.at("rows").size(), 3u);
  EXPECT_EQ(json.at("rows")[0].at("change"), "faster");
  EXPECT_EQ(json.at("rows")[2].at("change"), "slower");
  EXPECT_DOUBLE_EQ(json.at("rows")[2].at("ratio").get<double>(), 3.0);
}

}  // namespace
}  // namespace collido::study
