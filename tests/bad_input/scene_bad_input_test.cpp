// Bad scene files, one test per case. Each starts from a valid scene (checked on its own below),
// breaks one thing, and asserts kInvalidArgument with a message that names the file, the JSON
// pointer of the culprit and the problem. The comment above each test shows the message.
#include <collido/scene/scene.h>

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bad_input/rejection.h"
#include "support/test_paths.h"

namespace collido {
namespace {

using Json = nlohmann::json;
using test::rejected;

constexpr const char* kLabel = "bad.json";

/// A valid two-frame scene: a small sphere "a" at the origin, a small torus "b" at x = 3, and
/// one boolean query "q" between them.
Json validScene() {
  return Json::parse(R"({
    "name": "valid",
    "frames": 2,
    "objects": [
      {"name": "a", "shape": {"generator": "sphere", "radius": 1, "slices": 8, "stacks": 4}},
      {"name": "b",
       "shape": {"generator": "torus", "major_radius": 1, "minor_radius": 0.25,
                 "major_segments": 8, "minor_segments": 4},
       "pose": {"translation": [3, 0, 0]}}
    ],
    "queries": [{"name": "q", "a": "a", "b": "b", "kind": "boolean"}]
  })");
}

Result<Scene> parse(const Json& scene) {
  return parseScene(scene.dump(), kLabel, test::sourcePath("scenes"));
}

Json rotation(const Json& rows) {
  return Json{{"matrix", rows}};
}

TEST(SceneBadInput, TheValidSceneLoads) {
  Result<Scene> scene = parse(validScene());
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  EXPECT_EQ(scene.value().objects.size(), 2u);
  EXPECT_EQ(scene.value().queries.size(), 1u);
  EXPECT_EQ(scene.value().frames, 2u);
}

// ---- the document ----------------------------------------------------------------------------

// "bad.json: not valid JSON (byte 14): [json.exception.parse_error.101] parse error at line 1,
//  column 14: syntax error while parsing value - unexpected end of input; ..."
TEST(SceneBadInput, NotJson) {
  EXPECT_TRUE(
      rejected(parseScene(R"({"objects": [)", kLabel, "."), {kLabel, "not valid JSON", "byte 14"}));
}

// "bad.json: /: expected an object, got array"
TEST(SceneBadInput, RootNotAnObject) {
  EXPECT_TRUE(rejected(parseScene("[1, 2]", kLabel, "."), {kLabel, ": /:", "expected an object"}));
}

// "<dir>/absent.json: file not found"
TEST(SceneBadInput, SceneFileMissing) {
  const std::string path = test::makeTempDirectory("bad_scene") + "/absent.json";
  EXPECT_TRUE(rejected(loadScene(path), {path, "not found"}));
}

// A file on disk is named by its path in every message.
TEST(SceneBadInput, SceneFileWithSyntaxErrorNamesTheFile) {
  const std::string path = test::makeTempDirectory("bad_scene") + "/broken.json";
  test::writeFile(path, "{\"frames\": 1,,}");
  EXPECT_TRUE(rejected(loadScene(path), {path, "not valid JSON", "byte 14"}));
}

// JSON parsers keep one of two equal keys; a scene must not silently drop the other:
// "bad.json: /frames: duplicate key 'frames' (only one of them would count)"
TEST(SceneBadInput, DuplicateTopLevelKey) {
  Json scene = validScene();
  scene.erase("frames");
  std::string text = scene.dump();
  text.insert(1, R"("frames": 1, "frames": 2, )");
  EXPECT_TRUE(
      rejected(parseScene(text, kLabel, "."), {kLabel, "/frames:", "duplicate key 'frames'"}));
}

// The path of a nested repeat counts array elements, including earlier scalars and containers:
// "bad.json: /objects/1/pose/translation: duplicate key 'translation' (only one of them would
//  count)"
TEST(SceneBadInput, DuplicateNestedKey) {
  const std::string text = R"({"frames": 1, "objects": [
      {"name": "a", "shape": {"generator": "sphere", "comment": [1, [2], {"x": 3}]}},
      {"name": "b", "shape": {"generator": "sphere"},
       "pose": {"translation": [3, 0, 0], "translation": [0, 0, 0]}}],
    "queries": [{"a": "a", "b": "b", "kind": "boolean"}]})";
  EXPECT_TRUE(rejected(parseScene(text, kLabel, "."),
                       {kLabel, ": /objects/1/pose/translation:", "duplicate key 'translation'"}));
}

// Equal keys in different objects are no repeat.
TEST(SceneBadInput, EqualKeysInDifferentObjectsAreFine) {
  const std::string text = R"({"objects": [
      {"name": "a", "shape": {"generator": "sphere"}},
      {"name": "b", "shape": {"generator": "sphere"}, "pose": {"translation": [3, 0, 0]}}],
    "queries": [{"name": "a", "a": "a", "b": "b", "kind": "boolean"}]})";
  Result<Scene> scene = parseScene(text, kLabel, ".");
  EXPECT_TRUE(scene.ok()) << scene.status().toString();
}

// ---- unknown keys ----------------------------------------------------------------------------

// "bad.json: /: unknown key 'object' (allowed: constraints, description, frames, name, objects,
//  queries, stress)"
TEST(SceneBadInput, UnknownTopLevelKey) {
  Json scene = validScene();
  scene["object"] = Json::array();
  EXPECT_TRUE(rejected(parse(scene),
                       {kLabel, ": /:", "unknown key 'object'",
                        "allowed: constraints, description, frames, name, objects, queries"}));
}

// "bad.json: /objects/0: unknown key 'shpe' (allowed: deform, frames, markers, motion, name,
// parent, pose,
//  schedule, shape, states)"
TEST(SceneBadInput, UnknownKeyInObject) {
  Json scene = validScene();
  scene["objects"][0]["shpe"] = 1;
  EXPECT_TRUE(
      rejected(parse(scene),
               {"/objects/0:", "unknown key 'shpe'",
                "allowed: deform, frames, markers, motion, name, parent, pose, schedule, shape, "
                "states"}));
}

// "bad.json: /objects/1/shape: unknown key 'minor_raduis' (allowed: generator, major_radius,
//  major_segments, minor_radius, minor_segments)"
TEST(SceneBadInput, UnknownKeyInShape) {
  Json scene = validScene();
  scene["objects"][1]["shape"]["minor_raduis"] = 0.5;
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/shape:", "unknown key 'minor_raduis'",
                                      "allowed: generator, major_radius, major_segments, "
                                      "minor_radius, minor_segments"}));
}

