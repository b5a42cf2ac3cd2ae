// The scene writers' pose (io::scenePoseJson) read back by the scene loader to the same bits:
// turned poses with their rotation matrix, unturned ones as their translation alone.
// (Collidoscope::record's own writer is held to the same in recorded_scene_test.cpp.)
#include <collido/io/scene_pose.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/scene/scene.h>

#include "support/test_paths.h"

namespace collido {
namespace {

TEST(ScenePose, WrittenPosesReadBackBitForBit) {
  const Pose turned = Eigen::Translation3d(0.1, -1e-7, 12345.678) *
                      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  const Pose unturned(Eigen::Translation3d(1.0 / 3.0, 2.0, -0.25));
  const nlohmann::json unturned_json = io::scenePoseJson(unturned);
  EXPECT_FALSE(unturned_json.contains("rotation")) << unturned_json.dump();
  EXPECT_TRUE(io::scenePoseJson(turned).contains("rotation"));

  const std::string dir = test::makeTempDirectory("scene_pose");
  const nlohmann::json cube = {{"generator", "box"}};
  const nlohmann::json scene = {
      {"name", "poses"},
      {"frames", 2},
      {"objects",
       {{{"name", "a"}, {"shape", cube}, {"pose", io::scenePoseJson(turned)}},
        {{"name", "b"},
         {"shape", cube},
         {"motion",
          {{"poses", {io::scenePoseJson(unturned), io::scenePoseJson(turned.inverse())}}}}}}},
      {"queries", {{{"a", "a"}, {"b", "b"}, {"kind", "boolean"}}}}};
  test::writeFile(dir + "/poses.json", scene.dump(1));
  const Result<Scene> loaded = loadScene(dir + "/poses.json");
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  EXPECT_EQ(loaded.value().objects[0].poseAt(1).matrix(), turned.matrix());
  EXPECT_EQ(loaded.value().objects[1].poseAt(0).matrix(), unturned.matrix());
  EXPECT_EQ(loaded.value().objects[1].poseAt(1).matrix(), turned.inverse().matrix());
}

}  // namespace
}  // namespace collido
