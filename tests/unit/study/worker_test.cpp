// What a worker does with one combination, in this process: scene resolution, answer limits,
// build needs and the finest truth. Also the scene load option it relies on.
#include <collido/study/worker.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <collido/scene/scene.h>

#include "support/test_paths.h"

namespace collido::study {
namespace {

std::size_t triangles(const Scene& scene) {
  std::size_t n = 0;
  for (const SceneObject& o : scene.objects)
    n += o.mesh->triangleCount();
  return n;
}

/// Two thick tori linked through each other (always intersecting), 3 jittered frames.
std::string writeSmallScene() {
  const std::string path = test::makeTempDirectory("worker_scene") + "/linked.json";
  test::writeFile(path, R"({
    "name": "linked",
    "frames": 3,
    "objects": [
      {"name": "a", "shape": {"generator": "torus", "minor_radius": 0.4,
                              "major_segments": 24, "minor_segments": 12}},
      {"name": "b", "shape": {"generator": "torus", "minor_radius": 0.4,
                              "major_segments": 24, "minor_segments": 12},
       "pose": {"translation": [1.5, 0, 0], "rotation": {"axis": [1, 0, 0], "degrees": 90}},
       "motion": {"jitter": {"seed": 5, "translation": 0.05, "rotation_deg": 5}}}
    ],
    "queries": [
      {"name": "pairs", "a": "a", "b": "b", "kind": "all_pairs"},
      {"name": "hit", "a": "a", "b": "b", "kind": "boolean"}
    ]})");
  return path;
}

TEST(SceneResolution, ScalesGeneratorSampleCounts) {
  const std::string path = test::sourcePath("scenes/interlocked_tori.json");
  const Result<Scene> full = loadScene(path);
  const Result<Scene> half = loadScene(path, SceneLoadOptions{0.5});
  const Result<Scene> tiny = loadScene(path, SceneLoadOptions{0.001});
  ASSERT_TRUE(full.ok()) << full.status().message();
  ASSERT_TRUE(half.ok()) << half.status().message();
  ASSERT_TRUE(tiny.ok()) << tiny.status().message();
  EXPECT_EQ(full.value().resolution, 1.0);
  EXPECT_EQ(half.value().resolution, 0.5);
  EXPECT_TRUE(full.value().hasGeneratedShapes());
  // 64 x 32 segments, two triangles per quad: 4096 per torus; half of each count: 1024.
  EXPECT_EQ(triangles(full.value()), 2u * 4096u);
  EXPECT_EQ(triangles(half.value()), 2u * 1024u);
  EXPECT_LT(triangles(half.value()), triangles(full.value()));
  // Never below the generator's minimum (3 segments each way).
  EXPECT_EQ(triangles(tiny.value()), 2u * 2u * 3u * 3u);
  // Only the meshes change: frames, queries and poses are the scene's.
  EXPECT_EQ(half.value().frames, full.value().frames);
  ASSERT_EQ(half.value().objects.size(), full.value().objects.size());
  for (std::size_t i = 0; i < full.value().objects.size(); ++i) {
    ASSERT_EQ(half.value().objects[i].poses.size(), full.value().objects[i].poses.size());
    for (std::size_t f = 0; f < full.value().objects[i].poses.size(); ++f) {
      EXPECT_TRUE(half.value().objects[i].poses[f].isApprox(full.value().objects[i].poses[f]))
          << "object " << i << " frame " << f;
    }
  }
}

TEST(SceneResolution, MeshFilesAreReadAsTheyAre) {
  const std::string path = test::sourcePath("scenes/env_rob.json");
  const Result<Scene> full = loadScene(path);
  const Result<Scene> half = loadScene(path, SceneLoadOptions{0.5});
  ASSERT_TRUE(full.ok()) << full.status().message();
  ASSERT_TRUE(half.ok()) << half.status().message();
  EXPECT_FALSE(full.value().hasGeneratedShapes());
  EXPECT_EQ(triangles(half.value()), triangles(full.value()));
  EXPECT_EQ(triangles(full.value()), 2180u + 216u);
}

TEST(SceneResolution, RefusesNonPositiveResolutions) {
  const std::string path = test::sourcePath("scenes/interlocked_tori.json");
  for (const double resolution : {0.0, -1.0, std::nan("")}) {
    const Result<Scene> scene = loadScene(path, SceneLoadOptions{resolution});
    ASSERT_FALSE(scene.ok()) << resolution;
    EXPECT_NE(scene.status().message().find(path), std::string::npos);
    EXPECT_NE(scene.status().message().find("resolution"), std::string::npos);
  }
}

Combination smallCombination(const std::string& backend) {
  Combination c;
  c.id = "linked~test";
  c.scene_path = writeSmallScene();
  c.scene_name = "linked";
  c.backend = backend;
  return c;
}

WorkerRequest requestFor(const Combination& c) {
  WorkerRequest request;
  request.combination = c;
  request.plugin_paths = {test::pluginDirectory()};
  request.default_plugins = false;
  request.repetitions = 1;
  return request;
}

TEST(RunCombination, MeasuresEveryQueryAgainstTheOracle) {
  WorkerRequest request = requestFor(smallCombination("obbtree"));
  std::vector<std::pair<std::size_t, std::size_t>> progress;
  request.progress = [&progress](std::size_t done, std::size_t total) {
    progress.emplace_back(done, total);
  };
  const Result<CombinationResult> result = runCombination(request);
  ASSERT_TRUE(result.ok()) << result.status().message();
  EXPECT_EQ(result.value().combination.id, "linked~test");
  EXPECT_EQ(result.value().outcome.status, WorkerStatus::kOk);
  ASSERT_EQ(result.value().measurements.size(), 2u);
  for (const QueryMeasurement& m : result.value().measurements) {
    SCOPED_TRACE(m.query);
    EXPECT_EQ(m.status, "ok");
    EXPECT_EQ(m.backend, "obbtree");
    EXPECT_EQ(m.frames.size(), 3u);
    // One repetition per frame is raised to the 12 timed calls a round every query gets.
    EXPECT_EQ(m.times_us.size(), 12u);
    EXPECT_EQ(m.disagreements, 0u);
    EXPECT_EQ(m.triangles, 2u * 2u * 24u * 12u);
    EXPECT_FALSE(m.finest_disagreements.has_value());  // at resolution 1 there is no coarser mesh
    for (const FrameRecord& f : m.frames) {
      EXPECT_TRUE(f.oracle_intersecting);
      EXPECT_FALSE(f.truncated);
    }
  }
  ASSERT_EQ(progress.size(), 6u);
  EXPECT_EQ(progress.front(), std::make_pair(std::size_t{1}, std::size_t{6}));
  EXPECT_EQ(progress.back(), std::make_pair(std::size_t{6}, std::size_t{6}));
}

TEST(RunCombination, CoarseResolutionIsJudgedAgainstTheFinestMesh) {
  Combination c = smallCombination("obbtree");
  c.resolution = 0.5;
  const Result<CombinationResult> result = runCombination(requestFor(c));
  ASSERT_TRUE(result.ok()) << result.status().message();
  ASSERT_EQ(result.value().measurements.size(), 2u);
  for (const QueryMeasurement& m : result.value().measurements) {
    SCOPED_TRACE(m.query);
    EXPECT_EQ(m.status, "ok");
    EXPECT_EQ(m.triangles, 2u * 2u * 12u * 6u);
    EXPECT_EQ(m.disagreements, 0u);  // against the oracle on the coarse meshes themselves
    ASSERT_TRUE(m.finest_disagreements.has_value());
    EXPECT_EQ(*m.finest_disagreements, 0u);  // deeply linked at every resolution
    for (const FrameRecord& f : m.frames)
      EXPECT_EQ(f.finest_intersecting, true);
  }
}

TEST(RunCombination, LimitCapsAllPairsAnswers) {
  Combination c = smallCombination("obbtree");
  c.limit = 2;
  c.needs = NeedsMode::kEvery;
  const Result<CombinationResult> result = runCombination(requestFor(c));
  ASSERT_TRUE(result.ok()) << result.status().message();
  const QueryMeasurement& pairs = result.value().measurements.at(0);
  ASSERT_EQ(pairs.kind, QueryKind::kAllPairs);
  EXPECT_EQ(pairs.status, "ok");
  EXPECT_EQ(pairs.disagreements, 0u);  // a truncated answer with only real pairs is right
  for (const FrameRecord& f : pairs.frames) {
    EXPECT_GT(f.oracle_pairs, 2u);
    EXPECT_TRUE(f.truncated);
    EXPECT_EQ(f.reported_pairs, 2u);
  }
}

TEST(RunCombination, BadInputIsAnError) {
  const Result<CombinationResult> unknown = runCombination(requestFor(smallCombination("nope")));
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.status().message().find("nope"), std::string::npos)
      << unknown.status().message();
  Combination missing = smallCombination("obbtree");
  missing.scene_path += ".missing";
  const Result<CombinationResult> scene = runCombination(requestFor(missing));
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.status().message().find(missing.scene_path), std::string::npos);
}

}  // namespace
}  // namespace collido::study