// "bad.json: /objects/1/pose: unknown key 'translate' (allowed: rotation, translation)"
TEST(SceneBadInput, UnknownKeyInPose) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["translate"] = Json::array({1, 2, 3});
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/pose:", "unknown key 'translate'",
                                      "allowed: rotation, translation"}));
}

// "bad.json: /objects/1/pose/rotation: unknown key 'angle' (allowed: axis, degrees, matrix,
//  quaternion)"
TEST(SceneBadInput, UnknownKeyInRotation) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["rotation"] = {{"axis", {0, 0, 1}}, {"angle", 90}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/pose/rotation:", "unknown key 'angle'",
                                      "allowed: axis, degrees, matrix, quaternion"}));
}

// "bad.json: /queries/0: unknown key 'max_pair' (allowed: a, abs_tolerance, among, b,
//  bracket_width, except, frames, kind, max_contacts, max_pairs, name, rel_tolerance)"
TEST(SceneBadInput, UnknownKeyInQuery) {
  Json scene = validScene();
  scene["queries"][0]["max_pair"] = 3;
  EXPECT_TRUE(
      rejected(parse(scene), {"/queries/0:", "unknown key 'max_pair'",
                              "allowed: a, abs_tolerance, among, b, bracket_width, except, "
                              "frames, kind, max_contacts, max_pairs, name, rel_tolerance"}));
}

// "bad.json: /queries/0/frames/1: ranges must be ascending and apart: this one starts at frame 1,
//  the one before ends at 0"
TEST(SceneBadInput, FrameRangesThatTouch) {
  Json scene = validScene();
  scene["queries"][0]["frames"] = Json::parse("[[0, 0], [1, 1]]");
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/frames/1:", "ascending and apart"}));
}

// "bad.json: /queries/0/frames: query 'q' is asked in frame 0, but object 'b' does not exist in
//  frame 0"
TEST(SceneBadInput, QueryAskedWhereItsObjectDoesNotExist) {
  Json scene = validScene();
  scene["objects"][1]["frames"] = Json::parse("[[1, 1]]");
  scene["queries"][0]["frames"] = Json::parse("[[0, 1]]");
  EXPECT_TRUE(rejected(parse(scene),
                       {"/queries/0/frames:", "asked in frame 0", "object 'b' does not exist"}));
}

// A first-contact query asks about the step from each frame to the next.
TEST(SceneBadInput, AFirstContactQueryAsksEveryStepAndItsWidth) {
  Json scene = validScene();
  scene["queries"][0]["kind"] = "first_contact";
  scene["queries"][0]["bracket_width"] = 0.01;
  Result<Scene> loaded = parse(scene);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  EXPECT_EQ(loaded.value().queries[0].asked.text(), "frame 0");
  EXPECT_EQ(loaded.value().queries[0].request.step->bracket_width, 0.01);
}

// "bad.json: /queries/0/frames: query 'q' is asked over a step from frame 1, the last: a step
//  needs the frame after it"
TEST(SceneBadInput, AFirstContactQueryFromTheLastFrame) {
  Json scene = validScene();
  scene["queries"][0]["kind"] = "first_contact";
  scene["queries"][0]["frames"] = Json::parse("[[0, 1]]");
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/frames:", "step from frame 1, the last"}));
}

// "bad.json: /queries/0/frames: query 'q' is asked over the step from frame 0, but object 'b'
//  does not exist in frame 1"
TEST(SceneBadInput, AFirstContactStepWhereAnObjectIsGoneInTheNextFrame) {
  Json scene = validScene();
  scene["frames"] = 3;
  scene["objects"][1]["frames"] = Json::parse("[[0, 0], [2, 2]]");
  scene["queries"][0]["kind"] = "first_contact";
  scene["queries"][0]["frames"] = Json::parse("[[0, 0]]");
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/frames:", "over the step from frame 0",
                                      "object 'b' does not exist in frame 1"}));
}

// "bad.json: /queries/0/bracket_width: bracket_width must be > 0"
TEST(SceneBadInput, ABracketWidthAtOrBelowZero) {
  for (const double width : {0.0, -0.1}) {
    Json scene = validScene();
    scene["queries"][0]["kind"] = "first_contact";
    scene["queries"][0]["bracket_width"] = width;
    EXPECT_TRUE(rejected(parse(scene), {"/queries/0/bracket_width:", "must be > 0"}));
  }
}

// "bad.json: /queries/0/bracket_width: bracket_width applies to first_contact queries only"
TEST(SceneBadInput, ABracketWidthOnASnapshotQuery) {
  Json scene = validScene();
  scene["queries"][0]["bracket_width"] = 0.01;
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/bracket_width:", "first_contact queries only"}));
}

// "bad.json: /queries/0/kind: a first_contact query is asked over a step from one frame to the
//  next: the scene needs at least two frames"
TEST(SceneBadInput, AFirstContactQueryOfAOneFrameScene) {
  Json scene = validScene();
  scene["frames"] = 1;
  scene["queries"][0]["kind"] = "first_contact";
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/kind:", "at least two frames"}));
}

TEST(SceneBadInput, ADistanceQueryWithTolerancesLoads) {
  Json scene = validScene();
  scene["queries"][0]["kind"] = "distance";
  scene["queries"][0]["abs_tolerance"] = 1e-3;
  scene["queries"][0]["rel_tolerance"] = 0.01;
  Result<Scene> loaded = parse(scene);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  const QueryRequest& request = loaded.value().queries[0].request;
  EXPECT_EQ(request.kind, QueryKind::kDistance);
  EXPECT_EQ(request.abs_tolerance, 1e-3);
  EXPECT_EQ(request.rel_tolerance, 0.01);
}

// "bad.json: /queries/0/rel_tolerance: rel_tolerance must be >= 0"
TEST(SceneBadInput, NegativeDistanceTolerance) {
  Json scene = validScene();
  scene["queries"][0]["kind"] = "distance";
  scene["queries"][0]["rel_tolerance"] = -0.1;
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/rel_tolerance:", "must be >= 0"}));
}

// "bad.json: /queries/0/abs_tolerance: abs_tolerance applies to distance queries only"
TEST(SceneBadInput, ToleranceOnANonDistanceQuery) {
  Json scene = validScene();
  scene["queries"][0]["abs_tolerance"] = 0.1;
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/abs_tolerance:", "distance queries only"}));
}

