// Deformable scenes end to end: states and movable nodes load, change the shape frame by frame,
// enter the oracle's fingerprint, and the OBB tree (updated every frame) answers exactly.
#include <collido/scene/scene.h>

#include <map>
#include <string>

#include <gtest/gtest.h>

#include <collido/runner/runner.h>

#include "support/runs/run_plugin.h"
#include "support/test_paths.h"

namespace collido {
namespace {

Scene load(const std::string& relative, double resolution = 1.0) {
  SceneLoadOptions options;
  options.resolution = resolution;
  Result<Scene> scene = loadScene(test::sourcePath(relative), options);
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  return scene.ok() ? std::move(scene).value() : Scene{};
}

// Two objects: "a" switches between a unit sphere (state 0) and a sphere of radius 0.1
// (state 1); "b", a sphere at x = 1.5, meets only the large one.
std::string statesScene(const std::string& schedule) {
  return R"({"name": "states", "frames": 4, "objects": [
    {"name": "a", "states": [
       {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6},
       {"generator": "sphere", "radius": 0.1, "slices": 12, "stacks": 6}])" +
         schedule + R"(},
    {"name": "b", "shape": {"generator": "sphere", "radius": 0.6, "slices": 12, "stacks": 6},
     "pose": {"translation": [1.5, 0, 0]}}],
   "queries": [{"name": "all", "a": "a", "b": "b", "kind": "all_pairs"},
               {"name": "any", "a": "a", "b": "b", "kind": "boolean"}]})";
}

std::vector<std::size_t> scheduleOf(const std::string& schedule) {
  Result<Scene> scene = parseScene(statesScene(schedule), "states.json", ".");
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  return scene.ok() ? scene.value().objects[0].schedule : std::vector<std::size_t>{};
}

TEST(DeformableScene, SchedulesOfActiveStates) {
  EXPECT_EQ(scheduleOf(""), (std::vector<std::size_t>{0, 0, 1, 1}));
  EXPECT_EQ(scheduleOf(R"(, "schedule": [1, 0, 1, 1])"), (std::vector<std::size_t>{1, 0, 1, 1}));
  EXPECT_EQ(scheduleOf(R"(, "schedule": {"hold": 1})"), (std::vector<std::size_t>{0, 1, 0, 1}));
}

TEST(DeformableScene, BundledScenesDeformEveryFrame) {
  for (const auto& [name, index] :
       {std::pair<const char*, std::size_t>{"scenes/deforming_tori.json", 0},
        {"scenes/squeezed_sphere.json", 0},
        {"scenes/sheet_over_bunny.json", 1},
        {"scenes/station_panels_arm.json", 2}}) {
    SCOPED_TRACE(name);
    const Scene scene = load(name);
    ASSERT_GT(scene.objects.size(), index);
    const SceneObject& object = scene.objects[index];
    ASSERT_TRUE(object.changesShape());
    EXPECT_TRUE(scene.needsOf(index).deforms);
    const auto first = object.shapeAt(1);
    const auto second = object.shapeAt(2);
    EXPECT_EQ(first->triangles, object.mesh->triangles);
    EXPECT_NE(first->vertices, second->vertices);
    EXPECT_EQ(object.shapeAt(1)->vertices, first->vertices);  // frames are pure functions
  }
}

RunReport runBackend(const Scene& scene, const std::string& plugin, const std::string& variant,
                     const std::map<std::string, std::string>& backend_options = {}) {
  return test::runPlugin(scene, plugin, variant, test::repeated(1), backend_options);
}

RunReport runObbTree(const Scene& scene) {
  return runBackend(scene, "obbtree", "obbtree");
}

