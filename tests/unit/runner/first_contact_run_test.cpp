// A first-contact query through the runner: each step asked with the next frame's poses, the
// answer held to the oracle's certified bracket, the verdicts counted as missed and false
// contacts, and the bracket's error recorded.
#include <gtest/gtest.h>

#include <collido/runner/runner.h>
#include <collido/scene/scene.h>

#include "support/runs/run_plugin.h"
#include "support/runs/scripted_backend.h"
#include "support/test_paths.h"

namespace collido {
namespace {

// A rod 0.02 thick crossing a plate 0.02 thick between frames 0 and 1: they share points for t
// in [0.498, 0.502] of that step only. From frame 1 to 2 the rod stays where it is.
constexpr const char* kCrossing = R"({"name": "crossing", "frames": 3, "objects": [
  {"name": "plate", "shape": {"generator": "box", "size": [0.02, 2, 2]}},
  {"name": "rod", "shape": {"generator": "box", "size": [0.02, 0.2, 0.2]},
   "motion": {"keyframes": [{"frame": 0, "pose": {"translation": [-5, 0, 0]}},
                            {"frame": 1, "pose": {"translation": [5, 0, 0]}}]}}],
  "queries": [{"name": "cross", "a": "plate", "b": "rod", "kind": "first_contact",
               "bracket_width": 0.01}]})";

const QueryMeasurement& runWith(const Scene& scene,
                                const std::map<std::string, std::string>& options,
                                RunReport& report) {
  report =
      runScene(scene, BackendSpec{test::scriptedBackend(), "scripted", options}, test::repeated(1));
  EXPECT_EQ(report.measurements.size(), 1u);
  return report.measurements.front();
}