// "bad.json: /queries/0/kind: a group query ('among') asks all_pairs or contacts only, not
// distance"
TEST(SceneBadInput, GroupAsksForADistance) {
  Json scene = validScene();
  scene["queries"] = Json::array({Json{{"among", "*"}, {"kind", "distance"}}});
  EXPECT_TRUE(
      rejected(parse(scene), {"/queries/0/kind:", "all_pairs or contacts only, not distance"}));
}

// ---- group queries ---------------------------------------------------------------------------

Json groupScene(const Json& among) {
  Json scene = validScene();
  scene["queries"] = Json::array({Json{{"among", among}, {"kind", "all_pairs"}}});
  return scene;
}

TEST(SceneBadInput, AGroupQueryOverEveryObjectLoads) {
  Result<Scene> scene = parse(groupScene("*"));
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  const SceneQuery& q = scene.value().queries[0];
  EXPECT_TRUE(q.isGroup());
  EXPECT_EQ(q.among, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(q.name, "2 objects all_pairs");
  EXPECT_TRUE(scene.value().needsOf(1).queries.contains(QueryKind::kAllPairs));
}

TEST(SceneBadInput, AGroupQueryByNamesLoadsInObjectOrder) {
  Result<Scene> scene = parse(groupScene(Json::array({"b", "a"})));
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  EXPECT_EQ(scene.value().queries[0].among, (std::vector<std::size_t>{0, 1}));
}

// "bad.json: /queries/0: a query names either 'a' and 'b' or 'among', not both"
TEST(SceneBadInput, GroupQueryWithAAndB) {
  Json scene = groupScene("*");
  scene["queries"][0]["a"] = "a";
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0:", "either 'a' and 'b' or 'among'"}));
}

// "bad.json: /queries/0/among: a group query needs at least two objects"
TEST(SceneBadInput, GroupOfOneObject) {
  EXPECT_TRUE(rejected(parse(groupScene(Json::array({"a"}))),
                       {"/queries/0/among:", "at least two objects"}));
}

// "bad.json: /queries/0/among/1: no object named 'c'"
TEST(SceneBadInput, GroupNamesAnUnknownObject) {
  EXPECT_TRUE(rejected(parse(groupScene(Json::array({"a", "c"}))),
                       {"/queries/0/among/1:", "no object named 'c'"}));
}

// "bad.json: /queries/0/among/2: object 'a' named twice"
TEST(SceneBadInput, GroupNamesAnObjectTwice) {
  EXPECT_TRUE(rejected(parse(groupScene(Json::array({"a", "b", "a"}))),
                       {"/queries/0/among/2:", "object 'a' named twice"}));
}

// "bad.json: /queries/0/among: 'among' is "*" or an array of object names"
TEST(SceneBadInput, GroupIsAnUnknownWord) {
  EXPECT_TRUE(rejected(parse(groupScene("all")), {"/queries/0/among:", "'among' is \"*\""}));
}

// "bad.json: /queries/0/kind: a group query ('among') asks all_pairs or contacts only, not boolean"
TEST(SceneBadInput, GroupAsksABooleanQuestion) {
  Json scene = groupScene("*");
  scene["queries"][0]["kind"] = "boolean";
  EXPECT_TRUE(
      rejected(parse(scene), {"/queries/0/kind:", "all_pairs or contacts only, not boolean"}));
}

// ---- wrong types -----------------------------------------------------------------------------

// "bad.json: /objects/1/pose/translation/0: expected a number, got string"
TEST(SceneBadInput, StringForANumber) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["translation"][0] = "3";
  EXPECT_TRUE(rejected(parse(scene),
                       {"/objects/1/pose/translation/0:", "expected a number", "got string"}));
}

// "bad.json: /objects/0/name: expected a string, got number"
TEST(SceneBadInput, NumberForAString) {
  Json scene = validScene();
  scene["objects"][0]["name"] = 5;
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/name:", "expected a string", "got number"}));
}

// "bad.json: /objects/1/shape/major_segments: expected an integer, got a fractional number"
TEST(SceneBadInput, FractionalNumberForAnInteger) {
  Json scene = validScene();
  scene["objects"][1]["shape"]["major_segments"] = 8.5;
  EXPECT_TRUE(rejected(parse(scene),
                       {"/objects/1/shape/major_segments:", "expected an integer", "fractional"}));
}

// "bad.json: /objects: expected an array, got object"
TEST(SceneBadInput, ObjectForAnArray) {
  Json scene = validScene();
  scene["objects"] = Json::object();
  EXPECT_TRUE(rejected(parse(scene), {kLabel, "/objects:", "expected an array", "got object"}));
}

// "bad.json: /frames: expected an integer, got boolean"
TEST(SceneBadInput, BooleanForAnInteger) {
  Json scene = validScene();
  scene["frames"] = true;
  EXPECT_TRUE(rejected(parse(scene), {"/frames:", "expected an integer", "got boolean"}));
}

// "bad.json: /objects/1/pose/translation: expected 3 numbers, got 2"
TEST(SceneBadInput, VectorOfTwoNumbers) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["translation"] = Json::array({1, 2});
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/pose/translation:", "expected 3 numbers"}));
}

// ---- missing or empty ------------------------------------------------------------------------

// "bad.json: /: missing 'objects'"
TEST(SceneBadInput, MissingObjects) {
  Json scene = validScene();
  scene.erase("objects");
  EXPECT_TRUE(rejected(parse(scene), {kLabel, ": /:", "missing 'objects'"}));
}

// "bad.json: /: missing 'queries'"
TEST(SceneBadInput, MissingQueries) {
  Json scene = validScene();
  scene.erase("queries");
  EXPECT_TRUE(rejected(parse(scene), {": /:", "missing 'queries'"}));
}

// "bad.json: /objects/1: missing 'name'"
TEST(SceneBadInput, MissingObjectName) {
  Json scene = validScene();
  scene["objects"][1].erase("name");
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1:", "missing 'name'"}));
}

// "bad.json: /objects/0: missing 'shape'"
TEST(SceneBadInput, MissingShape) {
  Json scene = validScene();
  scene["objects"][0].erase("shape");
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0:", "missing 'shape'"}));
}

