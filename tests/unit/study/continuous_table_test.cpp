// "Between the frames": per query over a step, the certified pick against the peer's own answer
// and the discrete settings' misses and time errors.
#include <collido/study/continuous_table.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "study_test_data.h"
#include "table_cells.h"

namespace collido::study {
namespace {

// Three steps, the first touching at [0.4, 0.401]: `reported` brackets it (or misses it, with
// t_lo past the oracle's contact), the other two pass clear. Each step's calls take `us`.
CombinationResult stepResult(const std::string& backend, bool touches, double t_lo, double t_hi,
                             double us) {
  CombinationResult r;
  r.combination = testdata::combination(backend);
  QueryMeasurement m = testdata::named(backend, "tori", "first contact", QueryKind::kFirstContact);
  for (std::size_t i = 0; i < 3; ++i) {
    FrameRecord f;
    f.frame = i;
    f.bracket_width = 1e-3;
    f.oracle_touches = i == 0;
    f.oracle_intersecting = i == 0;
    f.oracle_t_lo = i == 0 ? 0.4 : 1.0;
    if (i == 0) {
      f.oracle_t_hi = 0.401;
      f.reported_intersecting = touches;
      if (touches) {
        f.reported_t_lo = t_lo;
        f.reported_t_hi = t_hi;
        f.first_contact_error = std::max(t_hi - 0.4, 0.401 - t_lo);
      } else {
        f.invalid_first_contact = true;  // its free part runs past the contact
      }
    }
    f.median_us = us;
    m.frames.push_back(f);
  }
  m.times_us = {us, us, us, us * 1.01, us, us * 0.99};
  summariseMeasurement(m);
  r.measurements = {m};
  return r;
}

TEST(ContinuousTable, PicksTheCertifiedAnswerAndCountsMissesAndCoarseTimes) {
  const std::vector<CombinationResult> results = {
      stepResult("obbtree", true, 0.4, 0.401, 10.0),
      stepResult("obbtree[substeps=4]", true, 0.25, 0.5, 2.0),
      stepResult("obbtree[substeps=1]", false, 1.0, 1.0, 1.0),
      stepResult("fcl:obbrss", false, 1.0, 1.0, 500.0)};
  const std::string table = continuousTable(results);
  SCOPED_TRACE(table);
  // The pick is the tree's own answer, 50x faster than FCL's, which missed the contact; sub-steps
  // at 4 caught it, 0.151 of a step off; at 1, missed it.
  const std::vector<std::string> pick = testdata::cellsOfLine(table, 2);
  ASSERT_GE(pick.size(), 3u);
  EXPECT_EQ(pick[0], "tori");
  EXPECT_NE(table.find("obbtree 10.0 [10.0, 10.0]"), std::string::npos);
  EXPECT_NE(table.find("50.00x"), std::string::npos);
  EXPECT_NE(table.find("faster (wrong on 1 of 3 steps)"), std::string::npos);
  EXPECT_NE(table.find("obbtree[substeps=4] 2.0 [2.0, 2.0], time err 0.151"), std::string::npos);
  // Every setting's row: steps, touching, missed, false, time err, coarse, wrong.
  const auto row = [&](int line) {
    const std::vector<std::string> cells = testdata::cellsOfLine(table, line);
    return std::vector<std::string>(cells.end() - 7, cells.end());
  };
  EXPECT_EQ(row(6), (std::vector<std::string>{"3", "1", "0", "0", "0.001", "0", "0"}));
  EXPECT_EQ(row(7), (std::vector<std::string>{"3", "1", "0", "0", "0.151", "1", "0"}));
  EXPECT_EQ(row(8), (std::vector<std::string>{"3", "1", "1", "0", "-", "0", "0"}));
  EXPECT_EQ(row(9), (std::vector<std::string>{"3", "1", "1", "0", "-", "0", "0"}));
}

TEST(ContinuousTable, EmptyWithoutQueriesOverAStep) {
  EXPECT_EQ(continuousTable({testdata::okResult(testdata::combination("obbtree"))}), "");
}

}  // namespace
}  // namespace collido::study
