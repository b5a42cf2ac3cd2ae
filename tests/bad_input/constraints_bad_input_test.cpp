// Bad `constraints` blocks in scene files: each breaks one thing in a valid block and asserts a
// message naming the file, the JSON pointer of the culprit and the problem.
#include <collido/scene/scene.h>

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bad_input/rejection.h"
#include "support/test_paths.h"

namespace collido {
namespace {

using Json = nlohmann::json;
using test::rejected;

constexpr const char* kConstraintsLabel = "bad.json";

/// Two small spheres 3 apart; "b" is held on the x axis and 0.5 from "a".
Json validConstraintScene() {
  return Json::parse(R"({
    "objects": [
      {"name": "a", "shape": {"generator": "sphere", "radius": 1, "slices": 8, "stacks": 4}},
      {"name": "b", "shape": {"generator": "sphere", "radius": 1, "slices": 8, "stacks": 4},
       "pose": {"translation": [3, 0.1, 0]}}
    ],
    "constraints": {
      "fixed": ["a"],
      "variables": [{"name": "gap", "value": 0.5, "fixed": true}],
      "list": [
        {"name": "on axis", "type": "point_on_line", "p": {"object": "b", "at": [0, 0, 0]},
         "line": {"at": [0, 0, 0], "direction": [1, 0, 0]}},
        {"name": "gap held", "type": "clearance", "a": "a", "b": "b", "variable": "gap"}
      ]
    },
    "queries": [{"name": "q", "a": "a", "b": "b", "kind": "distance"}]
  })");
}

Result<Scene> parseConstrained(const Json& scene) {
  return parseScene(scene.dump(), kConstraintsLabel, test::sourcePath("scenes"));
}

TEST(ConstraintsBadInput, TheValidBlockSolves) {
  Result<Scene> scene = parseConstrained(validConstraintScene());
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  ASSERT_TRUE(scene.value().placement.has_value());
  EXPECT_EQ(scene.value().placement->moved, std::vector<std::size_t>{1});
}

// "bad.json: /constraints: unknown key 'lists' (allowed: ...)"
TEST(ConstraintsBadInput, UnknownKey) {
  Json scene = validConstraintScene();
  scene["constraints"]["lists"] = Json::array();
  EXPECT_TRUE(rejected(parseConstrained(scene),
                       {kConstraintsLabel, "/constraints:", "unknown key 'lists'"}));
}

// "bad.json: /constraints/list/1/type: unknown constraint type 'gap' (coincident, ...)"
TEST(ConstraintsBadInput, UnknownType) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"][1]["type"] = "gap";
  EXPECT_TRUE(
      rejected(parseConstrained(scene), {"/constraints/list/1/type", "unknown constraint type"}));
}

// "bad.json: /constraints/list/1/b: no object named 'c'"
TEST(ConstraintsBadInput, UnknownObject) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"][1]["b"] = "c";
  EXPECT_TRUE(rejected(parseConstrained(scene), {"/constraints/list/1/b", "no object named 'c'"}));
}

// "bad.json: /constraints/fixed/0: no object named 'z'"
TEST(ConstraintsBadInput, UnknownFixedObject) {
  Json scene = validConstraintScene();
  scene["constraints"]["fixed"][0] = "z";
  EXPECT_TRUE(rejected(parseConstrained(scene), {"/constraints/fixed/0", "no object named 'z'"}));
}

// "bad.json: /constraints/list/1: give exactly one of 'value' and 'variable'"
TEST(ConstraintsBadInput, ValueAndVariableBoth) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"][1]["value"] = 0.2;
  EXPECT_TRUE(
      rejected(parseConstrained(scene), {"/constraints/list/1:", "exactly one of 'value'"}));
}

// "bad.json: /constraints/list/1/variable: no variable named 'play' in /constraints/variables"
TEST(ConstraintsBadInput, UnknownVariable) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"][1]["variable"] = "play";
  EXPECT_TRUE(
      rejected(parseConstrained(scene), {"/constraints/list/1/variable", "no variable named"}));
}

// "bad.json: /constraints/list/1: constraint 'gap held': a clearance must be >= 0 (0 is contact)"
TEST(ConstraintsBadInput, NegativeClearance) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"][1].erase("variable");
  scene["constraints"]["list"][1]["value"] = -0.1;
  EXPECT_TRUE(rejected(parseConstrained(scene), {"/constraints/list/1:", "'gap held'", ">= 0"}));
}

// "bad.json: /constraints/list/0/line/direction: expected 3 numbers, got 2"
TEST(ConstraintsBadInput, ShortVector) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"][0]["line"]["direction"] = Json::array({1, 0});
  EXPECT_TRUE(
      rejected(parseConstrained(scene), {"/constraints/list/0/line/direction", "3 numbers"}));
}

// "bad.json: /constraints/list/0: constraint 'on axis': the second direction is a zero vector"
TEST(ConstraintsBadInput, ZeroDirection) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"][0]["line"]["direction"] = Json::array({0, 0, 0});
  EXPECT_TRUE(
      rejected(parseConstrained(scene), {"/constraints/list/0:", "'on axis'", "zero vector"}));
}

