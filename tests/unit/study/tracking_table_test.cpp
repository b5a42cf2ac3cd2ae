// "Poses from tracked markers": the tracking's collision error once per scene and query, and
// each backend's own disagreements beside it.
#include <collido/study/tracking_table.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "study_test_data.h"
#include "table_cells.h"

namespace collido::study {
namespace {

// The all-pairs measurement (oracle contact in frames 0 and 1, frame 1 answered wrongly) with
// true-pose answers: contact in frames 1 and 2 (frame 0 a false contact, frame 2 missed).
CombinationResult tracked(const std::string& backend) {
  CombinationResult r = testdata::okResult(testdata::combination(backend));
  QueryMeasurement& m = r.measurements[0];
  const bool truth[3] = {false, true, true};
  for (std::size_t i = 0; i < m.frames.size(); ++i)
    m.frames[i].truth_intersecting = truth[i];
  summariseMeasurement(m);
  return r;
}

// The same with the possible-contact answer: frames 0 and 1 within the margin (so frame 2's
// true contact falls outside it).
CombinationResult trackedWithMargin(const std::string& backend) {
  CombinationResult r = tracked(backend);
  QueryMeasurement& m = r.measurements[0];
  const bool possible[3] = {true, true, false};
  for (std::size_t i = 0; i < m.frames.size(); ++i) {
    m.frames[i].possible_contact = possible[i];
    m.frames[i].tracking_margin = 0.01;
  }
  summariseMeasurement(m);
  return r;
}

TEST(TrackingTable, PossibleContactsAndTrueContactsOutsideThem) {
  const std::string table = trackingTable({trackedWithMargin("obbtree")});
  SCOPED_TRACE(table);
  const std::vector<std::string> cells = testdata::cellsOfLine(table, 2);
  ASSERT_EQ(cells.size(), 10u);
  EXPECT_EQ(cells[7], "2");
  EXPECT_EQ(cells[8], "1");
}

TEST(TrackingTable, ErrorOncePerQueryAndEachBackendsDisagreements) {
  const std::string table = trackingTable({tracked("obbtree"), tracked("fcl:obb")});
  SCOPED_TRACE(table);
  const std::vector<std::string> expected = {"tori", "all_pairs", "3", "2", "2",
                                             "1",    "1",         "-", "-", "obbtree 1, fcl:obb 1"};
  EXPECT_EQ(testdata::cellsOfLine(table, 2), expected);
  // One row (the boolean measurement has no true-pose answers), then the explanation.
  EXPECT_EQ(testdata::cellsOfLine(table, 3).at(0).rfind("The recovered poses", 0), 0u);
}

TEST(TrackingTable, EmptyWithoutTrackedScenes) {
  EXPECT_EQ(trackingTable({testdata::okResult(testdata::combination("obbtree"))}), "");
}

}  // namespace
}  // namespace collido::study
