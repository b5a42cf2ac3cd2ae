// The work a backend's update() reports, per frame: summed into the measurement's rebuilds and
// kept through the records' JSON, absent where the backend does not count.
#include <gtest/gtest.h>

#include <collido/runner/measurement_json.h>
#include <collido/runner/runner.h>

namespace collido {
namespace {

QueryMeasurement withUpdates(bool counted) {
  QueryMeasurement m;
  m.backend = "b";
  m.scene = "s";
  m.query = "any";
  for (int i = 0; i < 3; ++i) {
    FrameRecord f;
    f.frame = static_cast<std::size_t>(i);
    f.median_us = 1.0;
    f.update_us = 2.0;
    f.update_work.counted = counted;
    f.update_work.nodes_refit = counted ? 10u * static_cast<std::uint64_t>(i) : 0u;
    f.update_work.rebuilds = counted && i == 2 ? 2u : 0u;
    f.update_work.nodes_rebuilt = counted && i == 2 ? 14u : 0u;
    m.frames.push_back(f);
    m.times_us.push_back(f.median_us);
  }
  summariseMeasurement(m);
  return m;
}

TEST(UpdateWork, RebuildsAreSummedAndSurviveJson) {
  const QueryMeasurement m = withUpdates(true);
  EXPECT_EQ(m.update_rebuilds, std::optional<std::uint64_t>(2));
  const Result<QueryMeasurement> back = measurementFromJson(measurementToJson(m));
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(back.value().update_rebuilds, m.update_rebuilds);
  const UpdateCounters& last = back.value().frames[2].update_work;
  EXPECT_TRUE(last.counted);
  EXPECT_EQ(last.nodes_refit, 20u);
  EXPECT_EQ(last.rebuilds, 2u);
  EXPECT_EQ(last.nodes_rebuilt, 14u);
}

TEST(UpdateWork, AbsentWhereTheBackendDoesNotCount) {
  const QueryMeasurement m = withUpdates(false);
  EXPECT_FALSE(m.update_rebuilds.has_value());
  const nlohmann::json json = measurementToJson(m);
  EXPECT_TRUE(json.at("frames")[0].at("update_rebuilds").is_null());
  const Result<QueryMeasurement> back = measurementFromJson(json);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_FALSE(back.value().frames[0].update_work.counted);
  EXPECT_FALSE(back.value().update_rebuilds.has_value());
}

}  // namespace
}  // namespace collido