// "bad.json: /queries/0: missing 'kind'"
TEST(SceneBadInput, MissingQueryKind) {
  Json scene = validScene();
  scene["queries"][0].erase("kind");
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0:", "missing 'kind'"}));
}

// "bad.json: /queries/0: missing 'b' (or 'among')"
TEST(SceneBadInput, MissingQueryObject) {
  Json scene = validScene();
  scene["queries"][0].erase("b");
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0:", "missing 'b'"}));
}

// "bad.json: /objects/1/motion/random: missing 'overlap'"
TEST(SceneBadInput, RandomMotionWithoutOverlap) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"random", {{"relative_to", "a"}}}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion/random:", "missing 'overlap'"}));
}

// "bad.json: /queries/0/except/0/1: object 'c' is not in the query's group", a pair named twice,
// and "except" on a query of two objects
TEST(SceneBadInput, ExceptPairsOutsideTheGroup) {
  Json scene = validScene();
  scene["objects"].push_back(scene["objects"][1]);
  scene["objects"][2]["name"] = "c";
  scene["queries"][0] =
      Json::parse(R"({"among": ["a", "b"], "except": [["a", "c"]], "kind": "all_pairs"})");
  EXPECT_TRUE(
      rejected(parse(scene), {"/queries/0/except/0/1:", "'c' is not in the query's group"}));
  scene["queries"][0]["except"] = Json::parse(R"([["a", "b"], ["b", "a"]])");
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/except/1:", "named twice"}));
  scene["queries"][0] =
      Json::parse(R"({"a": "a", "b": "b", "except": [["a", "b"]], "kind": "boolean"})");
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/except:", "group queries"}));
}

// "bad.json: /up: must be a non-zero direction"
TEST(SceneBadInput, ZeroUpDirection) {
  Json scene = validScene();
  scene["up"] = {0, 0, 0};
  EXPECT_TRUE(rejected(parse(scene), {"/up:", "must be a non-zero direction"}));
}

// "bad.json: /objects: a scene needs at least one object"
TEST(SceneBadInput, EmptyObjectList) {
  Json scene = validScene();
  scene["objects"] = Json::array();
  EXPECT_TRUE(rejected(parse(scene), {"/objects:", "at least one object"}));
}

// "bad.json: /queries: a scene needs at least one query"
TEST(SceneBadInput, EmptyQueryList) {
  Json scene = validScene();
  scene["queries"] = Json::array();
  EXPECT_TRUE(rejected(parse(scene), {"/queries:", "at least one query"}));
}

// ---- names -----------------------------------------------------------------------------------

// "bad.json: /objects/1/name: duplicate object name 'a'"
TEST(SceneBadInput, DuplicateObjectName) {
  Json scene = validScene();
  scene["objects"][1]["name"] = "a";
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/name:", "duplicate object name 'a'"}));
}

// "bad.json: /queries/1: duplicate query name 'q'"
TEST(SceneBadInput, DuplicateQueryName) {
  Json scene = validScene();
  scene["queries"].push_back(scene["queries"][0]);
  scene["queries"][1]["kind"] = "all_pairs";
  EXPECT_TRUE(rejected(parse(scene), {"/queries/1", "duplicate query name 'q'"}));
}

// "bad.json: /queries/0/b: no object named 'c'"
TEST(SceneBadInput, QueryNamesAnUnknownObject) {
  Json scene = validScene();
  scene["queries"][0]["b"] = "c";
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/b:", "no object named 'c'"}));
}

// "bad.json: /queries/0: a query needs two different objects"
TEST(SceneBadInput, QueryOfAnObjectWithItself) {
  Json scene = validScene();
  scene["queries"][0]["b"] = "a";
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0", "two different objects"}));
}

// "bad.json: /queries/0/kind: unknown query kind 'penetration' (known: boolean, all_pairs,
//  contacts, distance or first_contact)"
TEST(SceneBadInput, UnknownQueryKind) {
  Json scene = validScene();
  scene["queries"][0]["kind"] = "penetration";
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/kind:", "unknown query kind 'penetration'",
                                      "boolean, all_pairs, contacts, distance or first_contact"}));
}

// "bad.json: /queries/0/max_pairs: expected an integer in [0, 9223372036854775807], got -1"
TEST(SceneBadInput, NegativeMaxPairs) {
  Json scene = validScene();
  scene["queries"][0]["max_pairs"] = -1;
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/max_pairs:", "got -1"}));
}

// "bad.json: /queries/0/max_contacts: expected an integer in [0, 9223372036854775807], got -5"
TEST(SceneBadInput, NegativeMaxContacts) {
  Json scene = validScene();
  scene["queries"][0]["max_contacts"] = -5;
  EXPECT_TRUE(rejected(parse(scene), {"/queries/0/max_contacts:", "got -5"}));
}

// "bad.json: /objects/1/motion/jitter/seed: expected an integer in [0, 9223372036854775807],
//  got -1"
TEST(SceneBadInput, NegativeJitterSeed) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"jitter", {{"seed", -1}, {"translation", 0.1}}}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion/jitter/seed:", "got -1"}));
}

// "bad.json: /objects/1/motion/random/seed: expected an integer in [0, 9223372036854775807],
//  got -7"
TEST(SceneBadInput, NegativeRandomSeed) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {
      {"random", {{"seed", -7}, {"relative_to", "a"}, {"overlap", 0.5}}}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion/random/seed:", "got -7"}));
}

// ---- shapes ----------------------------------------------------------------------------------

// "bad.json: /objects/0/shape/generator: unknown generator 'cube' (known: box, chain, cylinder,
//  flange, gear, grid_sheet, sphere, station_module, torus)"
TEST(SceneBadInput, UnknownGenerator) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"generator", "cube"}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape/generator:", "unknown generator 'cube'",
                                      "box, chain, cylinder, flange, gear, grid_sheet, sphere, "
                                      "station_module, torus"}));
}

// A count below the generator's minimum is refused by the generator, not raised to the minimum
// by the load's resolution:
// "bad.json: /objects/1/shape: torus: minor_segments = 2, must be >= 3"
TEST(SceneBadInput, TorusWithTwoMinorSegments) {
  Json scene = validScene();
  scene["objects"][1]["shape"]["minor_segments"] = 2;
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/shape:", "minor_segments = 2", "must be >= 3"}));
}

