// The study's time statistic: each frame's calls, the bootstrap interval, ratios paired by frame,
// and the equivalence band.
#include <collido/runner/time_statistic.h>

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

namespace collido {
namespace {

/// A measurement whose frame f has the calls `calls[f]`, stored as the runner stores them.
QueryMeasurement timed(const std::vector<std::vector<double>>& calls) {
  QueryMeasurement m;
  for (std::size_t f = 0; f < calls.size(); ++f) {
    FrameRecord record;
    record.frame = f;
    std::vector<double> sorted = calls[f];
    std::sort(sorted.begin(), sorted.end());
    const std::size_t k = sorted.size();
    record.median_us = k % 2 == 1 ? sorted[k / 2] : (sorted[k / 2 - 1] + sorted[k / 2]) / 2.0;
    m.frames.push_back(record);
    m.times_us.insert(m.times_us.end(), calls[f].begin(), calls[f].end());
  }
  return m;
}

TEST(TimeStatistic, EachFramesCallsAndTheMeanOfTheirMedians) {
  const QueryMeasurement m = timed({{3, 1, 2}, {10, 30, 20}});
  EXPECT_EQ(callsPerFrame(m), (std::vector<std::vector<double>>{{3, 1, 2}, {10, 30, 20}}));
  EXPECT_DOUBLE_EQ(meanFrameTimeUs(m), 11.0);
  const TimeBootstrap time(m);
  EXPECT_DOUBLE_EQ(time.estimate(), 11.0);
  // Frames and calls resampled: a replicate lies between the smallest and largest possible mean.
  const Interval ci = time.ci95();
  EXPECT_LT(ci.lo, 11.0);
  EXPECT_GT(ci.hi, 11.0);
  EXPECT_GE(ci.lo, 1.0);
  EXPECT_LE(ci.hi, 30.0);
  // The same measurement always gives the same interval.
  EXPECT_EQ(TimeBootstrap(m).ci95().lo, ci.lo);
  EXPECT_EQ(TimeBootstrap(m).ci95().hi, ci.hi);

  // Calls that do not fit the frames' medians (another layout) leave each frame its median.
  QueryMeasurement odd = m;
  std::swap(odd.times_us[1], odd.times_us[4]);
  EXPECT_EQ(callsPerFrame(odd), (std::vector<std::vector<double>>{{2}, {20}}));
}

TEST(TimeStatistic, OneFrameStillHasAnIntervalFromItsCalls) {
  const TimeBootstrap time(timed({{100, 104, 96, 101, 99}}));
  EXPECT_DOUBLE_EQ(time.estimate(), 100.0);
  EXPECT_LT(time.ci95().lo, 100.0);
  EXPECT_GT(time.ci95().hi, 100.0);
  EXPECT_GE(time.ci95().lo, 96.0);
}

TEST(TimeStatistic, RatiosPairByFrame) {
  // Frames of very different cost, each exactly twice as dear in `slow`: each time alone has a
  // wide interval, their ratio none.
  const TimeBootstrap fast(timed({{1}, {10}, {100}, {1000}}));
  const TimeBootstrap slow(timed({{2}, {20}, {200}, {2000}}));
  EXPECT_GT(fast.ci95().hi / fast.ci95().lo, 5.0);
  const std::optional<Ratio> ratio = timeRatio(slow, fast);
  ASSERT_TRUE(ratio);
  EXPECT_DOUBLE_EQ(ratio->value, 2.0);
  EXPECT_DOUBLE_EQ(ratio->ci95.lo, 2.0);
  EXPECT_DOUBLE_EQ(ratio->ci95.hi, 2.0);
  EXPECT_EQ(differenceOf(ratio->ci95), Difference::kClearlyMore);
  EXPECT_EQ(differenceOf(timeRatio(fast, slow)->ci95), Difference::kClearlyLess);
  // No ratio over a time of 0.
  EXPECT_FALSE(timeRatio(slow, TimeBootstrap(timed({{0}, {0}, {0}, {0}}))));
}

TEST(TimeStatistic, RoundsThatDisagreeWidenTheIntervalAndAreUnstable) {
  // Two frames, each with three calls from a steady round and three from a round 1.5x slower.
  QueryMeasurement m = timed({{10, 10.1, 9.9, 15, 15.1, 14.9}, {10, 10.1, 9.9, 15, 15.1, 14.9}});
  m.rounds = 2;
  EXPECT_NEAR(*roundSpread(m), 1.5, 1e-9);
  EXPECT_TRUE(unstable(m));
  // Drawing whole rounds reaches down to the steady round alone and up to the slow one alone.
  const TimeBootstrap time(m);
  EXPECT_DOUBLE_EQ(time.estimate(), 12.5);
  EXPECT_NEAR(time.ci95().lo, 10.0, 0.2);
  EXPECT_NEAR(time.ci95().hi, 15.0, 0.2);
  // Rounds that agree are stable; one round has no spread.
  QueryMeasurement steady = timed({{10, 10.1, 9.9, 10.2, 10, 9.8}});
  steady.rounds = 2;
  EXPECT_FALSE(unstable(steady));
  steady.rounds = 1;
  EXPECT_FALSE(roundSpread(steady));
}

TEST(TimeStatistic, TheBandDecidesWhatIsTheSame) {
  EXPECT_EQ(differenceOf({1.05, 1.20}), Difference::kSame);
  EXPECT_EQ(differenceOf({1.11, 1.20}), Difference::kClearlyMore);
  EXPECT_EQ(differenceOf({0.80, 0.90}), Difference::kClearlyLess);
  EXPECT_EQ(differenceOf({0.80, 0.95}), Difference::kSame);
  // Noisy calls 3% apart are the same; 25% apart, clearly more.
  const std::vector<std::vector<double>> base = {{100, 98, 102}, {50, 49, 51}, {80, 78, 82}};
  std::vector<std::vector<double>> near = base;
  std::vector<std::vector<double>> far = base;
  for (std::size_t f = 0; f < base.size(); ++f) {
    for (std::size_t c = 0; c < base[f].size(); ++c) {
      near[f][c] *= 1.03;
      far[f][c] *= 1.25;
    }
  }
  const TimeBootstrap reference(timed(base));
  EXPECT_EQ(differenceOf(timeRatio(TimeBootstrap(timed(near)), reference)->ci95),
            Difference::kSame);
  EXPECT_EQ(differenceOf(timeRatio(TimeBootstrap(timed(far)), reference)->ci95),
            Difference::kClearlyMore);
  EXPECT_EQ(withInterval(12.34, {11.0, 13.96}), "12.3 [11.0, 14.0]");
}

}  // namespace
}  // namespace collido
