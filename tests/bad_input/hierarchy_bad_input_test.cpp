// Bad hierarchies, keyframes, joints and subtree queries, one test per case: each breaks one
// thing in a valid scene and expects kInvalidArgument naming the file, the JSON path and the
// problem (the comment above each test shows the message).
#include <collido/scene/scene.h>

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bad_input/rejection.h"

namespace collido {
namespace {

using Json = nlohmann::json;
using test::rejected;

/// A module with a truss on it and a panel on the truss, and a second module: valid.
Json validHierarchyScene() {
  return Json::parse(R"({
    "frames": 3,
    "objects": [
      {"name": "module", "shape": {"generator": "box", "size": [2, 1, 1]}},
      {"name": "truss", "parent": "module", "shape": {"generator": "box", "size": [0.2, 3, 0.2]},
       "pose": {"translation": [0, 2, 0]}},
      {"name": "panel", "parent": "truss", "shape": {"generator": "box", "size": [1, 1, 0.05]},
       "pose": {"translation": [0, 1, 0]},
       "motion": {"joint": {"axis": [0, 1, 0], "keys": [{"frame": 0, "degrees": 0}, {"frame": 2, "degrees": 90}]}}},
      {"name": "other", "shape": {"generator": "box"},
       "motion": {"keyframes": [{"frame": 0, "pose": {"translation": [5, 0, 0]}},
                                {"frame": 2, "pose": {"translation": [1, 0, 0]}}]}}
    ],
    "queries": [{"name": "q", "a": {"subtree": "module"}, "b": "other", "kind": "all_pairs"}]
  })");
}

Result<Scene> parseHierarchy(const Json& scene) {
  return parseScene(scene.dump(), "bad.json", ".");
}

TEST(HierarchyBadInput, TheValidSceneLoads) {
  const Result<Scene> scene = parseHierarchy(validHierarchyScene());
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  EXPECT_EQ(scene.value().queries[0].among.size(), 4u);
}

// "bad.json: /objects/1/parent: no object named 'modul'"
TEST(HierarchyBadInput, UnknownParent) {
  Json scene = validHierarchyScene();
  scene["objects"][1]["parent"] = "modul";
  EXPECT_TRUE(rejected(parseHierarchy(scene),
                       {"bad.json", "/objects/1/parent:", "no object named 'modul'"}));
}

// "bad.json: /objects/0/parent: expected a string, got number"
TEST(HierarchyBadInput, ParentNotAString) {
  Json scene = validHierarchyScene();
  scene["objects"][0]["parent"] = 3;
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/objects/0/parent:", "string"}));
}

// "bad.json: /objects/2/parent: an object cannot be its own parent"
TEST(HierarchyBadInput, OwnParent) {
  Json scene = validHierarchyScene();
  scene["objects"][2]["parent"] = "panel";
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/objects/2/parent:", "its own parent"}));
}

// "bad.json: /objects/0/parent: the parents form a cycle: 'module' -> 'panel' -> 'truss' ->
//  'module'"
TEST(HierarchyBadInput, CycleOfParents) {
  Json scene = validHierarchyScene();
  scene["objects"][0]["parent"] = "panel";
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/objects/0/parent:", "cycle",
                                               "'module' -> 'panel' -> 'truss' -> 'module'"}));
}

// A cycle among children hangs off a valid root; it is still found and listed.
// "bad.json: /objects/1/parent: the parents form a cycle: 'truss' -> 'panel' -> 'truss'"
TEST(HierarchyBadInput, CycleBelowARoot) {
  Json scene = validHierarchyScene();
  scene["objects"][1]["parent"] = "panel";
  EXPECT_TRUE(rejected(parseHierarchy(scene),
                       {"/objects/1/parent:", "cycle", "'truss' -> 'panel' -> 'truss'"}));
}

