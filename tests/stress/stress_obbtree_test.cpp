// The OBB tree held to the exact oracle on every case of every category's bundled stress scene
// (scenes/stress/<category>.json, the cases the study runs): the same intersecting triangle pairs,
// and the same boolean answer with a witness pair that really intersects, at leaf sizes 1 and 4
// with double and float boxes, and on the distance category the distance too. The bar is
// zero wrong answers in every category; a failure names the cases and how they differ.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <collido/obbtree/collide.h>
#include <collido/obbtree/distance.h>
#include <collido/obbtree/tree.h>
#include <collido/oracle/distance_oracle.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/scene/scene.h>
#include <collido/stress/stress_cases.h>

#include "stress_test_support.h"
#include "support/test_paths.h"

namespace collido::stress {
namespace {

struct TreeSetting {
  int max_leaf_triangles;
  bool float_boxes;
};

// Leaf sizes 1 and 4, double and float boxes: each case's exact answer is computed once, for all.
constexpr TreeSetting kSettings[] = {{1, false}, {1, true}, {4, false}, {4, true}};

// "leaf 4, float boxes", in a failure's report.
std::string settingText(const TreeSetting& s) {
  return "leaf " + std::to_string(s.max_leaf_triangles) +
         (s.float_boxes ? ", float boxes" : ", double boxes");
}

std::string paramName(const ::testing::TestParamInfo<Category>& info) {
  return categoryName(info.param);
}

std::vector<TrianglePair> sortedPairs(const obbtree::CollideResult& result) {
  std::vector<TrianglePair> pairs;
  for (const obbtree::TrianglePair& p : result.pairs)
    pairs.push_back({p.a, p.b});
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// What the OBB tree built with `setting` gets wrong on one case, against the exact answers
// `truth` (and `exact_distance` on the distance category); empty when nothing.
std::string problemsOf(const SceneObject& a, const Pose& pose_a, const SceneObject& b,
                       const Pose& pose_b, const OracleAnswer& truth,
                       const std::optional<double>& exact_distance, const TreeSetting& setting) {
  obbtree::BuildOptions options;
  options.max_leaf_triangles = setting.max_leaf_triangles;
  options.float_boxes = setting.float_boxes;
  const obbtree::ObbTree tree_a =
      obbtree::ObbTree::build(a.mesh->vertices, a.mesh->triangles, options);
  const obbtree::ObbTree tree_b =
      obbtree::ObbTree::build(b.mesh->vertices, b.mesh->triangles, options);

  obbtree::CollideResult all;
  obbtree::collide(tree_a, pose_a, tree_b, pose_b, {obbtree::CollideMode::kAllPairs, 0}, all);
  const std::vector<TrianglePair> pairs = sortedPairs(all);
  std::vector<TrianglePair> missed;
  std::vector<TrianglePair> extra;
  std::set_difference(truth.pairs.begin(), truth.pairs.end(), pairs.begin(), pairs.end(),
                      std::back_inserter(missed));
  std::set_difference(pairs.begin(), pairs.end(), truth.pairs.begin(), truth.pairs.end(),
                      std::back_inserter(extra));
  const bool repeated = std::adjacent_find(pairs.begin(), pairs.end()) != pairs.end();

  obbtree::CollideResult first;
  obbtree::collide(tree_a, pose_a, tree_b, pose_b, {obbtree::CollideMode::kFirstHit, 0}, first);
  const bool says_intersecting = !first.pairs.empty();
  const bool false_witness =
      says_intersecting && !exactPairIntersects(*a.mesh, pose_a, *b.mesh, pose_b,
                                                TrianglePair{first.pairs[0].a, first.pairs[0].b});

  // The distance category: 0 exactly on contact, an interval holding the exact distance, and
  // the value within the documented 2^-19 of it (collido/obbtree/distance.h).
  std::string distance_problem;
  if (exact_distance) {
    const double exact = *exact_distance;
    obbtree::DistanceAnswer d;
    obbtree::distance(tree_a, pose_a, tree_b, pose_b, obbtree::DistanceRequest{}, d);
    const double ulps = 4.0 * 0x1p-53 * exact;  // the reference is within two ulps
    if ((d.distance == 0.0) != (exact == 0.0) || d.lower_bound > exact + ulps ||
        d.upper_bound < exact - ulps || d.distance < d.lower_bound || d.distance > d.upper_bound ||
        std::abs(d.distance - exact) > 0x1p-19 * exact + ulps) {
      std::ostringstream text;
      text.precision(17);
      text << "; distance " << d.distance << " in [" << d.lower_bound << ", " << d.upper_bound
           << "], exact " << exact;
      distance_problem = text.str();
    }
  }
  if (missed.empty() && extra.empty() && !repeated && says_intersecting == truth.intersecting &&
      !false_witness && distance_problem.empty()) {
    return "";
  }
  std::ostringstream report;
  report << a.name.substr(0, a.name.size() - 2) << " (" << settingText(setting) << "): oracle "
         << (truth.intersecting ? "intersecting" : "apart") << " with " << truth.pairs.size()
         << " pairs; all pairs missed " << missed.size() << ", extra " << extra.size()
         << (repeated ? ", repeated pairs" : "") << "; boolean "
         << (says_intersecting ? "intersecting" : "apart")
         << (false_witness ? " (witness does not intersect)" : "") << distance_problem;
  return report.str();
}

class StressObbTree : public ::testing::TestWithParam<Category> {};

TEST_P(StressObbTree, AnswersLikeTheOracle) {
  const Category category = GetParam();
  const std::string path =
      collido::test::sourcePath(std::string("scenes/stress/") + categoryName(category) + ".json");
  Result<Scene> loaded = loadScene(path);
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  const Scene& scene = loaded.value();
  ASSERT_EQ(scene.category, categoryName(category));

  std::size_t cases = 0;
  std::size_t wrong = 0;
  std::ostringstream report;
  for (const SceneQuery& query : scene.queries) {
    if (query.request.kind != QueryKind::kBoolean) continue;
    ++cases;
    const SceneObject& a = scene.objects[query.a];
    const SceneObject& b = scene.objects[query.b];
    const Pose& pose_a = a.poseAt(0);
    const Pose& pose_b = b.poseAt(0);
    const OracleAnswer truth = exactIntersectingPairs(*a.mesh, pose_a, *b.mesh, pose_b);
    std::optional<double> exact_distance;
    if (category == Category::kDistance)
      exact_distance = exactMeshDistance(*a.mesh, pose_a, *b.mesh, pose_b).distance;
    for (const TreeSetting& setting : kSettings) {
      const std::string problems = problemsOf(a, pose_a, b, pose_b, truth, exact_distance, setting);
      if (!problems.empty() && ++wrong <= 12) report << "  " << problems << "\n";
    }
  }
  EXPECT_GT(cases, 0u);
  EXPECT_EQ(wrong, 0u) << wrong << " of " << cases << " " << categoryName(category)
                       << " cases times " << std::size(kSettings)
                       << " tree settings answered differently from the oracle (first 12):\n"
                       << report.str();
}

INSTANTIATE_TEST_SUITE_P(EveryCategory, StressObbTree, ::testing::ValuesIn(allCategories()),
                         paramName);

// Every category has its bundled scene, which the study and the test above run.
TEST(StressScenes, OneSceneFileForEveryCategory) {
  for (const Category category : allCategories()) {
    const std::string path =
        collido::test::sourcePath(std::string("scenes/stress/") + categoryName(category) + ".json");
    Result<Scene> scene = loadScene(path);
    ASSERT_TRUE(scene.ok()) << scene.status().message();
    EXPECT_EQ(scene.value().category, categoryName(category));
    EXPECT_EQ(scene.value().frames, 1u);
    EXPECT_EQ(scene.value().objects.size(), scene.value().queries.size());
    EXPECT_GE(scene.value().queries.size(), 2u * 24u) << path << ": a few dozen cases";
  }
}

}  // namespace
}  // namespace collido::stress
