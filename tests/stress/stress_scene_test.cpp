// The scene format's "stress" block: it expands into exactly the generator's cases (two objects
// and two queries per case, one frame), and every mistake in it fails at load naming the JSON
// path.
#include <initializer_list>
#include <string>

#include <gtest/gtest.h>

#include <collido/scene/scene.h>
#include <collido/stress/stress_cases.h>

#include "stress_test_support.h"
#include "support/test_paths.h"

namespace collido::stress {
namespace {

Result<Scene> parse(const std::string& text) {
  return parseScene(text, "stress.json", collido::test::sourcePath("scenes/stress"));
}

// The load fails and its message holds every one of `parts`.
void expectRejected(const std::string& text, std::initializer_list<const char*> parts) {
  const Result<Scene> scene = parse(text);
  ASSERT_FALSE(scene.ok()) << text;
  for (const char* part : parts) {
    EXPECT_NE(scene.status().message().find(part), std::string::npos)
        << "message lacks \"" << part << "\": " << scene.status().message();
  }
}

TEST(StressScene, ExpandsIntoTheGeneratorsCases) {
  const Result<Scene> loaded = parse(R"({"name": "s", "stress": {"category": "degenerate",
      "severities": [0, 9], "cases_per_severity": 3, "seed": 5}})");
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  const Scene& scene = loaded.value();
  EXPECT_EQ(scene.category, "degenerate");
  EXPECT_EQ(scene.frames, 1u);
  ASSERT_EQ(scene.objects.size(), 12u);
  ASSERT_EQ(scene.queries.size(), 12u);
  std::size_t at = 0;
  for (const int severity : {0, 9}) {
    const auto cases = generateStressCases(Category::kDegenerate, severity, 3, 5);
    ASSERT_TRUE(cases.ok());
    for (const StressCase& c : cases.value()) {
      const SceneObject& a = scene.objects[2 * at];
      const SceneObject& b = scene.objects[2 * at + 1];
      EXPECT_EQ(a.name, c.name + "/a");
      EXPECT_EQ(b.name, c.name + "/b");
      EXPECT_EQ(a.mesh->vertices, c.a->vertices);
      EXPECT_EQ(b.mesh->triangles, c.b->triangles);
      EXPECT_EQ(a.poseAt(0).matrix(), c.pose_a.matrix());
      EXPECT_EQ(b.poseAt(0).matrix(), c.pose_b.matrix());
      EXPECT_EQ(a.report.importer, "stress");
      const SceneQuery& pairs = scene.queries[2 * at];
      const SceneQuery& boolean = scene.queries[2 * at + 1];
      EXPECT_EQ(pairs.name, c.name + " all_pairs");
      EXPECT_EQ(pairs.request.kind, QueryKind::kAllPairs);
      EXPECT_EQ(boolean.name, c.name + " boolean");
      EXPECT_EQ(boolean.request.kind, QueryKind::kBoolean);
      EXPECT_EQ(boolean.a, 2 * at);
      EXPECT_EQ(boolean.b, 2 * at + 1);
      ++at;
    }
  }
  // Generated shapes scale with a study's resolution; stress cases must not.
  EXPECT_FALSE(scene.hasGeneratedShapes());
}

TEST(StressScene, DefaultsAreTheCategorysSeverities) {
  const Result<Scene> loaded = parse(R"({"stress": {"category": "touching"}})");
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  EXPECT_EQ(loaded.value().queries.size(), 2u * 4u * defaultSeverities(Category::kTouching).size());
  EXPECT_EQ(loaded.value().name, "stress");  // from the label, as for other scenes
}

TEST(StressScene, MeshDefectsReadsItsMeshesRelativeToTheScene) {
  const Result<Scene> loaded = parse(R"({"stress": {"category": "mesh_defects",
      "severities": [3], "cases_per_severity": 4, "meshes": ["../meshes/truck_nonmanifold.obj"]}})");
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  EXPECT_EQ(loaded.value().objects[0].mesh->triangleCount(), 4770u);
  // The mesh is shared by the cases that pose it, not copied.
  EXPECT_EQ(loaded.value().objects[0].mesh, loaded.value().objects[2].mesh);
}

TEST(StressScene, RejectsUnknownCategory) {
  expectRejected(R"({"stress": {"category": "nearly_touching"}})",
                 {"stress.json", "/stress/category", "nearly_touching", "near_touching"});
}

TEST(StressScene, RejectsMissingCategory) {
  expectRejected(R"({"stress": {"seed": 1}})", {"/stress", "missing 'category'"});
}

TEST(StressScene, RejectsUnknownKey) {
  expectRejected(R"({"stress": {"category": "scaled", "severity": [1]}})",
                 {"/stress", "unknown key 'severity'"});
}

TEST(StressScene, RejectsSeverityOutOfRange) {
  expectRejected(R"({"stress": {"category": "near_touching", "severities": [3, 19]}})",
                 {"/stress/severities/1", "19", "[1, 18]", "near_touching"});
}

TEST(StressScene, RejectsFractionalSeverity) {
  expectRejected(R"({"stress": {"category": "scaled", "severities": [1.5]}})",
                 {"/stress/severities/0", "integer"});
}

TEST(StressScene, RejectsRepeatedSeverity) {
  expectRejected(R"({"stress": {"category": "scaled", "severities": [2, -2, 2]}})",
                 {"/stress/severities/2", "twice"});
}

TEST(StressScene, RejectsEmptySeverities) {
  expectRejected(R"({"stress": {"category": "scaled", "severities": []}})",
                 {"/stress/severities", "at least one"});
}

TEST(StressScene, RejectsCaseCountOutOfRange) {
  expectRejected(R"({"stress": {"category": "scaled", "cases_per_severity": 0}})",
                 {"/stress/cases_per_severity", "[1, 1000]"});
  expectRejected(R"({"stress": {"category": "scaled", "cases_per_severity": "4"}})",
                 {"/stress/cases_per_severity", "integer"});
}

TEST(StressScene, RejectsNegativeSeed) {
  expectRejected(R"({"stress": {"category": "scaled", "seed": -1}})", {"/stress/seed"});
}

TEST(StressScene, RejectsObjectsQueriesOrFramesBesideIt) {
  expectRejected(R"({"stress": {"category": "touching"}, "frames": 2})",
                 {"/frames", "not allowed beside 'stress'"});
  expectRejected(R"({"stress": {"category": "touching"}, "objects": []})", {"/objects"});
  expectRejected(R"({"stress": {"category": "touching"}, "queries": []})", {"/queries"});
}

TEST(StressScene, MeshesOnlyForMeshDefects) {
  expectRejected(R"({"stress": {"category": "touching", "meshes": ["a.obj"]}})",
                 {"/stress/meshes", "only the mesh_defects"});
  expectRejected(R"({"stress": {"category": "mesh_defects"}})", {"/stress", "'meshes'"});
  expectRejected(R"({"stress": {"category": "mesh_defects", "meshes": []}})",
                 {"/stress/meshes", "at least one"});
}

TEST(StressScene, RejectsMissingMeshFile) {
  expectRejected(R"({"stress": {"category": "mesh_defects", "meshes": ["../meshes/none.obj"]}})",
                 {"/stress/meshes/0", "none.obj"});
}

TEST(StressScene, RespectsTheTriangleLimit) {
  SceneLoadOptions options;
  options.max_triangles = 100;
  const Result<Scene> scene =
      parseScene(R"({"stress": {"category": "touching", "cases_per_severity": 20}})", "stress.json",
                 ".", options);
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.status().message().find("/stress"), std::string::npos)
      << scene.status().message();
}

}  // namespace
}  // namespace collido::stress
