// The expected study time: estimated from an earlier run's wall times, written by every study as
// times.json and read back, and used by the progress line before anything has finished.
#include <collido/study/expected_time.h>
#include <collido/study/progress.h>

#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_paths.h"
#include "unit/study/study_test_data.h"

namespace collido::study {
namespace {

CombinationResult finished(const std::string& backend, double wall_s,
                           WorkerStatus status = WorkerStatus::kOk) {
  CombinationResult r;
  r.combination = testdata::combination(backend);
  r.outcome.status = status;
  r.outcome.wall_s = wall_s;
  return r;
}

TEST(ExpectedTime, TimesRoundTripAndSkipRunsThatDidNotFinish) {
  const std::string dir = test::makeTempDirectory("expected_time");
  test::writeFile(dir + "/times.json",
                  timesJson({finished("obbtree", 2.5), finished("ode", 4.0),
                             finished("bullet", 99.0, WorkerStatus::kCrashed)}));
  const Result<CombinationTimes> times = loadCombinationTimes(dir);  // the folder finds its file
  ASSERT_TRUE(times.ok()) << times.status().message();
  EXPECT_EQ(times.value().seconds.size(), 2u);
  EXPECT_EQ(times.value().seconds.at("tori · obbtree"), 2.5);
  EXPECT_EQ(times.value().seconds.at("tori · ode"), 4.0);
}

TEST(ExpectedTime, EachCombinationFromItsOwnTimeElseItsSceneElseAll) {
  CombinationTimes times;
  times.seconds = {{"tori · obbtree", 2.0}, {"tori · ode", 4.0}, {"gears · ode", 9.0}};
  const Combination known = testdata::combination("obbtree");
  const Combination same_scene = testdata::combination("bullet");
  Combination elsewhere = testdata::combination("bullet");
  elsewhere.scene_name = "pile";
  const TimeEstimate estimate = estimateTimes({&known, &same_scene, &elsewhere}, times);
  EXPECT_EQ(estimate.seconds, (std::vector<double>{2.0, 3.0, 5.0}));
  EXPECT_EQ(estimate.measured, 1u);
  EXPECT_EQ(estimate.from_scene, 1u);
  EXPECT_EQ(estimate.unknown, 1u);
  EXPECT_EQ(startLine(5, 3, estimate, "", "out"),
            "study: 5 combinations, 3 to run, expected about 10s (1 timed before, 1 from their "
            "scene's other settings, 1 guessed), results in out");
  // The extra rounds' budget counts too, and is said.
  TimeEstimate with_extra = estimate;
  with_extra.extra_rounds_s = 20.0;
  EXPECT_EQ(startLine(5, 3, with_extra, "", "out"),
            "study: 5 combinations, 3 to run, expected about 30s (1 timed before, 1 from their "
            "scene's other settings, 1 guessed; up to 20s of extra rounds), results in out");
}

TEST(ExpectedTime, WithoutEarlierTimesTheLineSaysSo) {
  const Combination c = testdata::combination("obbtree");
  const TimeEstimate estimate = estimateTimes({&c}, CombinationTimes{});
  EXPECT_NE(startLine(1, 1, estimate, "0/2", "out")
                .find("in shard 0/2, 1 to run, expected time "
                      "unknown"),
            std::string::npos);
}

TEST(ExpectedTime, ABrokenTimesFileIsNamed) {
  const std::string dir = test::makeTempDirectory("expected_time");
  test::writeFile(dir + "/t.json", R"({"collidoscope_times": 1, "combinations": {"a": "x"}})");
  const Result<CombinationTimes> times = loadCombinationTimes(dir + "/t.json");
  ASSERT_FALSE(times.ok());
  EXPECT_NE(times.status().message().find(dir + "/t.json: /combinations/a: expected a number"),
            std::string::npos)
      << times.status().message();
}

TEST(ExpectedTime, ProgressLeftFollowsTheExpectationBeforeAnythingFinished) {
  std::ostringstream out;
  StudyProgress progress(out, 2, false);
  progress.setExpected({60.0, 120.0});
  EXPECT_EQ(progress.estimateLeft(), "3m00s");
}

}  // namespace
}  // namespace collido::study
