// Scenes that ask for too much or overflow: the load limits (SceneLoadOptions::max_triangles,
// max_frames) and numbers that are finite in the file but not in what they make. Each is refused
// with kInvalidArgument naming the file, the JSON path and the problem; the comment above each
// test shows the message. Most were found by tests/fuzz/scene_json_fuzz.
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

constexpr const char* kLimitsLabel = "limits.json";

/// Object "a" with `shape`, object "b" a 64-triangle torus at x = 3, one boolean query.
Json sceneWith(const Json& shape) {
  Json scene = Json::parse(R"({
    "objects": [
      {"name": "a", "shape": {}},
      {"name": "b",
       "shape": {"generator": "torus", "major_segments": 8, "minor_segments": 4},
       "pose": {"translation": [3, 0, 0]}}
    ],
    "queries": [{"name": "q", "a": "a", "b": "b", "kind": "boolean"}]
  })");
  scene["objects"][0]["shape"] = shape;
  return scene;
}
constexpr std::size_t kTorusB = 64;

Result<Scene> parseWithLimits(const Json& scene, const SceneLoadOptions& options = {}) {
  return parseScene(scene.dump(), kLimitsLabel, test::sourcePath("scenes"), options);
}

SceneLoadOptions maxTriangles(std::size_t limit) {
  SceneLoadOptions options;
  options.max_triangles = limit;
  return options;
}

// ---- max_triangles -------------------------------------------------------------------------

// The count each generator is charged is the count it makes: a load with exactly that limit
// passes, one triangle less is refused.
TEST(SceneLimits, EachGeneratorIsChargedItsTriangleCount) {
  const Json shapes[] = {
      {{"generator", "torus"}, {"major_segments", 12}, {"minor_segments", 6}},
      {{"generator", "chain"}, {"links", 3}, {"major_segments", 12}, {"minor_segments", 6}},
      {{"generator", "sphere"}, {"slices", 10}, {"stacks", 5}},
      {{"generator", "grid_sheet"}, {"cells_x", 7}, {"cells_y", 3}},
      {{"generator", "gear"}},
      {{"generator", "gear"}, {"teeth", 50}},  // root circle outside the base circle: no feet
      {{"generator", "station_module"}, {"segments", 12}, {"rings", 2}, {"truss_bays", 2}},
      {{"generator", "box"}},
      {{"generator", "cylinder"}, {"segments", 9}},
      {{"generator", "cylinder"}, {"segments", 9}, {"inner_radius", 0.25}},
      {{"generator", "flange"}, {"bolt_holes", 5}}};
  for (const Json& shape : shapes) {
    SCOPED_TRACE(shape.dump());
    const Result<Scene> unlimited = parseWithLimits(sceneWith(shape));
    ASSERT_TRUE(unlimited.ok()) << unlimited.status().toString();
    const std::size_t total = unlimited.value().objects[0].mesh->triangleCount() + kTorusB;
    EXPECT_TRUE(parseWithLimits(sceneWith(shape), maxTriangles(total)).ok());
    EXPECT_TRUE(rejected(parseWithLimits(sceneWith(shape), maxTriangles(total - 1)),
                         {kLimitsLabel, "/objects/1/shape:", "max_triangles"}));
  }
}

// Refused from its parameters, before anything is generated:
// "limits.json: /objects/0/shape: torus R=1 r=0.25 1048576x1048576 needs 2199023255552
//  triangles, which takes the scene to 2199023255552, more than this load allows (1000000,
//  SceneLoadOptions::max_triangles)"
TEST(SceneLimits, AHugeGeneratorIsRefusedBeforeItIsGenerated) {
  const Json torus = {
      {"generator", "torus"}, {"major_segments", 1 << 20}, {"minor_segments", 1 << 20}};
  EXPECT_TRUE(rejected(
      parseWithLimits(sceneWith(torus), maxTriangles(1000000)),
      {kLimitsLabel, "/objects/0/shape:", "2199023255552 triangles", "1000000", "max_triangles"}));
}

// Mesh files count too (rob.obj has 216 triangles):
// "limits.json: /objects/0/shape: <scenes>/meshes/rob.obj needs 216 triangles, which takes the
//  scene to 216, more than this load allows (100, SceneLoadOptions::max_triangles)"
TEST(SceneLimits, MeshFilesCountTowardsTheLimit) {
  const Json rob = {{"mesh", "meshes/rob.obj"}};
  EXPECT_TRUE(rejected(parseWithLimits(sceneWith(rob), maxTriangles(100)),
                       {"/objects/0/shape:", "rob.obj needs 216 triangles", "max_triangles"}));
  EXPECT_TRUE(parseWithLimits(sceneWith(rob), maxTriangles(216 + kTorusB)).ok());
}