// "bad.json: /objects/3/name: duplicate object name 'truss'"
TEST(HierarchyBadInput, DuplicateNameInAHierarchy) {
  Json scene = validHierarchyScene();
  scene["objects"][3]["name"] = "truss";
  EXPECT_TRUE(
      rejected(parseHierarchy(scene), {"/objects/3/name:", "duplicate object name 'truss'"}));
}

// "bad.json: /objects/1/motion/random/relative_to: 'panel' is not defined before this one
//  (objects are read in file order, each parent before its children)": a random placement
//  against the object's own child, which is placed through it.
TEST(HierarchyBadInput, RandomMotionAgainstItsOwnChild) {
  Json scene = validHierarchyScene();
  scene["objects"][1]["motion"] = {{"random", {{"relative_to", "panel"}, {"overlap", 0.5}}}};
  scene["objects"][1].erase("pose");
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/objects/1/motion/random/relative_to:",
                                               "'panel' is not defined before this one"}));
}

// "bad.json: /objects/1/parent: frame 0: composed with its parent 'module', the translation
//  (2e+18, 2, 0) is beyond the coordinate limit |t| <= 1e+18 (scenes/README.md)"
TEST(HierarchyBadInput, CompositionPastTheCoordinateLimit) {
  Json scene = validHierarchyScene();
  scene["objects"][0]["pose"] = {{"translation", {1e18, 0, 0}}};
  scene["objects"][1]["pose"] = {{"translation", {1e18, 0, 0}}};
  EXPECT_TRUE(
      rejected(parseHierarchy(scene),
               {"/objects/1/parent:", "composed with its parent 'module'", "coordinate limit"}));
}

// "bad.json: /objects/3/motion/keyframes/1/frame: frame 0 does not come after the previous key's
//  frame 0 (keys go in increasing frames)"
TEST(HierarchyBadInput, KeyframesOutOfOrder) {
  Json scene = validHierarchyScene();
  scene["objects"][3]["motion"]["keyframes"][1]["frame"] = 0;
  EXPECT_TRUE(rejected(parseHierarchy(scene),
                       {"/objects/3/motion/keyframes/1/frame:", "increasing frames"}));
}

// "bad.json: /objects/3/motion/keyframes/1/frame: expected an integer in [0, 2], got 3"
TEST(HierarchyBadInput, KeyframePastTheLastFrame) {
  Json scene = validHierarchyScene();
  scene["objects"][3]["motion"]["keyframes"][1]["frame"] = 3;
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/objects/3/motion/keyframes/1/frame:", "[0, 2]"}));
}

// "bad.json: /objects/3/motion/keyframes: give at least one keyframe"
TEST(HierarchyBadInput, NoKeyframes) {
  Json scene = validHierarchyScene();
  scene["objects"][3]["motion"]["keyframes"] = Json::array();
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/objects/3/motion/keyframes:", "at least one"}));
}

// "bad.json: /objects/3/motion/keyframes/0: missing 'pose'"
TEST(HierarchyBadInput, KeyframeWithoutPose) {
  Json scene = validHierarchyScene();
  scene["objects"][3]["motion"]["keyframes"][0].erase("pose");
  EXPECT_TRUE(
      rejected(parseHierarchy(scene), {"/objects/3/motion/keyframes/0:", "missing 'pose'"}));
}

// "bad.json: /objects/3/pose: 'pose' and motion 'keyframes' exclude each other"
TEST(HierarchyBadInput, KeyframesBesideAPose) {
  Json scene = validHierarchyScene();
  scene["objects"][3]["pose"] = Json::object();
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/objects/3/pose:", "exclude each other"}));
}

// "bad.json: /objects/2/motion/joint/axis: the axis must be a finite non-zero vector"
TEST(HierarchyBadInput, JointWithAZeroAxis) {
  Json scene = validHierarchyScene();
  scene["objects"][2]["motion"]["joint"]["axis"] = {0, 0, 0};
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/objects/2/motion/joint/axis:", "non-zero"}));
}

