// "Deforming scenes": update and query costs per frame, only for measurements with updates.
#include <collido/study/deform_table.h>

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "study_test_data.h"
#include "table_cells.h"

namespace collido::study {
namespace {

TEST(DeformTable, UpdateAndQueryPerFrame) {
  CombinationResult r = testdata::okResult(testdata::combination("obbtree"));
  QueryMeasurement& m = r.measurements[0];  // all pairs: frames at 10, 20 and 40 us
  const double updates[3] = {5.0, 7.0, 30.0};
  const std::uint64_t rebuilds[3] = {0, 2, 1};
  for (std::size_t i = 0; i < m.frames.size(); ++i) {
    m.frames[i].update_us = updates[i];
    m.frames[i].update_work.counted = true;
    m.frames[i].update_work.rebuilds = rebuilds[i];
  }
  m.memory_bytes = 3 * 1024 + 512;
  summariseMeasurement(m);
  const std::string table = deformTable({r});
  SCOPED_TRACE(table);
  // Means over the frames, each with its interval over the frames drawn: update 14 (5 to 30),
  // query (10 + 20 + 40) / 3, update + query (15 + 27 + 70) / 3; three rebuilds; 3.5 KiB; one
  // frame disagrees.
  const std::vector<std::string> expected = {
      "obbtree",           "tori", "all_pairs", "3", "14.0 [5.0, 30.0]", "23.3 [10.0, 40.0]",
      "37.3 [15.0, 70.0]", "3",    "3.5",       "1"};
  EXPECT_EQ(testdata::cellsOfLine(table, 2), expected);
  EXPECT_EQ(table.find("boolean"), std::string::npos);  // no updates: not a deforming row
}

TEST(DeformTable, RebuildsDashWhereTheBackendDoesNotCount) {
  CombinationResult r = testdata::okResult(testdata::combination("obbtree"));
  QueryMeasurement& m = r.measurements[0];
  for (FrameRecord& f : m.frames)
    f.update_us = 1.0;
  summariseMeasurement(m);
  EXPECT_FALSE(m.update_rebuilds.has_value());
  EXPECT_EQ(testdata::cellsOfLine(deformTable({r}), 2).at(7), "-");
}

TEST(DeformTable, EmptyWithoutUpdates) {
  EXPECT_EQ(deformTable({testdata::okResult(testdata::combination("obbtree"))}), "");
}

}  // namespace
}  // namespace collido::study
