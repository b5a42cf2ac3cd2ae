// Scenes with a `constraints` block: solved at load with the exact oracle's distances, the
// correction carried through every frame, the solution written back, and the bundled scenes.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <collido/oracle/distance_oracle.h>
#include <collido/scene/placement.h>
#include <collido/scene/scene.h>

#include "support/test_paths.h"

namespace collido {
namespace {

using Json = nlohmann::json;

/// Sphere "a" fixed; sphere "b" keyframed over three frames, starting off the x axis; "c"
/// unconstrained. The block holds b's centre on the x axis, 0.25 from a, its z axis upright.
Json keyframedScene() {
  return Json::parse(R"({
    "frames": 3,
    "objects": [
      {"name": "a", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6}},
      {"name": "b", "shape": {"generator": "sphere", "radius": 0.5, "slices": 12, "stacks": 6},
       "motion": {"poses": [
         {"translation": [3, 0.2, 0.1], "rotation": {"axis": [1, 0, 0], "degrees": 4}},
         {"translation": [3.5, 0.2, 0.1], "rotation": {"axis": [1, 0, 0], "degrees": 4}},
         {"translation": [4, 0.2, 0.1], "rotation": {"axis": [0, 0, 1], "degrees": 30}}]}},
      {"name": "c", "shape": {"generator": "sphere", "radius": 0.5, "slices": 8, "stacks": 4},
       "pose": {"translation": [0, 5, 0]}}
    ],
    "constraints": {
      "fixed": ["a"],
      "variables": [{"name": "gap", "value": 0.25, "fixed": true}],
      "list": [
        {"name": "on axis", "type": "point_on_line", "p": {"object": "b", "at": [0, 0, 0]},
         "line": {"at": [0, 0, 0], "direction": [1, 0, 0]}},
        {"name": "upright", "type": "parallel", "d": {"object": "b", "direction": [0, 0, 1]},
         "e": {"direction": [0, 0, 1]}},
        {"name": "gap held", "type": "clearance", "a": "a", "b": "b", "variable": "gap"}
      ]
    },
    "queries": [{"name": "q", "a": "a", "b": "b", "kind": "distance"}]
  })");
}

TEST(ConstraintScene, SolvesAtLoadAndMovesTheWholeMotion) {
  const Json document = keyframedScene();
  Json unconstrained = document;
  unconstrained.erase("constraints");
  const Result<Scene> before = parseScene(unconstrained.dump(), "s.json", ".");
  const Result<Scene> after = parseScene(document.dump(), "s.json", ".");
  ASSERT_TRUE(before.ok() && after.ok()) << after.status().toString();
  const Scene& scene = after.value();
  ASSERT_TRUE(scene.placement.has_value());
  EXPECT_EQ(scene.placement->moved, std::vector<std::size_t>{1});
  // Frame 0 meets the constraints: on the axis, upright, and the exact gap.
  const Pose& b0 = scene.objects[1].poses[0];
  EXPECT_NEAR(b0.translation().y(), 0.0, 1e-12);
  EXPECT_NEAR(b0.translation().z(), 0.0, 1e-12);
  EXPECT_NEAR((b0.linear() * Eigen::Vector3d::UnitZ()).z(), 1.0, 1e-12);
  const MeshDistance gap = exactMeshDistance(*scene.objects[0].mesh, scene.objects[0].poses[0],
                                             *scene.objects[1].mesh, b0);
  EXPECT_NEAR(gap.distance, 0.25, 1e-12);
  ASSERT_EQ(scene.placement->clearances.size(), 1u);
  EXPECT_EQ(scene.placement->clearances[0].second, gap.distance);
  // Every frame moved by the same correction; the others are untouched, bit for bit.
  const Pose& correction = scene.placement->corrections[0];
  for (std::size_t f = 0; f < 3; ++f) {
    const Pose expected = correction * before.value().objects[1].poses[f];
    EXPECT_LT((scene.objects[1].poses[f].matrix() - expected.matrix()).cwiseAbs().maxCoeff(), 1e-14)
        << "frame " << f;
  }
  for (std::size_t object : {0u, 2u}) {
    EXPECT_EQ(scene.objects[object].poses[0].matrix(),
              before.value().objects[object].poses[0].matrix());
  }
}

