// The witness-gap check (core/src/runner/checks/witness_gap.cpp) as the runner, the records and
// the tables see it: a backend whose closest points lie 0.25 from its reported distance.
#include <algorithm>

#include <gtest/gtest.h>

#include <collido/runner/checks.h>
#include <collido/runner/measurement_columns.h>
#include <collido/runner/runner.h>
#include <collido/scene/scene.h>

#include "support/runs/run_plugin.h"
#include "support/runs/scripted_backend.h"

namespace collido {
namespace {

constexpr const char* kTwoFrameScene = R"({"name": "apart", "frames": 2, "objects": [
  {"name": "a", "shape": {"generator": "sphere", "slices": 6, "stacks": 3}},
  {"name": "b", "shape": {"generator": "sphere", "slices": 6, "stacks": 3},
   "pose": {"translation": [5, 0, 0]}}],
  "queries": [{"name": "gap", "a": "a", "b": "b", "kind": "distance"},
              {"name": "touch", "a": "a", "b": "b", "kind": "boolean"}]})";

std::optional<double> figure(const QueryMeasurement& m, const std::string& name) {
  for (const CheckFigure& f : checkFigures()) {
    if (f.name == name) return f.value(m);
  }
  ADD_FAILURE() << "no check figure " << name;
  return std::nullopt;
}

TEST(WitnessGapCheck, IsTheLargestMissOfTheReportedPointsOnDistanceQueriesOnly) {
  const Result<Scene> scene = parseScene(kTwoFrameScene, "apart.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  const RunReport report = runScene(
      scene.value(), BackendSpec{test::scriptedBackend(), "scripted", {{"distance", "0.25"}}},
      test::repeated(1));
  ASSERT_EQ(report.measurements.size(), 2u);
  const QueryMeasurement& distance = report.measurements[0];
  const QueryMeasurement& boolean = report.measurements[1];
  ASSERT_EQ(distance.frames.size(), 2u);
  for (const FrameRecord& f : distance.frames)
    EXPECT_DOUBLE_EQ(f.values.at("witness_gap"), 0.25);
  EXPECT_EQ(figure(distance, "max_witness_gap"), 0.25);
  for (const FrameRecord& f : boolean.frames)
    EXPECT_EQ(f.values.count("witness_gap"), 0u);
  EXPECT_EQ(figure(boolean, "max_witness_gap"), std::nullopt);

  const std::vector<std::string> headers = measurementHeaders();
  const auto column = std::find(headers.begin(), headers.end(), "witness gap");
  ASSERT_NE(column, headers.end());
  const auto at = static_cast<std::size_t>(column - headers.begin());
  EXPECT_EQ(measurementCells(distance)[at], "0.25");
  EXPECT_EQ(measurementCells(boolean)[at], "-");
}

}  // namespace
}  // namespace collido
