// The floor of an all-pairs query: world triangles of the true pairs, and the floor ratio.
#include <collido/runner/floor.h>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/mesh/procedural.h>
#include <collido/runner/measurement_json.h>
#include <collido/runner/runner.h>

namespace collido {
namespace {

TEST(Floor, WorldPairsArePlacedByTheirPoses) {
  TriangleMesh mesh;
  mesh.vertices.resize(3, 3);
  mesh.vertices << 0, 1, 0,  //
      0, 0, 1,               //
      0, 0, 0;
  mesh.triangles.resize(3, 1);
  mesh.triangles << 0, 1, 2;
  const Pose pose_a = Pose(Eigen::Translation3d(1, 2, 3));
  const Pose pose_b = Pose(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  std::vector<WorldTrianglePair> out;
  appendWorldPairs(mesh, pose_a, mesh, pose_b, {TrianglePair{0, 0}}, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].first[1].isApprox(Eigen::Vector3d(2, 2, 3)));
  EXPECT_TRUE(out[0].second[1].isApprox(Eigen::Vector3d(0, 1, 0)));
}

TEST(Floor, NoPairsCostNothingAndPairsCostTime) {
  EXPECT_EQ(floorMicroseconds({}, 5), 0.0);
  const Result<TriangleMesh> made = makeTorus(TorusParams{});
  ASSERT_TRUE(made.ok());
  const TriangleMesh& torus = made.value();
  std::vector<TrianglePair> all;
  all.reserve(torus.triangleCount());
  for (std::int32_t t = 0; t < static_cast<std::int32_t>(torus.triangleCount()); ++t)
    all.push_back(TrianglePair{t, t});
  std::vector<WorldTrianglePair> pairs;
  appendWorldPairs(torus, Pose::Identity(), torus, Pose::Identity(), all, pairs);
  EXPECT_GT(floorMicroseconds(pairs, 3), 0.0);
}

TEST(Floor, RatioIsTimeOverFloorOnFramesWithAFloorAndSurvivesJson) {
  QueryMeasurement m;
  m.backend = "b";
  m.scene = "s";
  m.query = "all_pairs";
  m.kind = QueryKind::kAllPairs;
  for (int i = 0; i < 3; ++i) {
    FrameRecord f;
    f.frame = static_cast<std::size_t>(i);
    f.median_us = 10.0 * (i + 1);
    if (i < 2) f.floor_us = 2.0 * (i + 1);  // the third frame has none: left out
    m.frames.push_back(f);
    m.times_us.push_back(f.median_us);
  }
  summariseMeasurement(m);
  ASSERT_TRUE(m.floor_ratio.has_value());
  EXPECT_DOUBLE_EQ(*m.floor_ratio, (10.0 + 20.0) / (2.0 + 4.0));

  const Result<QueryMeasurement> back = measurementFromJson(measurementToJson(m));
  ASSERT_TRUE(back.ok()) << back.status().message();
  ASSERT_EQ(back.value().frames.size(), 3u);
  EXPECT_EQ(back.value().frames[1].floor_us, 4.0);
  EXPECT_FALSE(back.value().frames[2].floor_us.has_value());
  EXPECT_EQ(back.value().floor_ratio, m.floor_ratio);
}

TEST(Floor, NoRatioWithoutAFloor) {
  QueryMeasurement m;
  m.kind = QueryKind::kBoolean;
  FrameRecord f;
  f.median_us = 3.0;
  m.frames.push_back(f);
  summariseMeasurement(m);
  EXPECT_FALSE(m.floor_ratio.has_value());
}

}  // namespace
}  // namespace collido