// A generated shape whose coordinates go past the limit, close to the double maximum (found by
// scene_json_fuzz: the message's shortest round-trip text of 1.5e308 once threw out of stod).
TEST(SceneBadInput, GeneratedShapeNearTheDoubleMaximum) {
  Json scene = validScene();
  scene["objects"][1]["shape"]["major_radius"] = 1.5e308;
  scene["objects"][1]["shape"]["minor_segments"] = 3;
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/shape"}));
}

// The generator's own message, at the shape:
// "bad.json: /objects/1/shape: torus: minor_radius = 1, must be < major_radius = 1"
TEST(SceneBadInput, TorusMinorRadiusNotBelowMajorRadius) {
  Json scene = validScene();
  scene["objects"][1]["shape"]["minor_radius"] = 1;
  EXPECT_TRUE(rejected(
      parse(scene), {"/objects/1/shape", "torus", "minor_radius = 1", "must be < major_radius"}));
}

// "bad.json: /objects/0/shape: gear: pressure_angle_deg = 50, must be in (0, 45)"
TEST(SceneBadInput, GearPressureAngleOutOfRange) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"generator", "gear"}, {"pressure_angle_deg", 50}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape", "gear", "pressure_angle_deg", "45"}));
}

// "bad.json: /objects/0/shape: sphere: radius = 0, must be finite and > 0"
TEST(SceneBadInput, ZeroSphereRadius) {
  Json scene = validScene();
  scene["objects"][0]["shape"]["radius"] = 0;
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape:", "sphere: radius = 0", "> 0"}));
}

// "bad.json: /objects/0/shape: give exactly one of 'mesh' (a file), 'generator' or 'frep' (a
// solid)"
TEST(SceneBadInput, ShapeWithBothMeshAndGenerator) {
  Json scene = validScene();
  scene["objects"][0]["shape"]["mesh"] = "meshes/bunny.obj";
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape", "exactly one of 'mesh'"}));
}

// FRep shapes: an unbounded solid cannot be polygonized; a bad solid or cell count names its path.
TEST(SceneBadInput, FrepShapeErrorsNameTheirPath) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = Json{{"frep", {{"type", "half_space"}, {"normal", {0, 0, 1}}}}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape/frep", "unbounded"}));
  scene["objects"][0]["shape"] = Json{{"frep", {{"type", "sphere"}, {"radius", -1}}}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape/frep", "radius must be > 0"}));
  scene["objects"][0]["shape"] = Json{{"frep", {{"type", "sphere"}, {"radius", 1}}}, {"cells", 1}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape/cells", "[2, 512]"}));
}

// "bad.json: /objects/0/shape/mesh: <scenes>/meshes/absent.obj: file not found"
TEST(SceneBadInput, MeshFileMissing) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"mesh", "meshes/absent.obj"}};
  EXPECT_TRUE(
      rejected(parse(scene), {"/objects/0/shape/mesh:", "meshes/absent.obj", "file not found"}));
}

// The mesh's own problem comes through with the JSON path:
// "bad.json: /objects/0/shape/mesh: <dir>/nan.obj: vertex 0 has a non-finite x coordinate (nan)"
TEST(SceneBadInput, MeshFileWithNan) {
  const std::string dir = test::makeTempDirectory("bad_scene");
  test::writeFile(dir + "/nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"mesh", "nan.obj"}};
  EXPECT_TRUE(rejected(parseScene(scene.dump(), kLabel, dir),
                       {"/objects/0/shape/mesh:", "nan.obj", "non-finite"}));
}

// A mesh file past the coordinate limit (kMaxCoordinate, scenes/README.md), with line and vertex:
// "bad.json: /objects/0/shape/mesh: <dir>/huge.obj: line 2: vertex 1 has y coordinate '2e18',
//  beyond the coordinate limit |y| <= 1e18 (scenes/README.md)"
TEST(SceneBadInput, MeshFileBeyondTheCoordinateLimit) {
  const std::string dir = test::makeTempDirectory("bad_scene");
  test::writeFile(dir + "/huge.obj", "v 0 0 0\nv 1 2e18 0\nv 0 1 0\nf 1 2 3\n");
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"mesh", "huge.obj"}};
  EXPECT_TRUE(
      rejected(parseScene(scene.dump(), kLabel, dir),
               {"/objects/0/shape/mesh:", "huge.obj", "line 2", "vertex 1", "coordinate limit"}));
}

// A scale can take a valid mesh past the limit; the scale is the culprit:
// "bad.json: /objects/0/shape/scale: scaled by 1e+20: <scenes>/meshes/rob.obj: vertex 0 has x
//  coordinate ..., beyond the coordinate limit |x| <= 1e18 (scenes/README.md)"
TEST(SceneBadInput, MeshScaledBeyondTheCoordinateLimit) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"mesh", "meshes/rob.obj"}, {"scale", 1e20}};
  EXPECT_TRUE(rejected(
      parse(scene), {"/objects/0/shape/scale:", "scaled by 1e+20", "rob.obj", "coordinate limit"}));
}

// A mesh file that does not import comes through with the JSON path (here assimp's second opinion
// used to abort the process):
// "bad.json: /objects/0/shape/mesh: <dir>/cut.ply: the file ends early: the data stops in
//  'vertex' 2 (0-based) of the 3 that the header declares"
TEST(SceneBadInput, MeshFileThatDoesNotImport) {
  const std::string dir = test::makeTempDirectory("bad_scene");
  test::writeFile(dir + "/cut.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                  "end_header\n0 0 0\n1 0 0\n0 1\n");
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"mesh", "cut.ply"}};
  EXPECT_TRUE(rejected(parseScene(scene.dump(), kLabel, dir),
                       {"/objects/0/shape/mesh:", "cut.ply", "ends early"}));
}

// "bad.json: /objects/0/shape/mesh: <dir>/empty.stl: the file is empty"
TEST(SceneBadInput, EmptyMeshFile) {
  const std::string dir = test::makeTempDirectory("bad_scene");
  test::writeFile(dir + "/empty.stl", "");
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"mesh", "empty.stl"}};
  EXPECT_TRUE(rejected(parseScene(scene.dump(), kLabel, dir),
                       {"/objects/0/shape/mesh:", "empty.stl", "the file is empty"}));
}

// "bad.json: /objects/0/shape/scale: scale must be > 0"
TEST(SceneBadInput, NegativeMeshScale) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"mesh", "meshes/rob.obj"}, {"scale", -2}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape/scale", "> 0"}));
  // One factor per axis (a URDF mesh's scale), each held to the same rule.
  scene["objects"][0]["shape"]["scale"] = Json::array({1, 0, 1});
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape/scale", "factors must be > 0"}));
}

