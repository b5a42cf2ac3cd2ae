// Reusing the answer of the frame before for an object pair that did not change: the same
// answers as asking, the held frames untimed and unworked, a deforming object always asked.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/runner/measurement_json.h>
#include <collido/runner/runner.h>
#include <collido/scene/scene.h>

#include "support/runs/run_plugin.h"

namespace collido {
namespace {

// A ring held still in frames 2 to 4 (3 and 4 are as the frame before), through a fixed one;
// a third ring pulsates, so it is never as it was.
constexpr const char* kHeldScene = R"({"name": "held", "frames": 6, "objects": [
  {"name": "a", "shape": {"generator": "torus", "minor_radius": 0.3, "major_segments": 16,
                          "minor_segments": 8}},
  {"name": "b", "shape": {"generator": "torus", "minor_radius": 0.3, "major_segments": 16,
                          "minor_segments": 8},
   "motion": {"poses": [{"translation": [2.5, 0, 0]}, {"translation": [1.8, 0, 0]},
                        {"translation": [0.5, 0, 0]},
                        {"translation": [0.5, 0, 0]},
                        {"translation": [0.5, 0, 0]},
                        {"translation": [0.4, 0, 0]}]}},
  {"name": "c", "shape": {"generator": "torus", "minor_radius": 0.3, "major_segments": 16,
                          "minor_segments": 8},
   "pose": {"translation": [-1.2, 0, 0], "rotation": {"axis": [1, 0, 0], "degrees": 90}},
   "deform": {"rules": [{"pulsate": {"amplitude": 0.05, "period": 4}}]}}],
  "queries": [{"name": "held", "a": "a", "b": "b", "kind": "all_pairs"},
              {"name": "pulsing", "a": "a", "b": "c", "kind": "all_pairs"}]})";

RunReport run(const Scene& scene, TimingProtocol protocol, bool reuse, bool skip_apart = false) {
  RunOptions options = test::repeated(3);
  options.protocol = protocol;
  options.reuse_unchanged = reuse;
  options.skip_apart_pairs = skip_apart;
  return test::runPlugin(scene, "obbtree", "obbtree", options);
}

TEST(ReuseUnchanged, HeldFramesTakeTheAnswerBeforeAndAgreeWithTheOracle) {
  const Result<Scene> scene = parseScene(kHeldScene, "held.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  for (const TimingProtocol protocol : {TimingProtocol::kRepeated, TimingProtocol::kCycled}) {
    SCOPED_TRACE(timingProtocolName(protocol));
    const RunReport cold = run(scene.value(), protocol, false);
    const RunReport warm = run(scene.value(), protocol, true);
    ASSERT_EQ(warm.measurements.size(), 2u);
    for (std::size_t q = 0; q < 2; ++q) {
      const QueryMeasurement& c = cold.measurements[q];
      const QueryMeasurement& w = warm.measurements[q];
      SCOPED_TRACE(w.query);
      ASSERT_EQ(w.status, "ok");
      EXPECT_EQ(w.disagreements, 0u);
      ASSERT_EQ(w.frames.size(), 6u);
      for (std::size_t f = 0; f < 6; ++f) {
        SCOPED_TRACE(f);
        EXPECT_EQ(c.frames[f].reused_pairs, 0u);
        EXPECT_EQ(w.frames[f].reported_pairs, c.frames[f].reported_pairs);
        EXPECT_EQ(w.frames[f].oracle_pairs, c.frames[f].oracle_pairs);
        const bool held = q == 0 && (f == 3 || f == 4);
        EXPECT_EQ(w.frames[f].reused_pairs, held ? 1u : 0u);
        if (held) {
          EXPECT_EQ(w.frames[f].median_us, 0.0);
          EXPECT_EQ(w.frames[f].bv_tests, 0u);
        } else {
          EXPECT_GT(w.frames[f].median_us, 0.0);
        }
      }
      // Summed: two reused pairs, both in frames answered without a query; the floor ratio is
      // that of the asked frames only (the held frames, timed at 0, would lower it).
      EXPECT_EQ(w.reused_pairs, q == 0 ? 2u : 0u);
      EXPECT_EQ(w.unasked_frames, q == 0 ? 2u : 0u);
      EXPECT_EQ(c.unasked_frames, 0u);
      double timed = 0.0;
      double floor = 0.0;
      for (const FrameRecord& f : w.frames) {
        if (!f.floor_us || f.reused_pairs > 0) continue;
        timed += f.median_us;
        floor += *f.floor_us;
      }
      // The pulsing pair never meets: no true pair, no floor.
      ASSERT_EQ(w.floor_ratio.has_value(), q == 0);
      if (q == 0) {
        EXPECT_DOUBLE_EQ(*w.floor_ratio, timed / floor);
      }
      const Result<QueryMeasurement> back = measurementFromJson(measurementToJson(w));
      ASSERT_TRUE(back.ok()) << back.status().message();
      EXPECT_EQ(back.value().frames[3].reused_pairs, q == 0 ? 1u : 0u);
      EXPECT_EQ(back.value().unasked_frames, w.unasked_frames);
    }
    // The held frames of the first query intersect: reusing is not only reusing "apart".
    EXPECT_GT(warm.measurements[0].frames[3].oracle_pairs, 0u);
  }
}

