// "What to pick": the fastest and smallest exact settings, the fastest within an error budget,
// the best of every family and what the fastest of all costs, on hand-made figures.
#include <collido/study/selection_table.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "study_test_data.h"

namespace collido::study {
namespace {

/// A boolean query of two frames, both at `us`; `wrong`: the second frame's answer is wrong.
CombinationResult setting(const std::string& backend, double us, std::size_t memory_bytes,
                          bool wrong = false) {
  QueryMeasurement m;
  m.backend = backend;
  m.scene = "tori";
  m.query = "boolean";
  m.kind = QueryKind::kBoolean;
  m.times_us = {us, us};
  for (std::size_t i = 0; i < 2; ++i) {
    FrameRecord f;
    f.frame = i;
    f.oracle_intersecting = true;
    f.reported_intersecting = !(wrong && i == 1);
    f.median_us = us;
    m.frames.push_back(f);
  }
  m.triangles = 1000;
  m.memory_bytes = memory_bytes;
  summariseMeasurement(m);
  CombinationResult r;
  r.combination = testdata::combination(backend);
  r.measurements = {std::move(m)};
  return r;
}

std::vector<CombinationResult> field() {
  return {setting("obbtree", 20.0, 116000), setting("obbtree[float_boxes=true]", 15.0, 50000),
          setting("fcl:obb", 30.0, 200000), setting("bullet", 5.0, 40000, /*wrong=*/true)};
}

TEST(WhatToPick, FastestSmallestWithinTheBudgetAndPerFamily) {
  const std::vector<SceneQueryPicks> picks = whatToPick(field());
  ASSERT_EQ(picks.size(), 1u);
  const SceneQueryPicks& p = picks[0];
  EXPECT_EQ(p.scene, "tori");
  EXPECT_EQ(p.query, "boolean");
  ASSERT_TRUE(p.fastest_exact && p.fastest_exact->runner_up);
  EXPECT_EQ(p.fastest_exact->chosen.backend, "obbtree[float_boxes=true]");
  // The runner-up is the best of another family, not the pick's own double-box setting.
  EXPECT_EQ(p.fastest_exact->runner_up->backend, "fcl:obb");
  // Bullet's one wrong frame in two is past 5%: the budget's pick is the exact one.
  ASSERT_TRUE(p.fastest_within);
  EXPECT_EQ(p.fastest_within->chosen.backend, "obbtree[float_boxes=true]");
  ASSERT_TRUE(p.smallest_exact && p.smallest_exact->runner_up);
  EXPECT_EQ(p.smallest_exact->chosen.backend, "obbtree[float_boxes=true]");
  EXPECT_EQ(p.smallest_exact->runner_up->backend, "fcl:obb");
  std::vector<std::string> families;
  for (const PickedSetting& s : p.fastest_per_family)
    families.push_back(s.backend);
  EXPECT_EQ(families, (std::vector<std::string>{"obbtree[float_boxes=true]", "fcl:obb", "bullet"}));
  // Every other setting is clearly beaten: no ties.
  EXPECT_TRUE(p.fastest_exact->ties.empty());
  EXPECT_TRUE(p.smallest_exact->ties.empty());
  EXPECT_EQ(
      p.cost,
      "bullet is 3.00x faster than obbtree[float_boxes=true] here but wrong on 1 of 2 frames");

  const std::string text = whatToPickText(picks, PickBudget{});
  EXPECT_NE(text.find("within 5% wrong"), std::string::npos) << text;
  // fcl:obb's time over the pick's: its interval is the ratio itself (times that do not vary).
  EXPECT_NE(text.find(" 2.00x "), std::string::npos) << text;
  EXPECT_NE(text.find("4.00x"), std::string::npos) << text;  // fcl:obb's memory over the pick's
  EXPECT_NE(text.find("tori / boolean: bullet is 3.00x faster"), std::string::npos) << text;
  EXPECT_NE(text.find("tori / boolean: obbtree[float_boxes=true] "), std::string::npos) << text;
  EXPECT_NE(text.find(", bullet "), std::string::npos) << text;
  EXPECT_NE(text.find(" us (wrong on 1 of 2)"), std::string::npos) << text;

  const nlohmann::json json = whatToPickJson(picks, PickBudget{});
  EXPECT_EQ(json.at("budget").at("wrong_frame_share"), 0.05);
  const nlohmann::json& row = json.at("picks").at(0);
  EXPECT_EQ(row.at("fastest_exact").at("backend"), "obbtree[float_boxes=true]");
  EXPECT_DOUBLE_EQ(row.at("fastest_exact").at("runner_up_ratio").get<double>(), 2.0);
  EXPECT_EQ(row.at("fastest_exact").at("runner_up_ratio_ci95"), nlohmann::json::array({2.0, 2.0}));
  EXPECT_EQ(row.at("fastest_exact").at("ties"), nlohmann::json::array());
  EXPECT_EQ(row.at("fastest_exact").at("ci95_us"), nlohmann::json::array({15.0, 15.0}));
  EXPECT_EQ(row.at("fastest_exact").at("clearly_faster_than"),
            nlohmann::json::array({"obbtree", "fcl:obb"}));
  EXPECT_DOUBLE_EQ(row.at("fastest_exact").at("versus").at("fcl:obb").at(0).get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(json.at("equivalence_band").get<double>(), kEquivalenceBand);
  EXPECT_DOUBLE_EQ(row.at("smallest_exact").at("bytes_per_triangle").get<double>(), 50.0);
  EXPECT_EQ(row.at("fastest_per_family").size(), 3u);
  EXPECT_TRUE(row.at("settings").at(0).at("recall").is_null());  // a boolean query has no pairs
}

TEST(WhatToPick, SettingsWithinTheBandAreTiesNotWins) {
  // fcl:obb is 5% slower than the OBB tree, inside the band; the float-box setting 8% larger.
  const std::vector<SceneQueryPicks> picks =
      whatToPick({setting("obbtree", 20.0, 100000), setting("fcl:obb", 21.0, 300000),
                  setting("obbtree[float_boxes=true]", 30.0, 108000)});
  ASSERT_EQ(picks.size(), 1u);
  const SceneQueryPicks& p = picks[0];
  ASSERT_TRUE(p.fastest_exact && p.fastest_exact->runner_up_ratio);
  EXPECT_EQ(p.fastest_exact->chosen.backend, "obbtree");
  EXPECT_EQ(p.fastest_exact->ties, std::vector<std::string>{"fcl:obb"});
  EXPECT_DOUBLE_EQ(p.fastest_exact->runner_up_ratio->value, 1.05);
  ASSERT_TRUE(p.smallest_exact);
  EXPECT_EQ(p.smallest_exact->ties, std::vector<std::string>{"obbtree[float_boxes=true]"});
  const std::string text = whatToPickText(picks, PickBudget{});
  EXPECT_NE(text.find("obbtree ≈ fcl:obb "), std::string::npos) << text;
  EXPECT_NE(text.find("obbtree ≈ obbtree[float_boxes=true] "), std::string::npos) << text;
  EXPECT_EQ(whatToPickJson(picks, PickBudget{}).at("picks").at(0).at("fastest_exact").at("ties"),
            nlohmann::json::array({"fcl:obb"}));
}

TEST(WhatToPick, AllPairsSettingsCarryTheirPairRecallAndPrecision) {
  CombinationResult r = setting("bullet", 5.0, 40000, /*wrong=*/true);
  QueryMeasurement& m = r.measurements.at(0);
  m.query = "all_pairs";
  m.kind = QueryKind::kAllPairs;
  m.recall = 0.9;
  m.precision = 0.75;
  const nlohmann::json setting =
      whatToPickJson(whatToPick({r}), PickBudget{}).at("picks").at(0).at("settings").at(0);
  EXPECT_DOUBLE_EQ(setting.at("recall").get<double>(), 0.9);
  EXPECT_DOUBLE_EQ(setting.at("precision").get<double>(), 0.75);
}

TEST(WhatToPick, AWiderBudgetAdmitsTheFastWrongSetting) {
  const std::vector<SceneQueryPicks> picks = whatToPick(field(), PickBudget{0.5});
  ASSERT_TRUE(picks.at(0).fastest_within);
  EXPECT_EQ(picks[0].fastest_within->chosen.backend, "bullet");
  EXPECT_EQ(picks[0].fastest_within->chosen.wrong_frames, 1u);
}

TEST(WhatToPick, NoExactSettingIsSaid) {
  const std::vector<SceneQueryPicks> picks =
      whatToPick({setting("bullet", 5.0, 40000, true), setting("ode", 9.0, 30000, true)});
  ASSERT_EQ(picks.size(), 1u);
  EXPECT_FALSE(picks[0].fastest_exact);
  EXPECT_FALSE(picks[0].smallest_exact);
  EXPECT_EQ(picks[0].cost,
            "no setting is exact on every frame; the fewest wrong frames: bullet "
            "(1 of 2)");
  EXPECT_NE(whatToPickText(picks, PickBudget{}).find("none exact"), std::string::npos);
}

}  // namespace
}  // namespace collido::study