TEST(FirstContactRun, EachStepIsHeldToTheOraclesBracket) {
  const Result<Scene> scene = parseScene(kCrossing, "crossing.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  ASSERT_EQ(scene.value().queries.front().asked.text(), "frames 0-1");

  RunReport report;
  // A bracket holding the crossing is right in step 0 and a false contact in step 1.
  const QueryMeasurement& right =
      runWith(scene.value(),
              {{"first_contact", "true"}, {"touch_lo", "0.495"}, {"touch_hi", "0.499"}}, report);
  ASSERT_TRUE(right.ok()) << right.status.text();
  ASSERT_EQ(right.frames.size(), 2u);
  const FrameRecord& step = right.frames[0];
  EXPECT_EQ(step.oracle_touches, true);
  ASSERT_TRUE(step.oracle_t_lo && step.oracle_t_hi);
  EXPECT_LE(*step.oracle_t_lo, 0.498);
  EXPECT_GE(*step.oracle_t_hi, 0.498 - 1e-12);
  EXPECT_FALSE(step.disagrees(QueryKind::kFirstContact));
  ASSERT_TRUE(step.first_contact_error);
  EXPECT_GE(*step.first_contact_error, 0.499 - *step.oracle_t_lo);
  EXPECT_EQ(right.frames[1].oracle_touches, false);
  EXPECT_TRUE(right.frames[1].disagrees(QueryKind::kFirstContact));
  EXPECT_EQ(right.false_positives, 1u);
  EXPECT_EQ(right.false_negatives, 0u);
  EXPECT_EQ(right.disagreements, 1u);
  EXPECT_EQ(right.max_first_contact_error, step.first_contact_error);

  // Apart in both steps: the crossing is a missed contact.
  const QueryMeasurement& apart = runWith(scene.value(), {{"first_contact", "true"}}, report);
  EXPECT_EQ(apart.false_negatives, 1u);
  EXPECT_EQ(apart.false_positives, 0u);
  EXPECT_EQ(apart.disagreements, 1u);

  // A contact after the crossing has ended claims a free part the oracle proved touching.
  const QueryMeasurement& late =
      runWith(scene.value(),
              {{"first_contact", "true"}, {"touch_lo", "0.6"}, {"touch_hi", "0.601"}}, report);
  EXPECT_TRUE(late.frames[0].invalid_first_contact);
  EXPECT_EQ(late.false_negatives, 0u);
  EXPECT_EQ(late.disagreements, 2u);
}

// The OBB tree's own answer agrees with the oracle; the runner's discrete checks of its boolean
// answers miss the crossing with one sub-step and find it with 512 (1/512 < 0.004).
TEST(FirstContactRun, SubStepsOfAnyBackendAndTheTreesOwnAnswer) {
  const Result<Scene> scene = parseScene(kCrossing, "crossing.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  const RunReport own = test::runPlugin(scene.value(), "obbtree", "obbtree", test::repeated(1));
  ASSERT_EQ(own.measurements.size(), 1u);
  const QueryMeasurement& tree = own.measurements.front();
  ASSERT_TRUE(tree.ok()) << tree.status.text();
  EXPECT_EQ(tree.disagreements, 0u);
  ASSERT_TRUE(tree.frames[0].reported_t_hi);
  EXPECT_LE(*tree.frames[0].reported_t_hi - *tree.frames[0].reported_t_lo, 0.01);

  const RunReport one =
      test::runPlugin(scene.value(), "obbtree", "obbtree", test::repeated(1), {{"substeps", "1"}});
  ASSERT_EQ(one.measurements.size(), 1u);
  EXPECT_EQ(one.measurements.front().backend, "obbtree[substeps=1]");
  EXPECT_EQ(one.measurements.front().false_negatives, 1u);
  EXPECT_EQ(one.measurements.front().disagreements, 1u);

  const RunReport fine = test::runPlugin(scene.value(), "obbtree", "obbtree", test::repeated(1),
                                         {{"substeps", "512"}});
  const QueryMeasurement& discrete = fine.measurements.front();
  EXPECT_EQ(discrete.disagreements, 0u);
  ASSERT_TRUE(discrete.frames[0].reported_t_hi);
  EXPECT_DOUBLE_EQ(*discrete.frames[0].reported_t_hi - *discrete.frames[0].reported_t_lo,
                   1.0 / 512);
}

// The bundled crossing scene does what its comment says: the tree's first contact finds the
// three crossings, and checks at the frames alone (one sub-step: each step's two ends) or at 64
// sub-steps miss them all.
TEST(FirstContactRun, TheThinCrossingSceneTunnelsBetweenFrames) {
  const std::string path = test::sourcePath("scenes/continuous/thin_crossing.json");
  const Result<Scene> scene = loadScene(path);
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  const RunReport own = test::runPlugin(scene.value(), "obbtree", "obbtree", test::repeated(1));
  ASSERT_EQ(own.measurements.size(), 1u);
  const QueryMeasurement& crossing = own.measurements[0];
  EXPECT_EQ(crossing.disagreements, 0u);
  int touches = 0;
  for (const FrameRecord& f : crossing.frames)
    touches += f.oracle_touches.value_or(false) ? 1 : 0;
  EXPECT_EQ(touches, 3);
  for (const char* substeps : {"1", "64"}) {
    const RunReport coarse = test::runPlugin(scene.value(), "obbtree", "obbtree", test::repeated(1),
                                             {{"substeps", substeps}});
    EXPECT_EQ(coarse.measurements[0].false_negatives, 3u) << substeps << " sub-steps";
    for (const FrameRecord& f : coarse.measurements[0].frames)
      EXPECT_FALSE(f.reported_intersecting) << "step " << f.frame << ", " << substeps;
  }
}

TEST(FirstContactRun, SubStepsMustBeAWholeNumberFromOneTo4096) {
  for (const char* text : {"scripted[substeps=0]", "scripted[substeps=4097]",
                           "scripted[substeps=x]", "scripted[substeps=2.5]"}) {
    const Result<std::vector<BackendSpec>> specs =
        resolveBackends({text}, {test::scriptedBackend()});
    ASSERT_FALSE(specs.ok()) << text;
    EXPECT_NE(specs.status().message().find("sub-steps must be a whole number from 1 to 4096"),
              std::string::npos)
        << specs.status().message();
  }
  const Result<std::vector<BackendSpec>> four =
      resolveBackends({"scripted[substeps=4;distance=1]"}, {test::scriptedBackend()});
  ASSERT_TRUE(four.ok()) << four.status().toString();
  EXPECT_EQ(four.value()[0].substeps(), 4);
  EXPECT_EQ(four.value()[0].pluginOptions(),
            (std::map<std::string, std::string>{{"distance", "1"}}));
}

TEST(FirstContactRun, ABackendWithoutTheKindIsSkippedNotFailed) {
  const Result<Scene> scene = parseScene(kCrossing, "crossing.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  RunReport report;
  const QueryMeasurement& m = runWith(scene.value(), {}, report);
  EXPECT_TRUE(m.status.skipped()) << m.status.text();
}

}  // namespace
}  // namespace collido