// ---- frames ----------------------------------------------------------------------------------

// "bad.json: /frames: expected an integer in [1, 1000000], got 0"
TEST(SceneBadInput, ZeroFrames) {
  Json scene = validScene();
  scene["frames"] = 0;
  EXPECT_TRUE(rejected(parse(scene), {"/frames:", "got 0"}));
}

// "bad.json: /frames: expected an integer in [1, 1000000], got -3"
TEST(SceneBadInput, NegativeFrames) {
  Json scene = validScene();
  scene["frames"] = -3;
  EXPECT_TRUE(rejected(parse(scene), {"/frames:", "got -3"}));
}

// ---- poses -----------------------------------------------------------------------------------

// "bad.json: /objects/1/pose/rotation/matrix: not a rotation: max |R^T R - I| = 3, det = 8 (...)"
TEST(SceneBadInput, ScaledRotationMatrix) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["rotation"] = rotation({{2, 0, 0}, {0, 2, 0}, {0, 0, 2}});
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/pose/rotation/matrix:", "not a rotation"}));
}

// "bad.json: /objects/1/pose/rotation/matrix: not a rotation: max |R^T R - I| = 0.1, det = 1 ..."
TEST(SceneBadInput, ShearedRotationMatrix) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["rotation"] = rotation({{1, 0.1, 0}, {0, 1, 0}, {0, 0, 1}});
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/pose/rotation/matrix:", "not a rotation"}));
}

// A reflection is orthonormal, but its determinant is -1:
// "bad.json: /objects/1/pose/rotation/matrix: not a rotation: max |R^T R - I| = 0, det = -1 ..."
TEST(SceneBadInput, ReflectionMatrix) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["rotation"] = rotation({{1, 0, 0}, {0, 1, 0}, {0, 0, -1}});
  EXPECT_TRUE(
      rejected(parse(scene), {"/objects/1/pose/rotation/matrix:", "not a rotation", "det = -1"}));
}

// "bad.json: /objects/1/pose/rotation/quaternion: not a unit quaternion (norm 1.414214)"
TEST(SceneBadInput, NonUnitQuaternion) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["rotation"] = {{"quaternion", {1, 1, 0, 0}}};
  EXPECT_TRUE(rejected(parse(scene),
                       {"/objects/1/pose/rotation/quaternion:", "not a unit quaternion", "1.41"}));
}

// "bad.json: /objects/1/pose/rotation/quaternion: not a unit quaternion (norm 0.000000)"
TEST(SceneBadInput, ZeroQuaternion) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["rotation"] = {{"quaternion", {0, 0, 0, 0}}};
  EXPECT_TRUE(rejected(
      parse(scene), {"/objects/1/pose/rotation/quaternion:", "not a unit quaternion", "norm 0"}));
}

// "bad.json: /objects/1/pose/translation/1: 2e+18 is beyond the coordinate limit |t| <= 1e+18
//  (scenes/README.md)"
TEST(SceneBadInput, TranslationBeyondTheCoordinateLimit) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["translation"] = {3, 2e18, 0};
  EXPECT_TRUE(rejected(parse(scene),
                       {"/objects/1/pose/translation/1:", "2e+18", "beyond the coordinate limit"}));
}

// "bad.json: /objects/1/pose/rotation/axis: the axis must not be zero"
TEST(SceneBadInput, ZeroRotationAxis) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["rotation"] = {{"axis", {0, 0, 0}}, {"degrees", 30}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/pose/rotation/axis:", "must not be zero"}));
}

// "bad.json: /objects/1/pose/rotation: give exactly one of matrix, quaternion, or axis + degrees"
TEST(SceneBadInput, TwoRotationForms) {
  Json scene = validScene();
  scene["objects"][1]["pose"]["rotation"] = {{"quaternion", {1, 0, 0, 0}},
                                             {"matrix", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/pose/rotation:", "exactly one of"}));
}

// ---- motion ----------------------------------------------------------------------------------

// "bad.json: /objects/1/motion/poses: has 3 poses but the scene has 2 frames"
TEST(SceneBadInput, PoseListLengthDiffersFromFrames) {
  Json scene = validScene();
  scene["objects"][1].erase("pose");
  scene["objects"][1]["motion"] = {
      {"poses", Json::array({Json::object(), Json::object(), Json::object()})}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion/poses:", "3 poses", "2 frames"}));
}

// "bad.json: /objects/1/pose: 'pose' and motion 'poses' exclude each other"
TEST(SceneBadInput, PoseTogetherWithPoses) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"poses", Json::array({Json::object(), Json::object()})}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/pose:", "exclude each other"}));
}

// Every pose of a motion's list is checked like a fixed one:
// "bad.json: /objects/1/motion/poses/1/rotation/matrix: not a rotation: max |R^T R - I| = 0.21,
//  det = 1.1 (...)"
TEST(SceneBadInput, NonRigidPoseInAPoseList) {
  Json scene = validScene();
  scene["objects"][1].erase("pose");
  scene["objects"][1]["motion"] = {
      {"poses", Json::array({Json::object(),
                             {{"rotation", rotation({{1.1, 0, 0}, {0, 1, 0}, {0, 0, 1}})}}})}};
  EXPECT_TRUE(
      rejected(parse(scene), {"/objects/1/motion/poses/1/rotation/matrix:", "not a rotation"}));
}

// "bad.json: /objects/1/motion/poses/0/translation/0: -1e+300 is beyond the coordinate limit
//  |t| <= 1e+18 (scenes/README.md)"
TEST(SceneBadInput, HugeTranslationInAPoseList) {
  Json scene = validScene();
  scene["objects"][1].erase("pose");
  scene["objects"][1]["motion"] = {
      {"poses", Json::array({{{"translation", {-1e300, 0, 0}}}, Json::object()})}};
  EXPECT_TRUE(rejected(
      parse(scene), {"/objects/1/motion/poses/0/translation/0:", "-1e+300", "coordinate limit"}));
}

// "bad.json: /objects/1/motion: give exactly one of poses, random, jitter, linear"
TEST(SceneBadInput, TwoMotionKinds) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"random", {{"relative_to", "a"}, {"overlap", 0.5}}},
                                   {"jitter", {{"translation", 0.1}}}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion:", "exactly one of"}));
}