// "bad.json: /constraints/list/1: constraint 'on axis': the name is already used by a
//  constraint"
TEST(ConstraintsBadInput, DuplicateName) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"][1]["name"] = "on axis";
  EXPECT_TRUE(
      rejected(parseConstrained(scene), {"/constraints/list/1:", "'on axis'", "already used"}));
}

// "bad.json: /constraints/list/1: constraint 'gap': the name is already used by a variable"
TEST(ConstraintsBadInput, NameOfAVariable) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"][1]["name"] = "gap";
  EXPECT_TRUE(
      rejected(parseConstrained(scene), {"/constraints/list/1:", "'gap'", "used by a variable"}));
}

// "bad.json: /constraints/list: the constraints cannot be met: the constraints conflict: 'flat'
//  with 'on axis'"
TEST(ConstraintsBadInput, ConflictNamesTheConstraints) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"].push_back(Json::parse(R"(
    {"name": "off axis", "type": "point_on_plane", "p": {"object": "b", "at": [0, 0, 0]},
     "plane": {"at": [0, 1, 0], "normal": [0, 1, 0]}})"));
  EXPECT_TRUE(rejected(parseConstrained(scene),
                       {"/constraints/list:", "cannot be met", "'off axis'", "'on axis'"}));
}

// "bad.json: /constraints/list: the constraints cannot be met: 'gap held' has no gradient ..."
// (the spheres overlap by 0.5; 16 length scales of 0.01 do not part them)
TEST(ConstraintsBadInput, OverlapNothingNearbyPartsHasNoDirection) {
  Json scene = validConstraintScene();
  scene["objects"][1]["pose"]["translation"] = Json::array({1.5, 0.1, 0});
  scene["constraints"]["length_scale"] = 0.01;
  EXPECT_TRUE(rejected(parseConstrained(scene), {"/constraints/list:", "'gap held' has no gradient",
                                                 "already share a point"}));
}

// "bad.json: /constraints/list/0/p/object: the constraints would move object 'b', but its
//  motion is jitter about a base pose: list it under 'fixed', or ..."
TEST(ConstraintsBadInput, AMotionACorrectionCannotMoveIsRefused) {
  Json scene = validConstraintScene();
  scene["objects"][1]["motion"] = Json::parse(R"({"jitter": {"seed": 3, "translation": 0.1}})");
  EXPECT_TRUE(rejected(parseConstrained(scene),
                       {"/constraints/list/0/p/object", "would move object 'b'", "jitter"}));
}

// "bad.json: /constraints/list/1/a: the constraints would move object 'a', but another object's
//  random motion is placed relative to it: ..."
TEST(ConstraintsBadInput, AReferenceOfARandomMotionCannotMove) {
  Json scene = validConstraintScene();
  scene["constraints"]["fixed"] = Json::array();
  scene["objects"].push_back(Json::parse(R"(
    {"name": "c", "shape": {"generator": "sphere", "radius": 1, "slices": 8, "stacks": 4},
     "motion": {"random": {"seed": 1, "relative_to": "a", "overlap": 0.5}}})"));
  EXPECT_TRUE(rejected(parseConstrained(scene),
                       {"/constraints/list/1/a", "would move object 'a'", "relative to it"}));
}

// "bad.json: /constraints/list/0/p/object: the constraints would move object 'b', but another
//  object drapes onto it, ..."
TEST(ConstraintsBadInput, ADrapeTargetCannotMove) {
  Json scene = validConstraintScene();
  scene["objects"].push_back(Json::parse(R"(
    {"name": "sheet", "shape": {"generator": "grid_sheet", "cells_x": 2, "cells_y": 2},
     "pose": {"translation": [3, 0, 3]},
     "deform": {"rules": [{"drape": {"onto": "b", "direction": [0, 0, -1], "drop": 3}}]}})"));
  EXPECT_TRUE(rejected(parseConstrained(scene), {"/constraints/list/0/p/object",
                                                 "would move object 'b'", "drapes onto it"}));
}

// "bad.json: /constraints: 'constraints' is not allowed beside 'stress', ..."
TEST(ConstraintsBadInput, NotBesideAStressBlock) {
  const Json scene = Json::parse(R"({"stress": {"category": "touching"}, "constraints": {}})");
  EXPECT_TRUE(rejected(parseConstrained(scene), {"/constraints:", "not allowed beside 'stress'"}));
}

// "bad.json: /constraints/list: the list holds no constraint"
TEST(ConstraintsBadInput, EmptyList) {
  Json scene = validConstraintScene();
  scene["constraints"]["list"] = Json::array();
  EXPECT_TRUE(rejected(parseConstrained(scene), {"/constraints/list:", "no constraint"}));
}

// "bad.json: /constraints/variables/0/scale: scale must be > 0"
TEST(ConstraintsBadInput, VariableScaleNotPositive) {
  Json scene = validConstraintScene();
  scene["constraints"]["variables"][0]["scale"] = 0;
  EXPECT_TRUE(rejected(parseConstrained(scene), {"/constraints/variables/0/scale", "> 0"}));
}

}  // namespace
}  // namespace collido
