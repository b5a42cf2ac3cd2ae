// Bad deformable objects in scene files: states, schedules, movable-node rules and recordings.
// Each breaks one thing in a valid scene and expects a message naming the file, the JSON
// pointer and the problem.
#include <collido/scene/scene.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bad_input/rejection.h"
#include "support/test_paths.h"

namespace collido {
namespace {

using Json = nlohmann::json;
using test::rejected;

constexpr const char* kDeformingLabel = "bad.json";

/// A valid three-frame scene: "a" a sphere that pulsates, "b" with two states, one query.
Json validDeformingScene() {
  return Json::parse(R"({
    "frames": 3,
    "objects": [
      {"name": "a", "shape": {"generator": "sphere", "radius": 1, "slices": 8, "stacks": 4},
       "deform": {"rules": [{"pulsate": {"amplitude": 0.1}}]}},
      {"name": "b",
       "states": [{"generator": "sphere", "radius": 1, "slices": 8, "stacks": 4},
                  {"generator": "sphere", "radius": 0.5, "slices": 8, "stacks": 4}],
       "schedule": [0, 1, 0],
       "pose": {"translation": [3, 0, 0]}}
    ],
    "queries": [{"name": "q", "a": "a", "b": "b", "kind": "all_pairs"}]
  })");
}

Result<Scene> parseDeforming(const Json& scene, const std::string& base = ".") {
  return parseScene(scene.dump(), kDeformingLabel, base);
}

TEST(DeformationBadInput, TheValidSceneLoads) {
  const Result<Scene> scene = parseDeforming(validDeformingScene());
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_TRUE(scene.value().objects[0].deformation != nullptr);
  EXPECT_EQ(scene.value().objects[1].states.size(), 2u);
}

TEST(DeformationBadInput, ShapeAndStatesTogether) {
  Json scene = validDeformingScene();
  scene["objects"][1]["shape"] = scene["objects"][0]["shape"];
  EXPECT_TRUE(rejected(parseDeforming(scene), {"/objects/1:", "only one of 'shape' or 'states'"}));
}

TEST(DeformationBadInput, ScheduleWithoutStates) {
  Json scene = validDeformingScene();
  scene["objects"][0]["schedule"] = Json::array({0, 0, 0});
  EXPECT_TRUE(rejected(parseDeforming(scene), {"/objects/0/schedule:", "needs 'states'"}));
}

TEST(DeformationBadInput, ScheduleOfTheWrongLength) {
  Json scene = validDeformingScene();
  scene["objects"][1]["schedule"] = Json::array({0, 1});
  EXPECT_TRUE(rejected(parseDeforming(scene), {"/objects/1/schedule:", "2 entries", "3 frames"}));
}

TEST(DeformationBadInput, ScheduleNamesAStateThatDoesNotExist) {
  Json scene = validDeformingScene();
  scene["objects"][1]["schedule"] = Json::array({0, 2, 0});
  EXPECT_TRUE(rejected(parseDeforming(scene), {"/objects/1/schedule/1:", "[0, 1]", "got 2"}));
}

TEST(DeformationBadInput, NoStates) {
  Json scene = validDeformingScene();
  scene["objects"][1]["states"] = Json::array();
  EXPECT_TRUE(rejected(parseDeforming(scene), {"/objects/1/states:", "at least one"}));
}

TEST(DeformationBadInput, UnknownRule) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"]["rules"][0] = {{"melt", {{"amplitude", 1}}}};
  EXPECT_TRUE(
      rejected(parseDeforming(scene), {"/objects/0/deform/rules/0:", "unknown rule 'melt'"}));
}

TEST(DeformationBadInput, UnknownKeyInARule) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"]["rules"][0]["pulsate"]["amplitud"] = 1;
  EXPECT_TRUE(rejected(parseDeforming(scene),
                       {"/objects/0/deform/rules/0/pulsate:", "unknown key 'amplitud'"}));
}

TEST(DeformationBadInput, RampAndPeriodTogether) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"]["rules"][0]["pulsate"]["ramp"] = true;
  scene["objects"][0]["deform"]["rules"][0]["pulsate"]["period"] = 4;
  EXPECT_TRUE(rejected(parseDeforming(scene), {"/objects/0/deform/rules/0/pulsate:", "exclude"}));
}