// A sheet 1 unit above a unit sphere drapes onto it: the vertex over the pole (a vertex of the
// sphere, at z = 1) stops 0.01 inside it; one beyond the sphere falls the whole drop.
TEST(DeformableScene, DrapeStopsOnTheSurfacePlusThePenetration) {
  const std::string text = R"({"name": "drape", "frames": 5, "objects": [
    {"name": "ball", "shape": {"generator": "sphere", "radius": 1, "slices": 16, "stacks": 8}},
    {"name": "sheet",
     "shape": {"generator": "grid_sheet", "width": 4, "depth": 4, "cells_x": 4, "cells_y": 4},
     "pose": {"translation": [0, 0, 2]},
     "deform": {"rules": [{"drape": {"onto": "ball", "direction": [0, 0, -1], "drop": 3,
                                     "penetration": 0.01, "ramp": true}}]}}],
    "queries": [{"name": "q", "a": "ball", "b": "sheet", "kind": "all_pairs"}]})";
  Result<Scene> scene = parseScene(text, "drape.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const SceneObject& sheet = scene.value().objects[1];
  // Vertex i + 5 j of the 4 x 4 sheet is at (-2 + i, -2 + j): the centre is vertex 12, a
  // corner vertex 0 at (-2, -2), beyond the ball.
  const auto last = sheet.shapeAt(4);
  EXPECT_NEAR(last->vertices(2, 12), 1.0 - 2.0 - 0.01, 1e-12);  // in the sheet's frame (z - 2)
  EXPECT_NEAR(last->vertices(2, 0), -3.0, 1e-12);
  const auto half = sheet.shapeAt(2);  // half the drop, 1.5: the centre has landed already
  EXPECT_NEAR(half->vertices(2, 12), -1.01, 1e-12);
  EXPECT_NEAR(half->vertices(2, 0), -1.5, 1e-12);
  const RunReport report = runBackend(scene.value(), "obbtree", "obbtree");
  ASSERT_EQ(report.measurements.size(), 1u);
  EXPECT_EQ(report.measurements[0].disagreements, 0u);
  EXPECT_TRUE(report.measurements[0].frames.back().oracle_intersecting);
}

TEST(DeformableScene, TheFingerprintFollowsTheDeformation) {
  Scene scene = load("scenes/squeezed_sphere.json", 0.25);
  const std::string before = OracleCache(scene).fingerprint();
  auto changed = std::make_shared<Deformation>(*scene.objects[0].deformation);
  changed->rules[0].amount = 0.3;
  scene.objects[0].deformation = changed;
  EXPECT_NE(OracleCache(scene).fingerprint(), before);
}

TEST(DeformableScene, ObbTreeIsExactOnEveryDeformedFrame) {
  for (const char* name : {"scenes/deforming_tori.json", "scenes/squeezed_sphere.json"}) {
    SCOPED_TRACE(name);
    const RunReport report = runObbTree(load(name, 0.25));
    ASSERT_FALSE(report.measurements.empty());
    for (const QueryMeasurement& m : report.measurements) {
      SCOPED_TRACE(m.query);
      ASSERT_TRUE(m.ok()) << m.status;
      EXPECT_EQ(m.disagreements, 0u);
      ASSERT_TRUE(m.update_median_us.has_value());
      EXPECT_EQ(m.update_rebuilds, std::optional<std::uint64_t>(0));  // rebuild_ratio 0: never
      std::size_t intersecting = 0;
      for (const FrameRecord& f : m.frames) {
        EXPECT_TRUE(f.update_us.has_value());
        EXPECT_TRUE(f.update_work.counted);
        // Frame 0 is the rest shape the model was built from: nothing moved.
        if (f.frame > 0) {
          EXPECT_GT(f.update_work.nodes_refit, 0u) << "frame " << f.frame;
        }
        intersecting += f.oracle_intersecting ? 1 : 0;
      }
      EXPECT_GT(intersecting, 0u);  // the scenes are in contact
    }
  }
}