// Without a limit (the default) only each generator's own 50 million applies; a huge resolution
// meets that limit instead of overflowing the sample counts.
TEST(SceneLimits, AHugeResolutionMeetsTheGeneratorsOwnLimit) {
  SceneLoadOptions options;
  options.resolution = 1e12;
  EXPECT_TRUE(rejected(parseWithLimits(sceneWith({{"generator", "sphere"}}), options),
                       {"/objects/0/shape:", "50000000"}));
}

// ---- max_frames ----------------------------------------------------------------------------

// "limits.json: /frames: expected an integer in [1, 10], got 11"
TEST(SceneLimits, MoreFramesThanTheLoadAllows) {
  Json scene = sceneWith({{"generator", "sphere"}});
  scene["frames"] = 11;
  SceneLoadOptions options;
  options.max_frames = 10;
  EXPECT_TRUE(rejected(parseWithLimits(scene, options), {"/frames:", "[1, 10]", "got 11"}));
  scene["frames"] = 10;
  EXPECT_TRUE(parseWithLimits(scene, options).ok());
}

// Without "frames", the longest pose list sets the count, and is held to the same limit:
// "limits.json: /objects/1/motion/poses: has 3 poses, more frames than this load allows (2,
//  SceneLoadOptions::max_frames)"
TEST(SceneLimits, APoseListLongerThanTheLoadAllows) {
  Json scene = sceneWith({{"generator", "sphere"}});
  scene["objects"][1].erase("pose");
  scene["objects"][1]["motion"] = {
      {"poses", Json::array({Json::object(), Json::object(), Json::object()})}};
  SceneLoadOptions options;
  options.max_frames = 2;
  EXPECT_TRUE(rejected(parseWithLimits(scene, options),
                       {"/objects/1/motion/poses:", "3 poses", "max_frames"}));
}

// ---- numbers past the double range ---------------------------------------------------------

// A literal beyond the double range is a JSON error, not an exception thrown at the caller:
// "limits.json: not valid JSON: [json.exception.out_of_range.406] number overflow parsing
//  '1e400'"
TEST(SceneLimits, ANumberBeyondTheDoubleRange) {
  EXPECT_TRUE(rejected(parseScene(R"({"frames": 1e400})", kLimitsLabel, "."),
                       {kLimitsLabel, "not valid JSON", "1e400"}));
}

// "limits.json: /objects/0/shape/scale: scaled by 1e+308: <scenes>/meshes/rob.obj: vertex 0
//  has a non-finite x coordinate (inf)"
TEST(SceneLimits, AMeshScaledPastTheDoubleRange) {
  const Json rob = {{"mesh", "meshes/rob.obj"}, {"scale", 1e308}};
  EXPECT_TRUE(rejected(parseWithLimits(sceneWith(rob)), {"/objects/0/shape/scale:", "non-finite"}));
}

// "limits.json: /objects/0/shape: torus R=1.5e+308 r=1e+308 3x3: vertex 0 has a non-finite x
//  coordinate (-nan)"
TEST(SceneLimits, AGeneratorWhoseShapeOverflows) {
  const Json torus = {{"generator", "torus"},
                      {"major_radius", 1.5e308},
                      {"minor_radius", 1e308},
                      {"major_segments", 3},
                      {"minor_segments", 3}};
  EXPECT_TRUE(rejected(parseWithLimits(sceneWith(torus)), {"/objects/0/shape:", "non-finite"}));
}

// Both ends are finite, their difference is not; but ends this far out are refused first, by
// the coordinate limit (kMaxCoordinate, within which no motion overflows):
// "limits.json: /objects/1/motion/linear/from/translation/0: -1.7e+308 is beyond the coordinate
//  limit |t| <= 1e+18 (scenes/README.md)"
TEST(SceneLimits, AMotionThatOverflows) {
  Json scene = sceneWith({{"generator", "sphere"}});
  scene["frames"] = 3;
  scene["objects"][1].erase("pose");
  scene["objects"][1]["motion"] = {{"linear",
                                    {{"from", {{"translation", {-1.7e308, 0, 0}}}},
                                     {"to", {{"translation", {1.7e308, 0, 0}}}}}}};
  EXPECT_TRUE(rejected(parseWithLimits(scene), {"/objects/1/motion/linear/from/translation/0:",
                                                "beyond the coordinate limit"}));
}

}  // namespace
}  // namespace collido
