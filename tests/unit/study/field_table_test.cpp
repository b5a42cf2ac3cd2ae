// "The OBB tree against the field": which settings are compared, and the figures, by hand.
#include <collido/study/field_table.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <collido/runner/text_table.h>

#include "study_test_data.h"
#include "table_cells.h"

namespace collido::study {
namespace {

/// An all-pairs measurement of two frames with these median times (the frames' mean is their
/// average), 10 and 30 true pairs, 200 and 400 box tests, 20 and 60 triangle tests, floors 1
/// and 2 us; `wrong`: the second frame misses every pair.
QueryMeasurement pairs(const std::string& backend, double first_us, double second_us,
                       bool wrong = false) {
  QueryMeasurement m;
  m.backend = backend;
  m.scene = "tori";
  m.query = "all_pairs";
  m.kind = QueryKind::kAllPairs;
  m.times_us = {first_us, second_us};
  const std::size_t exact[2] = {10, 30};
  for (std::size_t i = 0; i < 2; ++i) {
    FrameRecord f;
    f.frame = i;
    f.oracle_intersecting = true;
    f.reported_intersecting = !(wrong && i == 1);
    f.oracle_pairs = exact[i];
    f.reported_pairs = wrong && i == 1 ? 0 : exact[i];
    f.matched_pairs = f.reported_pairs;
    f.median_us = m.times_us[i];
    f.floor_us = 1.0 + static_cast<double>(i);
    f.bv_tests = 200 * (i + 1);
    f.primitive_tests = 20 + 40 * i;
    m.frames.push_back(f);
  }
  m.counts_bv_tests = true;
  m.counts_primitive_tests = true;
  m.triangles = 1000;
  m.memory_bytes = 116000;
  summariseMeasurement(m);
  return m;
}

CombinationResult result(const std::string& backend, QueryMeasurement m,
                         const std::string& category = "") {
  CombinationResult r;
  r.combination = testdata::combination(backend);
  r.combination.category = category;
  r.measurements = {std::move(m)};
  return r;
}

/// The table's first data row.
std::vector<std::string> onlyRow(const std::string& table) {
  return testdata::cellsOfLine(table, 2);
}

TEST(FieldTable, FastestExactSingleThreadSettingAgainstEachFamilysFastest) {
  const std::vector<CombinationResult> results = {
      result("obbtree[max_leaf_triangles=4]", pairs("obbtree[max_leaf_triangles=4]", 10, 30)),
      // Faster but wrong, and faster on two threads: neither is the one compared.
      result("obbtree[max_leaf_triangles=1]", pairs("obbtree[max_leaf_triangles=1]", 1, 1, true)),
      result("obbtree[threads=2]", pairs("obbtree[threads=2]", 5, 15)),
      result("fcl:obb", pairs("fcl:obb", 50, 110)),
      result("fcl:obbrss", pairs("fcl:obbrss", 40, 80)),
      result("bullet", pairs("bullet", 30, 50, true)),
  };
  const std::string table = fieldTable(results);
  SCOPED_TRACE(table);
  const std::vector<std::string> cells = onlyRow(table);
  // scene, query, ours, mean us, B/tri, floor x, box/pair, tri/pair, then per comparator
  // (fcl:obb, fcl, bullet) its time and the ratio.
  const std::vector<std::string> expected = {
      // Each time with its interval: one call per frame, so the frames drawn decide it.
      "tori", "all_pairs", "obbtree[max_leaf_triangles=4]", "20.0 [10.0, 30.0]", "116",
      // (10 + 30) / (1 + 2); (200 + 400) / 40; (20 + 60) / 40.
      "13.3", "15.0", "2.0",
      // fcl:obb mean 80; FCL's fastest is OBBRSS (60); Bullet 40, wrong on a frame. A ratio's
      // interval pairs the frames: fcl:obb's 5x and 3.67x on each alone bound its 4x.
      "80.0 [50.0, 110.0]", "4.00x [3.67, 5.00]", "60.0 [40.0, 80.0]", "3.00x [2.67, 4.00]",
      "40.0 [30.0, 50.0]!", "2.00x [1.67, 3.00]"};
  EXPECT_EQ(cells, expected);
}

TEST(FieldTable, NoExactSettingIsSaidNotHidden) {
  const std::vector<CombinationResult> results = {
      result("obbtree", pairs("obbtree", 1, 1, true)),
      result("fcl:obb", pairs("fcl:obb", 50, 110)),
  };
  const std::vector<std::string> cells = onlyRow(fieldTable(results));
  ASSERT_GE(cells.size(), 3u);
  EXPECT_EQ(cells[2], "no exact setting");
}

TEST(FieldTable, ARatioWithinTheBandIsMarkedATie) {
  const std::vector<std::string> cells =
      onlyRow(fieldTable({result("obbtree", pairs("obbtree", 10, 30)),
                          result("fcl:obb", pairs("fcl:obb", 10.5, 31.5))}));
  // scene, query, ours (4 cells), then fcl:obb's and FCL's fastest's time and ratio.
  ASSERT_EQ(cells.size(), 12u);
  EXPECT_EQ(cells[9], "≈1.05x");
}

// "Ours" is a study setting (the sweep's "field"): a plugin's authors put theirs first.
TEST(FieldTable, AnotherFamilyMayBeOurs) {
  const FieldSides sides{"bullet", "obbtree"};
  const std::string table = fieldTable(
      {result("obbtree", pairs("obbtree", 10, 30)), result("bullet", pairs("bullet", 30, 50)),
       result("fcl:obb", pairs("fcl:obb", 50, 110))},
      sides);
  SCOPED_TRACE(table);
  EXPECT_EQ(fieldTableTitle(sides), "bullet against the field");
  EXPECT_NE(table.find("bullet (fastest exact)"), std::string::npos);
  EXPECT_NE(table.find("time over bullet's"), std::string::npos);
  // scene, query, ours (bullet) and its 5 figures, the peer obbtree's time and ratio, then
  // those of each other family: obbtree's and fcl's fastest.
  const std::vector<std::string> cells = onlyRow(table);
  ASSERT_EQ(cells.size(), 14u);
  EXPECT_EQ(cells[2], "bullet");
  EXPECT_EQ(cells[8], "20.0 [10.0, 30.0]");
  EXPECT_EQ(cells[12], "80.0 [50.0, 110.0]");
}

TEST(FieldTable, EmptyWithoutAComparatorOrForStressScenes) {
  EXPECT_EQ(fieldTable({result("obbtree", pairs("obbtree", 10, 30))}), "");
  EXPECT_EQ(fieldTable({result("obbtree", pairs("obbtree", 10, 30), "near_touching"),
                        result("fcl:obb", pairs("fcl:obb", 50, 110), "near_touching")}),
            "");
}

}  // namespace
}  // namespace collido::study