// "bad.json: /objects/2/motion/joint: missing 'keys' ([{frame, degrees}, ...])"
TEST(HierarchyBadInput, JointWithoutKeys) {
  Json scene = validHierarchyScene();
  scene["objects"][2]["motion"]["joint"].erase("keys");
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/objects/2/motion/joint:", "missing 'keys'"}));
}

// "bad.json: /objects/2/motion/joint/keys/1: missing 'degrees'"
TEST(HierarchyBadInput, JointKeyWithoutDegrees) {
  Json scene = validHierarchyScene();
  scene["objects"][2]["motion"]["joint"]["keys"][1].erase("degrees");
  EXPECT_TRUE(
      rejected(parseHierarchy(scene), {"/objects/2/motion/joint/keys/1:", "missing 'degrees'"}));
}

// "bad.json: /queries/0/a/subtree: no object named 'nothing'"
TEST(HierarchyBadInput, SubtreeOfAnUnknownObject) {
  Json scene = validHierarchyScene();
  scene["queries"][0]["a"] = {{"subtree", "nothing"}};
  EXPECT_TRUE(
      rejected(parseHierarchy(scene), {"/queries/0/a/subtree:", "no object named 'nothing'"}));
}

// "bad.json: /queries/0/a: unknown key 'subtre' (allowed: subtree)"
TEST(HierarchyBadInput, SubtreeKeyMisspelt) {
  Json scene = validHierarchyScene();
  scene["queries"][0]["a"] = {{"subtre", "module"}};
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/queries/0/a:", "subtre"}));
}

// "bad.json: /queries/0/b: object 'truss' is on both sides: 'a' and 'b' must not share objects"
TEST(HierarchyBadInput, SubtreesThatOverlap) {
  Json scene = validHierarchyScene();
  scene["queries"][0]["b"] = {{"subtree", "truss"}};
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/queries/0/b:", "'truss' is on both sides"}));
}

// "bad.json: /queries/0/kind: a group query ('among', or a subtree of more than one object) asks
//  all_pairs or contacts only, not boolean"
TEST(HierarchyBadInput, BooleanSubtreeQuery) {
  Json scene = validHierarchyScene();
  scene["queries"][0]["kind"] = "boolean";
  EXPECT_TRUE(rejected(parseHierarchy(scene),
                       {"/queries/0/kind:", "subtree", "all_pairs or contacts only"}));
}

// "bad.json: /queries/0/among/1: object 'truss' named twice"
TEST(HierarchyBadInput, AmongNamesAnObjectTwiceThroughASubtree) {
  Json scene = validHierarchyScene();
  scene["queries"][0].erase("a");
  scene["queries"][0].erase("b");
  scene["queries"][0]["among"] = {{{"subtree", "module"}}, "truss"};
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"/queries/0/among/1:", "'truss' named twice"}));
}

// "bad.json: /constraints/list/0: the constraints would move object 'module', but objects are
//  mounted on it, which would have to move with it: list it under 'fixed' (...)"
TEST(HierarchyBadInput, ConstraintsMovingAParent) {
  Json scene = validHierarchyScene();
  scene["constraints"] = Json::parse(R"({"fixed": ["other"], "list": [
    {"type": "point_on_line", "p": {"object": "module", "at": [0, 0, 0]},
     "line": {"at": [0, 0, 0], "direction": [1, 0, 0]}}]})");
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"'module'", "mounted on it", "under 'fixed'"}));
}

// "... the constraints would move object 'panel', but it is mounted on a parent ..."
TEST(HierarchyBadInput, ConstraintsMovingAChild) {
  Json scene = validHierarchyScene();
  scene["constraints"] = Json::parse(R"({"fixed": ["other"], "list": [
    {"type": "point_on_line", "p": {"object": "panel", "at": [0, 0, 0]},
     "line": {"at": [0, 0, 0], "direction": [1, 0, 0]}}]})");
  EXPECT_TRUE(rejected(parseHierarchy(scene), {"'panel'", "mounted on a parent"}));
}

}  // namespace
}  // namespace collido