// "bad.json: /objects/1/motion/random/relative_to: 'c' is not an object defined before this one"
TEST(SceneBadInput, RandomMotionRelativeToAnUnknownObject) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"random", {{"relative_to", "c"}, {"overlap", 0.5}}}};
  EXPECT_TRUE(
      rejected(parse(scene), {"/objects/1/motion/random/relative_to:", "'c'", "defined before"}));
}

// "bad.json: /objects/0/motion/random/relative_to: 'b' is not an object defined before this one"
TEST(SceneBadInput, RandomMotionRelativeToALaterObject) {
  Json scene = validScene();
  scene["objects"][0]["motion"] = {{"random", {{"relative_to", "b"}, {"overlap", 0.5}}}};
  EXPECT_TRUE(
      rejected(parse(scene), {"/objects/0/motion/random/relative_to:", "'b'", "defined before"}));
}

// "bad.json: /objects/1/motion/random/overlap: overlap must satisfy 0 <= low <= high <= 1"
TEST(SceneBadInput, OverlapAboveOne) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"random", {{"relative_to", "a"}, {"overlap", 1.5}}}};
  EXPECT_TRUE(
      rejected(parse(scene), {"/objects/1/motion/random/overlap:", "0 <= low <= high <= 1"}));
}

// "bad.json: /objects/1/motion/random/overlap: overlap must satisfy 0 <= low <= high <= 1"
TEST(SceneBadInput, OverlapRangeBelowZero) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"random", {{"relative_to", "a"}, {"overlap", {-0.1, 0.5}}}}};
  EXPECT_TRUE(
      rejected(parse(scene), {"/objects/1/motion/random/overlap:", "0 <= low <= high <= 1"}));
}

// "bad.json: /objects/1/motion/random/overlap: overlap must satisfy 0 <= low <= high <= 1"
TEST(SceneBadInput, OverlapRangeReversed) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"random", {{"relative_to", "a"}, {"overlap", {0.8, 0.2}}}}};
  EXPECT_TRUE(
      rejected(parse(scene), {"/objects/1/motion/random/overlap:", "0 <= low <= high <= 1"}));
}

// "bad.json: /objects/1/motion/jitter: translation must be >= 0 and rotation_deg in [0, 180]"
TEST(SceneBadInput, NegativeJitter) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"jitter", {{"translation", -0.1}}}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion/jitter", "translation must be >= 0"}));
}

// A jitter takes every frame far past the coordinate limit that the base pose is within:
// "bad.json: /objects/1/motion: frame 0: the translation (..., ..., ...) is beyond the coordinate
//  limit |t| <= 1e+18 (scenes/README.md)"
TEST(SceneBadInput, JitterBeyondTheCoordinateLimit) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"jitter", {{"translation", 1e300}}}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion:", "frame 0", "the translation",
                                      "beyond the coordinate limit"}));
}

// ---- linear motion ---------------------------------------------------------------------------

/// The valid scene with object "b" moving linearly over `frames` frames (its fixed pose removed).
Json linearScene(int frames, const Json& from, const Json& to) {
  Json scene = validScene();
  scene["frames"] = frames;
  scene["objects"][1].erase("pose");
  scene["objects"][1]["motion"] = {{"linear", {{"from", from}, {"to", to}}}};
  return scene;
}

// Frame f of F: translation from + (to - from) f / (F - 1), rotation slerp; the ends exact.
TEST(SceneBadInput, LinearMotionInterpolatesBetweenTheEnds) {
  const Json from = {{"translation", {1, 2, 3}}};
  const Json to = {{"translation", {5, -2, 3}},
                   {"rotation", {{"axis", {0, 0, 1}}, {"degrees", 90}}}};
  Result<Scene> scene = parse(linearScene(5, from, to));
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  const std::vector<Pose>& poses = scene.value().objects[1].poses;
  ASSERT_EQ(poses.size(), 5u);
  const Eigen::Matrix3d quarter_turn =
      Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_TRUE(poses[0].translation() == Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(poses[0].linear() == Eigen::Matrix3d::Identity());
  EXPECT_TRUE(poses[4].translation() == Eigen::Vector3d(5, -2, 3));
  EXPECT_TRUE(poses[4].linear() == quarter_turn);
  for (int f = 1; f < 4; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    const Pose& pose = poses[static_cast<std::size_t>(f)];
    // (to - from) f / (F - 1) = (4, -4, 0) f / 4: every operation exact.
    EXPECT_TRUE(pose.translation() == Eigen::Vector3d(1 + f, 2 - f, 3));
    const Eigen::Matrix3d expected =
        Eigen::AngleAxisd(M_PI / 8.0 * f, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    EXPECT_LT((pose.linear() - expected).cwiseAbs().maxCoeff(), 1e-15);
  }
}

// Equal rotations at both ends are kept exactly, bit for bit, in every frame; one frame is `from`.
TEST(SceneBadInput, LinearMotionKeepsAnEqualRotationExactly) {
  const Json flip = {{"matrix", {{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}}}};
  Result<Scene> scene = parse(linearScene(7, {{"translation", {0, 0, 9.04}}, {"rotation", flip}},
                                          {{"translation", {0, 0, 8.994}}, {"rotation", flip}}));
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  Eigen::Matrix3d flipped;
  flipped << -1, 0, 0, 0, 1, 0, 0, 0, -1;
  for (const Pose& pose : scene.value().objects[1].poses) {
    EXPECT_TRUE(pose.linear() == flipped);
    EXPECT_EQ(pose.translation().x(), 0.0);
    EXPECT_EQ(pose.translation().y(), 0.0);
  }
  scene = parse(linearScene(1, {{"translation", {1, 0, 0}}}, {{"translation", {2, 0, 0}}}));
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  ASSERT_EQ(scene.value().objects[1].poses.size(), 1u);
  EXPECT_EQ(scene.value().objects[1].poses[0].translation().x(), 1.0);
}

// "bad.json: /objects/1/motion/linear: missing 'to'"
TEST(SceneBadInput, LinearMotionWithoutTo) {
  Json scene = linearScene(2, Json::object(), Json::object());
  scene["objects"][1]["motion"]["linear"].erase("to");
  EXPECT_TRUE(rejected(parse(scene), {kLabel, "/objects/1/motion/linear:", "missing 'to'"}));
}

// "bad.json: /objects/1/motion/linear: missing 'from'"
TEST(SceneBadInput, LinearMotionWithoutFrom) {
  Json scene = linearScene(2, Json::object(), Json::object());
  scene["objects"][1]["motion"]["linear"].erase("from");
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion/linear:", "missing 'from'"}));
}

// "bad.json: /objects/1/motion/linear: unknown key 'via' (allowed: from, to)"
TEST(SceneBadInput, UnknownKeyInLinearMotion) {
  Json scene = linearScene(2, Json::object(), Json::object());
  scene["objects"][1]["motion"]["linear"]["via"] = Json::object();
  EXPECT_TRUE(rejected(parse(scene),
                       {"/objects/1/motion/linear:", "unknown key 'via'", "allowed: from, to"}));
}

// "bad.json: /objects/1/motion/linear: expected an object, got array"
TEST(SceneBadInput, LinearMotionNotAnObject) {
  Json scene = validScene();
  scene["objects"][1].erase("pose");
  scene["objects"][1]["motion"] = {{"linear", Json::array({1, 2})}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion/linear:", "expected an object"}));
}

// "bad.json: /objects/1/motion/linear/to/translation: expected 3 numbers, got 2"
TEST(SceneBadInput, LinearMotionWithABadEnd) {
  Json scene = linearScene(2, Json::object(), {{"translation", {1, 2}}});
  EXPECT_TRUE(
      rejected(parse(scene), {"/objects/1/motion/linear/to/translation:", "expected 3 numbers"}));
}

// "bad.json: /objects/1/motion/linear/from/rotation/quaternion: not a unit quaternion (norm 2)"
TEST(SceneBadInput, LinearMotionWithANonUnitQuaternion) {
  Json scene = linearScene(2, {{"rotation", {{"quaternion", {2, 0, 0, 0}}}}}, Json::object());
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion/linear/from/rotation/quaternion:",
                                      "not a unit quaternion"}));
}

