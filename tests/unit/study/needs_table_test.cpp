// The needs section of table.txt: every against declared and changed, per setting, scene and
// query, with what declaring saved and the frames answered without a query.
#include <collido/study/needs_table.h>

#include <gtest/gtest.h>

#include "study_test_data.h"

namespace collido::study {
namespace {

// The all-pairs measurement of `r` built with `bytes` and `build_ms`; with `reused` frames held
// (every pair's answer reused), as the runner records them.
CombinationResult withFigures(CombinationResult r, std::size_t bytes, double build_ms,
                              std::size_t reused) {
  QueryMeasurement& pairs = r.measurements.front();
  pairs.memory_bytes = bytes;
  pairs.build_ms = build_ms;
  for (std::size_t f = 0; f < reused; ++f)
    pairs.frames[f].reused_pairs = pairs.frames[f].object_pairs;
  summariseMeasurement(pairs);
  return r;
}

TEST(NeedsTable, EveryAgainstDeclaredAndChanged) {
  using testdata::combination;
  using testdata::okResult;
  const std::vector<CombinationResult> results = {
      withFigures(okResult(combination("fcl:obbrss", NeedsMode::kEvery)), 300000, 4.0, 0),
      withFigures(okResult(combination("fcl:obbrss", NeedsMode::kDeclared)), 180000, 3.0, 0),
      withFigures(okResult(combination("fcl:obbrss", NeedsMode::kChanged)), 180000, 3.0, 2),
      // Another backend run declared only: no row of its own.
      okResult(combination("bullet"))};
  const std::string table = needsTable(results);
  ASSERT_FALSE(table.empty());
  for (const char* column : {"B/tri every", "B/tri declared", "B/tri saved", "build ms saved",
                             "mean us changed", "frames unasked", "disagree changed"}) {
    EXPECT_NE(table.find(column), std::string::npos) << column;
  }
  // 300 against 180 bytes a triangle (1000 triangles): 120 saved, 40%; build 1 ms, 25%; 2 of 3
  // frames answered without a query.
  EXPECT_NE(table.find("120 (40%)"), std::string::npos) << table;
  EXPECT_NE(table.find("1.00 (25%)"), std::string::npos) << table;
  EXPECT_NE(table.find("2/3"), std::string::npos) << table;
  EXPECT_EQ(table.find("bullet"), std::string::npos) << table;
}

TEST(NeedsTable, EmptyWithoutEvery) {
  EXPECT_EQ(needsTable({testdata::okResult(testdata::combination("obbtree")),
                        testdata::okResult(testdata::combination("obbtree", NeedsMode::kChanged))}),
            "");
}

}  // namespace
}  // namespace collido::study