TEST(DeformationBadInput, NonPositivePeriod) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"]["rules"][0]["pulsate"]["period"] = 0;
  EXPECT_TRUE(
      rejected(parseDeforming(scene), {"/objects/0/deform/rules/0/pulsate/period:", "> 0"}));
}

TEST(DeformationBadInput, SquashOfTheWholeHeight) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"]["rules"][0] = {{"squash", {{"amount", 1.0}}}};
  EXPECT_TRUE(
      rejected(parseDeforming(scene), {"/objects/0/deform/rules/0/squash/amount:", "[0, 1)"}));
}

TEST(DeformationBadInput, BendTowardsItsOwnAxis) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"]["rules"][0] = {
      {"bend", {{"angle_deg", 30}, {"axis", {0, 0, 1}}, {"direction", {0, 0, 2}}}}};
  EXPECT_TRUE(
      rejected(parseDeforming(scene), {"/objects/0/deform/rules/0/bend/direction:", "axis"}));
}

TEST(DeformationBadInput, ZeroAxis) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"]["rules"][0] = {{"twist", {{"axis", {0, 0, 0}}}}};
  EXPECT_TRUE(
      rejected(parseDeforming(scene), {"/objects/0/deform/rules/0/twist/axis:", "zero vector"}));
}

TEST(DeformationBadInput, NothingToDo) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"] = Json::object();
  EXPECT_TRUE(
      rejected(parseDeforming(scene), {"/objects/0/deform:", "'rules' or a 'recorded' file"}));
}

TEST(DeformationBadInput, DeformationBeyondTheCoordinateLimit) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"]["rules"][0]["pulsate"]["amplitude"] = 1e300;
  EXPECT_TRUE(rejected(parseDeforming(scene), {"/objects/0/deform:", "frame", "coordinate limit"}));
}

TEST(DeformationBadInput, DrapeOntoAnObjectDefinedLater) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"]["rules"][0] = {{"drape", {{"onto", "b"}, {"drop", 1}}}};
  EXPECT_TRUE(rejected(parseDeforming(scene), {"/objects/0/deform/rules/0/drape/onto:",
                                               "'b' is not an object defined before this one"}));
}

TEST(DeformationBadInput, DrapeOfAnObjectWithStates) {
  Json scene = validDeformingScene();
  scene["objects"][1]["deform"] = {{"rules", {{{"drape", {{"onto", "a"}, {"drop", 1}}}}}}};
  EXPECT_TRUE(rejected(parseDeforming(scene), {"/objects/1/deform/rules/0/drape:", "one shape"}));
}

TEST(DeformationBadInput, DrapeWithNegativePenetration) {
  Json scene = validDeformingScene();
  scene["objects"][1].erase("states");
  scene["objects"][1].erase("schedule");
  scene["objects"][1]["shape"] = scene["objects"][0]["shape"];
  scene["objects"][1]["deform"] = {
      {"rules", {{{"drape", {{"onto", "a"}, {"drop", 1}, {"penetration", -0.1}}}}}}};
  EXPECT_TRUE(
      rejected(parseDeforming(scene), {"/objects/1/deform/rules/0/drape/penetration:", ">= 0"}));
}

TEST(DeformationBadInput, MissingRecording) {
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"] = {{"recorded", "no_such.pos"}};
  EXPECT_TRUE(rejected(parseDeforming(scene), {"/objects/0/deform/recorded:", "no_such.pos"}));
}

TEST(DeformationBadInput, RecordingOfAnotherMesh) {
  const std::string folder = test::makeTempDirectory("recording");
  RecordedPositions recording;
  recording.vertices = 5;
  recording.frames = 3;
  recording.values.assign(45, 0.0);
  ASSERT_TRUE(writeRecordedPositions(folder + "/five.pos", recording).ok());
  Json scene = validDeformingScene();
  scene["objects"][0]["deform"] = {{"recorded", "five.pos"}};
  EXPECT_TRUE(rejected(parseDeforming(scene, folder),
                       {"/objects/0/deform/recorded:", "records 5 vertices", "state 0 has"}));
  recording.frames = 2;
  recording.values.assign(30, 0.0);
  ASSERT_TRUE(writeRecordedPositions(folder + "/five.pos", recording).ok());
  EXPECT_TRUE(rejected(parseDeforming(scene, folder),
                       {"/objects/0/deform/recorded:", "records 2 frames", "3"}));
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace collido
