// The two timing protocols measure the same answers: cycled passes time one call per frame each,
// `repetitions` passes, with deforming objects updated to each frame first; the repeated
// protocol's secondary figure can be measured after them.
#include <gtest/gtest.h>

#include <collido/runner/measurement_json.h>
#include <collido/runner/runner.h>
#include <collido/scene/scene.h>

#include "support/runs/run_plugin.h"

namespace collido {
namespace {

// A rigid ring through a pulsating one, 4 frames.
constexpr const char* kRingsScene = R"({"name": "rings", "frames": 4, "objects": [
  {"name": "a", "shape": {"generator": "torus", "minor_radius": 0.3, "major_segments": 16,
                          "minor_segments": 8}},
  {"name": "b", "shape": {"generator": "torus", "minor_radius": 0.3, "major_segments": 16,
                          "minor_segments": 8},
   "pose": {"translation": [1.2, 0, 0], "rotation": {"axis": [1, 0, 0], "degrees": 90}},
   "deform": {"rules": [{"pulsate": {"amplitude": 0.05, "period": 4}}]}}],
  "queries": [{"name": "pairs", "a": "a", "b": "b", "kind": "all_pairs"},
              {"name": "hit", "a": "a", "b": "b", "kind": "boolean"}]})";

RunReport run(const Scene& scene, TimingProtocol protocol) {
  RunOptions options = test::repeated(3);
  options.protocol = protocol;
  options.repeated_calls = 2;  // the secondary figure, measured under the cycled protocol only
  return test::runPlugin(scene, "obbtree", "obbtree", options);
}

TEST(TimingProtocol, CycledTimesEveryFrameAndAnswersAlike) {
  const Result<Scene> scene = parseScene(kRingsScene, "rings.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  const RunReport repeated = run(scene.value(), TimingProtocol::kRepeated);
  const RunReport cycled = run(scene.value(), TimingProtocol::kCycled);
  ASSERT_EQ(cycled.measurements.size(), 2u);
  for (std::size_t q = 0; q < 2; ++q) {
    const QueryMeasurement& r = repeated.measurements[q];
    const QueryMeasurement& c = cycled.measurements[q];
    SCOPED_TRACE(c.query);
    ASSERT_EQ(c.status, "ok");
    EXPECT_EQ(r.protocol, TimingProtocol::kRepeated);
    EXPECT_EQ(c.protocol, TimingProtocol::kCycled);
    EXPECT_EQ(c.times_us.size(), 4u * 3u) << "the secondary figure's calls are not the headline's";
    EXPECT_FALSE(r.repeated_us.has_value());
    ASSERT_TRUE(c.repeated_us.has_value());
    EXPECT_GT(*c.repeated_us, 0.0);
    EXPECT_EQ(c.disagreements, 0u);
    ASSERT_EQ(c.frames.size(), r.frames.size());
    for (std::size_t f = 0; f < c.frames.size(); ++f) {
      EXPECT_EQ(c.frames[f].reported_pairs, r.frames[f].reported_pairs);
      EXPECT_EQ(c.frames[f].oracle_pairs, r.frames[f].oracle_pairs);
      EXPECT_GT(c.frames[f].median_us, 0.0);
      EXPECT_TRUE(c.frames[f].update_us.has_value()) << "the checking pass times the update";
    }
    const Result<QueryMeasurement> back = measurementFromJson(measurementToJson(c));
    ASSERT_TRUE(back.ok()) << back.status().message();
    EXPECT_EQ(back.value().protocol, TimingProtocol::kCycled);
    EXPECT_EQ(back.value().repeated_us, c.repeated_us);
  }
  EXPECT_EQ(parseTimingProtocol("cycled"), TimingProtocol::kCycled);
  EXPECT_FALSE(parseTimingProtocol("shuffled").has_value());
}

}  // namespace
}  // namespace collido