// A query asked in frames 1 and 3 only compares frame 3 with frame 1, not with frame 2: ring b
// moves from frame 1 to 2 and holds from 2 to 3, so frame 3 is asked again, not reused.
TEST(ReuseUnchanged, AQueryAskedInSomeFramesComparesWithTheLastItAsked) {
  nlohmann::json json = nlohmann::json::parse(kHeldScene);
  json["queries"] = nlohmann::json::parse(
      R"([{"name": "gaps", "a": "a", "b": "b", "kind": "all_pairs", "frames": [[1, 1], [3, 3]]}])");
  const Result<Scene> scene = parseScene(json.dump(), "gaps.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  const QueryMeasurement m = run(scene.value(), TimingProtocol::kCycled, true).measurements[0];
  ASSERT_EQ(m.frames.size(), 2u);
  for (const FrameRecord& f : m.frames)
    EXPECT_EQ(f.reused_pairs, 0u) << "frame " << f.frame;
  EXPECT_EQ(m.disagreements, 0u);
}

// Two spheres of radius 1, the second at x = 5, 3, then 1.5: apart, apart, overlapping.
constexpr const char* kApartScene = R"({"name": "apart", "frames": 3, "objects": [
  {"name": "a", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6}},
  {"name": "b", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6},
   "motion": {"poses": [{"translation": [5, 0, 0]}, {"translation": [3, 0, 0]},
                        {"translation": [1.5, 0, 0]}]}}],
  "queries": [{"name": "any", "a": "b", "b": "a", "kind": "boolean"},
              {"name": "pairs", "a": "a", "b": "b", "kind": "all_pairs"},
              {"name": "gap", "a": "a", "b": "b", "kind": "distance"}]})";

TEST(SkipApart, TwoObjectCollisionQueriesProvenApartAreNotAsked) {
  const Result<Scene> scene = parseScene(kApartScene, "apart.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  const RunReport cold = run(scene.value(), TimingProtocol::kRepeated, false);
  const RunReport culled = run(scene.value(), TimingProtocol::kRepeated, false, true);
  ASSERT_EQ(culled.measurements.size(), 3u);
  for (std::size_t q = 0; q < 3; ++q) {
    const QueryMeasurement& c = cold.measurements[q];
    const QueryMeasurement& k = culled.measurements[q];
    SCOPED_TRACE(k.query);
    ASSERT_EQ(k.status, "ok");
    EXPECT_EQ(k.disagreements, 0u);
    // A distance has an answer at any gap: never culled.
    const bool cullable = k.kind != QueryKind::kDistance;
    EXPECT_EQ(k.skipped_pairs, cullable ? 2u : 0u);
    EXPECT_EQ(k.unasked_frames, cullable ? 2u : 0u);
    EXPECT_EQ(c.skipped_pairs, 0u);
    for (std::size_t f = 0; f < 3; ++f) {
      SCOPED_TRACE(f);
      const bool apart = cullable && f < 2;
      EXPECT_EQ(k.frames[f].skipped_pairs, apart ? 1u : 0u);
      EXPECT_EQ(k.frames[f].object_pairs, apart ? 0u : 1u);
      EXPECT_EQ(k.frames[f].reported_intersecting, c.frames[f].reported_intersecting);
      EXPECT_EQ(k.frames[f].reported_pairs, c.frames[f].reported_pairs);
      EXPECT_EQ(k.frames[f].oracle_intersecting, f == 2);
    }
  }
}

}  // namespace
}  // namespace collido
