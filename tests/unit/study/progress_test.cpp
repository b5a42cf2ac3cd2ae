// Progress on a terminal and in logs: durations, bars, and the per-combination lines.
#include <collido/study/progress.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace collido::study {
namespace {

const std::string kFull = "\u2588";
const std::string kEmpty = "\u2591";

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
    ++n;
  return n;
}

TEST(FormatDuration, SecondsMinutesHours) {
  EXPECT_EQ(formatDuration(0.0), "0s");
  EXPECT_EQ(formatDuration(0.4), "0s");
  EXPECT_EQ(formatDuration(42.0), "42s");
  EXPECT_EQ(formatDuration(59.4), "59s");
  EXPECT_EQ(formatDuration(59.6), "1m00s");  // rounds before choosing the unit
  EXPECT_EQ(formatDuration(65.0), "1m05s");
  EXPECT_EQ(formatDuration(187.0), "3m07s");
  EXPECT_EQ(formatDuration(3599.0), "59m59s");
  EXPECT_EQ(formatDuration(3600.0), "1h00m");
  EXPECT_EQ(formatDuration(3720.0), "1h02m");
  EXPECT_EQ(formatDuration(100.0 * 3600.0 + 59.0 * 60.0), "100h59m");
}

TEST(FormatDuration, NonsenseIsAQuestionMark) {
  EXPECT_EQ(formatDuration(-1.0), "?");
  EXPECT_EQ(formatDuration(std::numeric_limits<double>::infinity()), "?");
  EXPECT_EQ(formatDuration(std::nan("")), "?");
}

TEST(ProgressBar, FillsToTheFractionClamped) {
  EXPECT_EQ(progressBar(0.0, 4), kEmpty + kEmpty + kEmpty + kEmpty);
  EXPECT_EQ(progressBar(0.5, 4), kFull + kFull + kEmpty + kEmpty);
  EXPECT_EQ(progressBar(1.0, 4), kFull + kFull + kFull + kFull);
  EXPECT_EQ(progressBar(2.0, 4), progressBar(1.0, 4));
  EXPECT_EQ(progressBar(-1.0, 4), progressBar(0.0, 4));
  EXPECT_EQ(progressBar(std::nan(""), 4), progressBar(0.0, 4));
  EXPECT_EQ(progressBar(0.5, 0), "");
  const std::string bar = progressBar(0.3, 10);
  EXPECT_EQ(count(bar, kFull), 3u);
  EXPECT_EQ(count(bar, kEmpty), 7u);
}

TEST(StudyProgress, NotATerminalPrintsOneLinePerCombination) {
  std::ostringstream out;
  StudyProgress progress(out, 3, false);
  progress.start(0, "tori · obbtree");
  progress.frames(5, 10);
  progress.tick();
  EXPECT_EQ(out.str(), "");  // nothing redrawn off a terminal
  progress.finish("ok in 1s");
  progress.start(1, "tori · fcl:obb");
  progress.finish("crashed (SIGSEGV)");
  const std::string text = out.str();
  EXPECT_EQ(text.find('\r'), std::string::npos) << text;
  EXPECT_EQ(text.find("\x1b["), std::string::npos) << text;
  EXPECT_EQ(count(text, "\n"), 2u) << text;
  EXPECT_EQ(text.rfind("[1/3] tori · obbtree: ok in 1s  (left: ", 0), 0u) << text;
  EXPECT_NE(text.find("\n[2/3] tori · fcl:obb: crashed (SIGSEGV)  (left: "), std::string::npos)
      << text;
}

TEST(StudyProgress, TerminalRedrawsInPlace) {
  std::ostringstream out;
  StudyProgress progress(out, 2, true);
  progress.start(0, "tori · obbtree");
  const std::string drawn = out.str();
  EXPECT_EQ(drawn.rfind("\r\x1b[K", 0), 0u) << drawn;
  EXPECT_NE(drawn.find("0/2"), std::string::npos) << drawn;
  EXPECT_NE(drawn.find("tori · obbtree"), std::string::npos) << drawn;
  EXPECT_EQ(drawn.find('\n'), std::string::npos) << drawn;
  progress.frames(3, 4);
  progress.finish("ok in 0s");
  EXPECT_NE(out.str().find("\r\x1b[K[1/2] tori · obbtree: ok in 0s"), std::string::npos)
      << out.str();
  EXPECT_EQ(progress.estimateLeft().empty(), false);
}

TEST(StudyProgress, FinishedCombinationCountsOnce) {
  // After the first of two combinations, about as long again is left: the frames of the one that
  // just finished must not count a second time on top of it.
  // A clock of the test's own: the first combination took 70 s.
  StudyProgress::Clock::time_point now{};
  std::ostringstream out;
  StudyProgress progress(out, 2, false, [&now] { return now; });
  progress.start(0, "x");
  progress.frames(4, 4);
  now += std::chrono::seconds(70);
  progress.finish("ok");
  EXPECT_NE(out.str().find("(left: 1m10s)"), std::string::npos) << out.str();
  EXPECT_EQ(progress.estimateLeft(), "1m10s");
}

TEST(StudyProgress, EstimateIsUnknownBeforeAnythingIsDone) {
  std::ostringstream out;
  StudyProgress progress(out, 4, false);
  EXPECT_EQ(progress.estimateLeft(), "?");
  progress.start(0, "x");
  progress.frames(1, 2);
  EXPECT_NE(progress.estimateLeft(), "?");
}

}  // namespace
}  // namespace collido::study