TEST(DeformableScene, SwitchingStatesSelectsTheStatesModel) {
  Result<Scene> scene = parseScene(statesScene(R"(, "schedule": [0, 1, 1, 0])"), "s.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const RunReport report = runObbTree(scene.value());
  for (const QueryMeasurement& m : report.measurements) {
    ASSERT_TRUE(m.ok()) << m.status;
    ASSERT_EQ(m.frames.size(), 4u);
    EXPECT_EQ(m.disagreements, 0u);
    EXPECT_TRUE(m.frames[0].oracle_intersecting);
    EXPECT_FALSE(m.frames[1].oracle_intersecting);
    EXPECT_FALSE(m.frames[2].reported_intersecting);
    EXPECT_TRUE(m.frames[3].reported_intersecting);
    EXPECT_FALSE(m.frames[0].update_us.has_value());  // states only: nothing to update
  }
}

// Two states with one triangle list: the second is built as the first's sibling and shares its
// leaf order, so both states' trees hold less than two trees on their own, and answer the same.
TEST(DeformableScene, StatesWithOneTriangleListShareTheirTreesOrder) {
  Result<Scene> scene = parseScene(statesScene(R"(, "schedule": [0, 1, 1, 0])"), "s.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const RunReport shared = runObbTree(scene.value());
  const RunReport apart =
      runBackend(scene.value(), "obbtree", "obbtree", {{"share_states", "false"}});
  ASSERT_EQ(shared.measurements.size(), apart.measurements.size());
  for (std::size_t i = 0; i < shared.measurements.size(); ++i) {
    const QueryMeasurement& m = shared.measurements[i];
    ASSERT_TRUE(m.ok() && apart.measurements[i].ok()) << m.status;
    EXPECT_EQ(m.disagreements, 0u);
    // Object a's second state shares the leaf order and ids: 10 bytes a triangle (16-bit
    // vertex indices on this small mesh, 32-bit ids).
    const std::size_t triangles = scene.value().objects[0].mesh->triangleCount();
    EXPECT_LE(m.memory_bytes + 10 * triangles, apart.measurements[i].memory_bytes) << m.query;
  }
}

// FCL's refit of RSS and AABB trees answers wrongly after deformation (recorded in the
// conformance expectations); rebuilding instead, FCL's other way to update, answers exactly.
#ifdef COLLIDO_HAS_ODE
// ODE's two ways to update: refit (dGeomTriMeshDataUpdate) and rebuild; each says which it did.
TEST(DeformableScene, OdeCountsItsRefitsAndRebuilds) {
  const Scene scene = load("scenes/deforming_tori.json", 0.25);
  for (const bool rebuild : {false, true}) {
    SCOPED_TRACE(rebuild ? "rebuild" : "refit");
    const RunReport report =
        runBackend(scene, "ode", "ode", {{"rebuild", rebuild ? "true" : "false"}});
    ASSERT_FALSE(report.measurements.empty());
    for (const QueryMeasurement& m : report.measurements) {
      if (m.status.skipped()) continue;  // ODE answers no all_pairs
      ASSERT_TRUE(m.ok()) << m.status;
      ASSERT_TRUE(m.update_rebuilds.has_value());
      for (const FrameRecord& f : m.frames) {
        ASSERT_TRUE(f.update_work.counted);
        EXPECT_EQ(f.update_work.nodes_rebuilt > 0, rebuild) << "frame " << f.frame;
        EXPECT_EQ(f.update_work.nodes_refit > 0, !rebuild) << "frame " << f.frame;
      }
      EXPECT_EQ(*m.update_rebuilds > 0, rebuild);
    }
  }
}
#endif

#ifdef COLLIDO_HAS_FCL
TEST(DeformableScene, FclRebuildOnUpdateIsExact) {
  const Scene scene = load("scenes/deforming_tori.json", 0.25);
  for (const char* variant : {"fcl:aabb", "fcl:obb"}) {
    SCOPED_TRACE(variant);
    const RunReport report = runBackend(scene, "fcl", variant, {{"rebuild", "true"}});
    ASSERT_FALSE(report.measurements.empty());
    for (const QueryMeasurement& m : report.measurements) {
      ASSERT_TRUE(m.ok()) << m.status;
      EXPECT_EQ(m.disagreements, 0u) << m.query;
      // One rebuild a frame for each deforming object.
      ASSERT_TRUE(m.update_rebuilds.has_value());
      EXPECT_GE(*m.update_rebuilds, m.frames.size()) << m.query;
    }
  }
}
#endif

}  // namespace
}  // namespace collido