// A placement store gives the scene the solve would, bit for bit; another block is solved anew,
// and a damaged file costs a solve, never a wrong placement.
TEST(ConstraintScene, AStoredSolveGivesTheSolvedScene) {
  const std::string store = test::makeTempDirectory("placement_store") + "/placements";
  SceneLoadOptions stored;
  stored.placement_store = store;
  const std::string text = keyframedScene().dump();
  const Result<Scene> solved = parseScene(text, "s.json", ".");
  const Result<Scene> first = parseScene(text, "s.json", ".", stored);
  ASSERT_TRUE(solved.ok() && first.ok()) << first.status().toString();
  ASSERT_EQ(std::distance(std::filesystem::directory_iterator(store), {}), 1);
  const std::string file = std::filesystem::directory_iterator(store)->path().string();
  const auto expectSame = [&](const Scene& scene) {
    for (std::size_t object = 0; object < 3; ++object) {
      for (std::size_t f = 0; f < scene.objects[object].poses.size(); ++f) {
        EXPECT_EQ(scene.objects[object].poses[f].matrix(),
                  solved.value().objects[object].poses[f].matrix())
            << "object " << object << ", frame " << f;
      }
    }
    const ScenePlacement& want = *solved.value().placement;
    const ScenePlacement& got = *scene.placement;
    EXPECT_EQ(got.moved, want.moved);
    EXPECT_EQ(got.corrections[0].matrix(), want.corrections[0].matrix());
    EXPECT_EQ(got.variables, want.variables);
    EXPECT_EQ(got.clearances, want.clearances);
    EXPECT_EQ(got.iterations, want.iterations);
    EXPECT_EQ(got.change, want.change);
  };
  const Result<Scene> again = parseScene(text, "s.json", ".", stored);
  ASSERT_TRUE(again.ok());
  expectSame(again.value());

  Json other = keyframedScene();
  other["constraints"]["variables"][0]["value"] = 0.3;
  ASSERT_TRUE(parseScene(other.dump(), "s.json", ".", stored).ok());
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(store), {}), 2);

  test::writeFile(file, R"({"format": "collido-placement-1", "body_poses": [[1, 2]]})");
  const Result<Scene> damaged = parseScene(text, "s.json", ".", stored);
  ASSERT_TRUE(damaged.ok());
  expectSame(damaged.value());
}

TEST(ConstraintScene, TheWrittenBackSceneIsAlreadySolved) {
  const std::string directory = test::makeTempDirectory("placed_scene");
  const std::string path = directory + "/scene.json";
  test::writeFile(path, keyframedScene().dump(1));
  const Result<std::string> placed = placedSceneText(path);
  ASSERT_TRUE(placed.ok()) << placed.status().toString();
  const Result<Scene> first = loadScene(path);
  const Result<Scene> again = parseScene(placed.value(), "placed.json", directory);
  ASSERT_TRUE(first.ok() && again.ok()) << again.status().toString();
  EXPECT_LT(again.value().placement->change, 1e-9);
  for (std::size_t f = 0; f < 3; ++f) {
    EXPECT_LT(
        (again.value().objects[1].poses[f].matrix() - first.value().objects[1].poses[f].matrix())
            .cwiseAbs()
            .maxCoeff(),
        1e-12);
  }
  // Written as a matrix pose, frame 0 reads back bit for bit.
  const Json written = Json::parse(placed.value());
  EXPECT_TRUE(written["objects"][1]["motion"]["poses"][0]["rotation"].contains("matrix"));
}

TEST(ConstraintScene, APlacedContactSceneReloadsWithoutAChange) {
  // The stacked parts touch (clearance 0): reloaded, each contact is found to touch (a rounding
  // step parts it) and nothing moves.
  const std::string directory = test::makeTempDirectory("placed_contact");
  const Result<std::string> placed =
      placedSceneText(test::sourcePath("scenes") + "/stacked_parts.json");
  ASSERT_TRUE(placed.ok()) << placed.status().toString();
  const Result<Scene> again = parseScene(placed.value(), "placed.json", test::sourcePath("scenes"));
  ASSERT_TRUE(again.ok()) << again.status().toString();
  EXPECT_LT(again.value().placement->change, 1e-9);
  for (const auto& [name, distance] : again.value().placement->clearances)
    EXPECT_EQ(distance, 0.0) << name;
}

TEST(ConstraintScene, ASceneWithoutConstraintsHasNothingToWriteBack) {
  const std::string path = test::sourcePath("scenes") + "/bunny_vs_bunny.json";
  const Result<std::string> placed = placedSceneText(path);
  ASSERT_FALSE(placed.ok());
  EXPECT_NE(placed.status().message().find("no 'constraints' block"), std::string::npos);
}

/// The bundled constrained scenes meet their clearances exactly, by the oracle's distance.
TEST(ConstraintScene, BundledScenesMeetTheirClearances) {
  const struct {
    const char* file;
    std::vector<double> clearances;
  } cases[] = {{"station_docking_clearance.json", {1e-4}},
               {"gears_at_backlash.json", {2e-4}},
               {"stacked_parts.json", {0.0, 0.0}}};
  for (const auto& c : cases) {
    const Result<Scene> scene = loadScene(test::sourcePath("scenes") + "/" + c.file);
    ASSERT_TRUE(scene.ok()) << scene.status().toString();
    ASSERT_TRUE(scene.value().placement.has_value()) << c.file;
    const auto& measured = scene.value().placement->clearances;
    ASSERT_EQ(measured.size(), c.clearances.size()) << c.file;
    for (std::size_t k = 0; k < measured.size(); ++k) {
      EXPECT_NEAR(measured[k].second, c.clearances[k], 1e-12) << c.file << " " << measured[k].first;
    }
  }
}

}  // namespace
}  // namespace collido
