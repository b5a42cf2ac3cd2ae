// A loaded scene lists every file it was read from, which a study fingerprints to notice that
// an input changed between a study's start and its resume.
#include <collido/mesh/input_file.h>
#include <collido/scene/scene.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace collido {
namespace {

TEST(SceneInputFiles, TheSceneFileThenEachMeshOnce) {
  const std::string dir = test::makeTempDirectory("scene_inputs");
  test::writeFile(dir + "/tet.obj",
                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n"
                  "f 1 4 3\nf 2 3 4\n");
  test::writeFile(dir + "/s.json", R"({"name": "s", "frames": 1, "objects": [
      {"name": "a", "shape": {"mesh": "tet.obj"}},
      {"name": "b", "shape": {"mesh": "tet.obj"}, "pose": {"translation": [0.5, 0, 0]}},
      {"name": "c", "shape": {"generator": "sphere"}}],
      "queries": [{"name": "q", "a": "a", "b": "b", "kind": "boolean"}]})");
  const Result<Scene> scene = loadScene(dir + "/s.json");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_EQ(scene.value().input_files.size(), 2u);
  EXPECT_EQ(scene.value().input_files[0], dir + "/s.json");
  EXPECT_NE(scene.value().input_files[1].find("tet.obj"), std::string::npos);
}

TEST(SceneInputFiles, ANestedRecorderPassesItsFilesOn) {
  const std::string dir = test::makeTempDirectory("scene_inputs");
  test::writeFile(dir + "/a.txt", "a");
  test::writeFile(dir + "/b.txt", "b");
  const InputFileRecorder outer;
  ASSERT_TRUE(checkInputFile(dir + "/a.txt", "file").ok());
  {
    const InputFileRecorder inner;
    ASSERT_TRUE(checkInputFile(dir + "/b.txt", "file").ok());
    ASSERT_TRUE(checkInputFile(dir + "/a.txt", "file").ok());
    EXPECT_EQ(inner.files(), (std::vector<std::string>{dir + "/b.txt", dir + "/a.txt"}));
  }
  EXPECT_EQ(outer.files(), (std::vector<std::string>{dir + "/a.txt", dir + "/b.txt"}));
}

}  // namespace
}  // namespace collido
