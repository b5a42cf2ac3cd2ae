// A backend that fails mid-run fails its measurement, naming the frame and the call, and the
// study goes on: driven by the scripted backend (support/runs/scripted_backend.h), which fails
// the N-th build, update or query as an engine does.
#include <gtest/gtest.h>

#include <collido/runner/runner.h>
#include <collido/scene/scene.h>

#include "support/runs/run_plugin.h"
#include "support/runs/scripted_backend.h"

namespace collido {
namespace {

// Two spheres far apart, the second pulsating, 3 frames: every answer is "apart".
constexpr const char* kPulsatingScene = R"({"name": "apart", "frames": 3, "objects": [
  {"name": "a", "shape": {"generator": "sphere", "slices": 6, "stacks": 3}},
  {"name": "b", "shape": {"generator": "sphere", "slices": 6, "stacks": 3},
   "pose": {"translation": [5, 0, 0]},
   "deform": {"rules": [{"pulsate": {"amplitude": 0.05, "period": 3}}]}}],
  "queries": [{"name": "pairs", "a": "a", "b": "b", "kind": "all_pairs"}]})";

// The one measurement of kPulsatingScene on the scripted backend with `script` under `protocol`.
QueryMeasurement measure(const std::map<std::string, std::string>& script,
                         TimingProtocol protocol) {
  const Result<Scene> scene = parseScene(kPulsatingScene, "apart.json", ".");
  EXPECT_TRUE(scene.ok()) << scene.status().toString();
  RunOptions options = test::repeated(2);
  options.protocol = protocol;
  const RunReport report =
      runScene(scene.value(), BackendSpec{test::scriptedBackend(), "scripted", script}, options);
  EXPECT_EQ(report.measurements.size(), 1u);
  return report.measurements.empty() ? QueryMeasurement{} : report.measurements.front();
}

void expectFailed(const QueryMeasurement& m, const std::string& message) {
  EXPECT_TRUE(m.status.failed()) << m.status;
  EXPECT_NE(m.status.reason().find(message), std::string::npos) << m.status;
}

TEST(RunnerFailures, WithoutFailuresTheScriptedBackendIsRight) {
  const QueryMeasurement m = measure({}, TimingProtocol::kCycled);
  EXPECT_TRUE(m.ok()) << m.status;
  EXPECT_EQ(m.disagreements, 0u);
  EXPECT_EQ(m.times_us.size(), 3u * 2u);
}

TEST(RunnerFailures, AFailedBuildFailsTheQuery) {
  expectFailed(measure({{"fail_build", "2"}}, TimingProtocol::kCycled),
               "build: engine failure: scripted failure of build call 2");
}

// The checking pass updates b to each frame, timed (calls 1-3).
TEST(RunnerFailures, AFailedUpdateNamesTheFrameAndTheObject) {
  expectFailed(measure({{"fail_update", "2"}}, TimingProtocol::kCycled),
               "frame 1: update b: engine failure: scripted failure of update call 2");
}

// The checking pass asks each frame once (calls 1-3); the repeated protocol's timed calls
// follow each frame's checked call (frame 0: calls 2 and 3).
TEST(RunnerFailures, AFailedTimedCallOfTheRepeatedProtocolNamesItsFrame) {
  expectFailed(measure({{"fail_query", "3"}}, TimingProtocol::kRepeated),
               "frame 0: engine failure: scripted failure of query call 3");
}

// The cycled passes follow the checking pass: query call 5 is the second frame of the first
// pass, and update call 4 its first frame's untimed update.
TEST(RunnerFailures, AFailedCallOfTheCycledPassesNamesItsFrame) {
  expectFailed(measure({{"fail_query", "5"}}, TimingProtocol::kCycled),
               "frame 1: engine failure: scripted failure of query call 5");
  expectFailed(measure({{"fail_update", "4"}}, TimingProtocol::kCycled),
               "frame 0: update b: engine failure: scripted failure of update call 4");
}

TEST(RunnerFailures, AFailedCheckedCallNamesItsFrame) {
  expectFailed(measure({{"fail_query", "2"}}, TimingProtocol::kCycled),
               "frame 1: engine failure: scripted failure of query call 2");
}

}  // namespace
}  // namespace collido