// "bad.json: /objects/1/motion/linear/to/rotation/matrix: not a rotation: max |R^T R - I| = 0,
//  det = -1 (...)"
TEST(SceneBadInput, LinearMotionToAReflection) {
  Json scene =
      linearScene(2, Json::object(), {{"rotation", rotation({{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}})}});
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion/linear/to/rotation/matrix:",
                                      "not a rotation", "det = -1"}));
}

// "bad.json: /objects/1/pose: 'pose' and motion 'linear' exclude each other"
TEST(SceneBadInput, PoseTogetherWithLinearMotion) {
  Json scene = validScene();
  scene["objects"][1]["motion"] = {{"linear", {{"from", Json::object()}, {"to", Json::object()}}}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/pose:", "'pose' and motion 'linear'"}));
}

// "bad.json: /objects/1/motion: give exactly one of poses, random, jitter, linear"
TEST(SceneBadInput, LinearTogetherWithJitter) {
  Json scene = linearScene(2, Json::object(), Json::object());
  scene["objects"][1]["motion"]["jitter"] = {{"translation", 0.1}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/1/motion:", "exactly one of", "linear"}));
}

// ---- CAD parts -------------------------------------------------------------------------------

// The generator's own message, at the shape:
// "bad.json: /objects/0/shape: flange: bore_radius = 0.7, must be < bolt_circle_radius *
//  cos(pi / bolt_holes) = 0.649519 (each hole's sector must be visible from its centre)"
TEST(SceneBadInput, FlangeBoreReachingTheBoltHoles) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"generator", "flange"}, {"bore_radius", 0.7}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape:", "flange", "bore_radius = 0.7",
                                      "must be < bolt_circle_radius"}));
}

// "bad.json: /objects/0/shape: cylinder: inner_radius = 2, must be 0 (solid) or in (0, radius =
//  0.5)"
TEST(SceneBadInput, TubeBoreWiderThanTheTube) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"generator", "cylinder"}, {"inner_radius", 2}};
  EXPECT_TRUE(rejected(parse(scene),
                       {"/objects/0/shape:", "cylinder", "inner_radius = 2", "radius = 0.5"}));
}

// ---- station module --------------------------------------------------------------------------

// The generator's own message, at the shape:
// "bad.json: /objects/0/shape: station module: port_radius = 1.5, must be < radius = 1"
TEST(SceneBadInput, StationModulePortWiderThanTheHull) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"generator", "station_module"}, {"port_radius", 1.5}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape:", "station module", "port_radius = 1.5",
                                      "must be < radius = 1"}));
}

// "bad.json: /objects/0/shape: unknown key 'panels' (allowed: generator, length, panel_span,
//  panel_width, port_length, port_radius, radius, rings, segments, truss_bays)"
TEST(SceneBadInput, UnknownKeyInStationModule) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"generator", "station_module"}, {"panels", 2}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape:", "unknown key 'panels'",
                                      "allowed: generator, length, panel_span, panel_width, "
                                      "port_length, port_radius, radius, rings, segments, "
                                      "truss_bays"}));
}

// "bad.json: /objects/0/shape: station module: truss_bays = 0, must be >= 1"
TEST(SceneBadInput, StationModuleWithoutTrussBays) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {{"generator", "station_module"}, {"truss_bays", 0}};
  EXPECT_TRUE(rejected(parse(scene), {"/objects/0/shape:", "truss_bays = 0", "must be >= 1"}));
}

// Segments and rings follow the load's resolution (down to their minimums); bays do not.
TEST(SceneBadInput, StationModuleSampleCountsFollowTheResolution) {
  Json scene = validScene();
  scene["objects"][0]["shape"] = {
      {"generator", "station_module"}, {"segments", 40}, {"rings", 1}, {"truss_bays", 3}};
  const auto triangles = [&](double resolution) {
    Result<Scene> loaded =
        parseScene(scene.dump(), kLabel, test::sourcePath("scenes"), {resolution});
    EXPECT_TRUE(loaded.ok()) << loaded.status().toString();
    return loaded.ok() ? loaded.value().objects[0].mesh->triangleCount() : 0;
  };
  const std::size_t boxes = 12 * (8 * 3 + 11);
  EXPECT_EQ(triangles(1.0), 4u * 40 * 2 + boxes);
  EXPECT_EQ(triangles(0.5), 4u * 20 * 2 + boxes);  // rings stays at its minimum, 1
  EXPECT_EQ(triangles(2.0), 4u * 80 * 3 + boxes);
}

}  // namespace
}  // namespace collido
