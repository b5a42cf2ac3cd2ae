// Reusing the answer of the frame before for an object pair that did not change: the same
// answers as asking, the held frames untimed and unworked, a deforming object always asked.
#include <gtest/gtest.h>

#include <collido/host/plugin_library.h>
#include <collido/runner/measurement_json.h>
#include <collido/runner/runner.h>
#include <collido/scene/scene.h>

#include "support/test_paths.h"

namespace collido {
namespace {

// A ring held still in frames 2 to 4 (3 and 4 are as the frame before), through a fixed one;
// a third ring pulsates, so it is never as it was.
constexpr const char* kScene = R"({"name": "held", "frames": 6, "objects": [
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

RunReport run(const Scene& scene, TimingProtocol protocol, bool reuse) {
  Result<std::shared_ptr<PluginLibrary>> library =
      PluginLibrary::open(test::pluginDirectory() + "/libcollido_plugin_obbtree.so");
  EXPECT_TRUE(library.ok()) << library.status().toString();
  RunOptions options;
  options.repetitions = 3;
  options.protocol = protocol;
  options.reuse_unchanged = reuse;
  return runScene(scene, BackendSpec{library.value(), "obbtree", {}}, options);
}

TEST(ReuseUnchanged, HeldFramesTakeTheAnswerBeforeAndAgreeWithTheOracle) {
  const Result<Scene> scene = parseScene(kScene, "held.json", ".");
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
      const Result<QueryMeasurement> back = measurementFromJson(measurementToJson(w));
      ASSERT_TRUE(back.ok()) << back.status().message();
      EXPECT_EQ(back.value().frames[3].reused_pairs, q == 0 ? 1u : 0u);
    }
    // The held frames of the first query intersect: reusing is not only reusing "apart".
    EXPECT_GT(warm.measurements[0].frames[3].oracle_pairs, 0u);
  }
}

}  // namespace
}  // namespace collido
