// Scene hierarchy: world poses composed through parents (keyframes, joints, fixed poses, a
// tracked parent) against hand-computed ones, the objects' file order kept when children come
// first, subtree selection, and a subtree-against-subtree query answering the union of its
// object pairs' answers.
#include <collido/scene/scene.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/runner/runner.h>
#include <collido/scene/broad_phase.h>

#include "support/runs/run_plugin.h"
#include "support/test_paths.h"

namespace collido {
namespace {

Pose translation(double x, double y, double z) {
  Pose pose = Pose::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

Pose rotation(const Eigen::Vector3d& axis, double degrees) {
  Pose pose = Pose::Identity();
  pose.linear() = Eigen::AngleAxisd(degrees * M_PI / 180.0, axis).toRotationMatrix();
  return pose;
}

void expectNear(const Pose& actual, const Pose& expected, const std::string& what) {
  EXPECT_LT((actual.matrix() - expected.matrix()).cwiseAbs().maxCoeff(), 1e-12)
      << what << "\nactual\n"
      << actual.matrix() << "\nexpected\n"
      << expected.matrix();
}

Result<Scene> parseHierarchyText(const std::string& text) {
  return parseScene(text, "hierarchy.json", ".");
}

// A hub moving by keyframes, a truss fixed on it, a link turning on the truss by a joint, and an
// unrelated sphere; the link and the truss are listed before their parents.
const char* const kChain = R"({"name": "chain", "frames": 5, "objects": [
  {"name": "link", "parent": "truss", "shape": {"generator": "box", "size": [0.2, 0.2, 1]},
   "pose": {"translation": [1, 0, 0]},
   "motion": {"joint": {"axis": [2, 0, 0], "origin": [0, 0, -0.5],
                        "keys": [{"frame": 0, "degrees": 0}, {"frame": 4, "degrees": 90}]}}},
  {"name": "truss", "parent": "hub", "shape": {"generator": "box", "size": [2, 0.2, 0.2]},
   "pose": {"translation": [0, 1, 0], "rotation": {"axis": [0, 0, 1], "degrees": 90}}},
  {"name": "hub", "shape": {"generator": "sphere", "radius": 0.5, "slices": 8, "stacks": 4},
   "motion": {"keyframes": [
     {"frame": 1, "pose": {}},
     {"frame": 3, "pose": {"translation": [4, 0, 0], "rotation": {"axis": [0, 0, 1], "degrees": 90}}}]}},
  {"name": "other", "shape": {"generator": "sphere", "radius": 0.5, "slices": 8, "stacks": 4},
   "pose": {"translation": [2, 2, 0]}}],
  "queries": [{"a": "link", "b": "other", "kind": "boolean"}]})";

TEST(SceneHierarchy, ComposedPosesEqualTheHandComputedOnes) {
  const Result<Scene> loaded = parseHierarchyText(kChain);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  const Scene& scene = loaded.value();
  ASSERT_EQ(scene.objects.size(), 4u);
  // File order is kept although parents are read first.
  EXPECT_EQ(scene.objects[0].name, "link");
  EXPECT_EQ(scene.objects[1].name, "truss");
  EXPECT_EQ(scene.objects[2].name, "hub");
  EXPECT_EQ(scene.objects[0].parent, std::optional<std::size_t>(1));
  EXPECT_EQ(scene.objects[1].parent, std::optional<std::size_t>(2));
  EXPECT_FALSE(scene.objects[2].parent.has_value());

  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  for (std::size_t f = 0; f < scene.frames; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    // Keyframes: held before frame 1 and after frame 3, halfway at frame 2.
    const double s = f <= 1 ? 0.0 : (f >= 3 ? 1.0 : 0.5);
    const Pose hub = translation(4.0 * s, 0.0, 0.0) * rotation(z, 90.0 * s);
    const Pose truss = hub * translation(0.0, 1.0, 0.0) * rotation(z, 90.0);
    // The joint turns about x through (0, 0, -0.5): 22.5 degrees a frame.
    const Pose link = truss * translation(1.0, 0.0, 0.0) * translation(0.0, 0.0, -0.5) *
                      rotation(Eigen::Vector3d::UnitX(), 22.5 * static_cast<double>(f)) *
                      translation(0.0, 0.0, 0.5);
    expectNear(scene.objects[2].poseAt(f), hub, "hub");
    expectNear(scene.objects[1].poseAt(f), truss, "truss");
    expectNear(scene.objects[0].poseAt(f), link, "link");
    expectNear(scene.objects[3].poseAt(f), translation(2.0, 2.0, 0.0), "other");
    // The joint's pivot stays where the truss carries it.
    const Eigen::Vector3d pivot(0.0, 0.0, -0.5);
    EXPECT_LT(
        (scene.objects[0].poseAt(f) * pivot - truss * translation(1.0, 0.0, 0.0) * pivot).norm(),
        1e-12);
  }
  // Keys are taken exactly as given.
  EXPECT_EQ(scene.objects[2].poseAt(3).translation(), Eigen::Vector3d(4.0, 0.0, 0.0));
  EXPECT_TRUE(scene.objects[2].poseAt(0).matrix().isIdentity(0.0));
}

TEST(SceneHierarchy, SubtreesHoldTheRootAndEverythingMountedOnIt) {
  const Result<Scene> loaded = parseHierarchyText(kChain);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  const Scene& scene = loaded.value();
  EXPECT_EQ(scene.subtree(2), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(scene.subtree(1), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(scene.subtree(0), (std::vector<std::size_t>{0}));
  EXPECT_EQ(scene.subtree(3), (std::vector<std::size_t>{3}));
}

TEST(SceneHierarchy, StaticChildOfAStaticParentKeepsOnePose) {
  const Result<Scene> loaded = parseHierarchyText(R"({"objects": [
    {"name": "p", "shape": {"generator": "box"}, "pose": {"translation": [1, 0, 0]}},
    {"name": "c", "parent": "p", "shape": {"generator": "box"}, "pose": {"translation": [0, 2, 0]}}],
    "frames": 3, "queries": [{"a": "p", "b": "c", "kind": "boolean"}]})");
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  ASSERT_EQ(loaded.value().objects[1].poses.size(), 1u);
  EXPECT_EQ(loaded.value().objects[1].poseAt(2).translation(), Eigen::Vector3d(1.0, 2.0, 0.0));
}

// A child of a tracked object follows the recovered poses in every query and keeps the true
// ones beside them: the truth scene puts it where the true motion does.
TEST(SceneHierarchy, AChildOfATrackedObjectFollowsItsRecoveredAndTruePoses) {
  const Result<Scene> loaded = parseHierarchyText(R"({"frames": 4, "objects": [
    {"name": "carrier", "shape": {"generator": "sphere", "radius": 0.3, "slices": 8, "stacks": 4},
     "motion": {"linear": {"from": {"translation": [-1, 0, 0]},
                           "to": {"translation": [1, 0, 0], "rotation": {"axis": [0, 1, 0], "degrees": 40}}}},
     "markers": {"layout": {"1": [0.2, 0.2, 0.2], "2": [-0.2, 0.2, -0.2], "3": [0.2, -0.2, -0.2],
                            "4": [-0.2, -0.2, 0.2]},
                 "generate": {"noise": 0.01, "seed": 3}}},
    {"name": "tool", "parent": "carrier", "shape": {"generator": "box"},
     "pose": {"translation": [0, 0, 1], "rotation": {"axis": [1, 0, 0], "degrees": 30}}}],
    "queries": [{"a": "carrier", "b": "tool", "kind": "boolean"}]})");
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  const Scene& scene = loaded.value();
  const SceneObject& carrier = scene.objects[0];
  const SceneObject& tool = scene.objects[1];
  ASSERT_NE(carrier.tracking, nullptr);
  const Pose local = translation(0.0, 0.0, 1.0) * rotation(Eigen::Vector3d::UnitX(), 30.0);
  bool recovered_differs = false;
  for (std::size_t f = 0; f < scene.frames; ++f) {
    expectNear(tool.poseAt(f), carrier.poseAt(f) * local, "recovered");
    expectNear(tool.truePoseAt(f), carrier.truePoseAt(f) * local, "true");
    recovered_differs |= !tool.poseAt(f).isApprox(tool.truePoseAt(f), 1e-12);
  }
  EXPECT_TRUE(recovered_differs) << "the noise should move the recovered poses";
  const Scene truth = scene.withTruePoses();
  for (std::size_t f = 0; f < scene.frames; ++f)
    expectNear(truth.objects[1].poseAt(f), carrier.truePoseAt(f) * local, "truth scene");
}

// A random placement applies at any level: mounted on a moving hub, the arm is placed against
// the target exactly as it would be as a root (the same seed, the same world poses), and its tip
// follows it; the hub's subtree holds both.
TEST(SceneHierarchy, ARandomMotionOnAMountedObjectPlacesItInTheWorld) {
  const std::string objects = R"(
    {"name": "target", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6}},
    {"name": "hub", "shape": {"generator": "box"},
     "motion": {"linear": {"from": {"translation": [-4, 0, 0]},
                           "to": {"translation": [4, 1, 0], "rotation": {"axis": [0, 0, 1], "degrees": 70}}}}},
    {"name": "arm", PARENT "shape": {"generator": "box", "size": [0.4, 0.4, 2]},
     "pose": {"rotation": {"axis": [1, 0, 0], "degrees": 20}},
     "motion": {"random": {"seed": 9, "relative_to": "target", "overlap": [0.2, 0.6]}}},
    {"name": "tip", "parent": "arm", "shape": {"generator": "box", "size": [0.1, 0.1, 0.1]},
     "pose": {"translation": [0, 0, 1.2]}}],
    "queries": [{"a": "target", "b": {"subtree": "hub"}, "kind": "all_pairs"}]})";
  const auto with = [&](const std::string& parent) {
    std::string text = R"({"frames": 6, "objects": [)" + objects;
    text.replace(text.find("PARENT"), 6, parent);
    return parseHierarchyText(text);
  };
  const Result<Scene> mounted = with(R"("parent": "hub",)");
  const Result<Scene> free = with("");
  ASSERT_TRUE(mounted.ok()) << mounted.status().toString();
  ASSERT_TRUE(free.ok()) << free.status().toString();
  const Pose tip = translation(0.0, 0.0, 1.2);
  bool hub_moves = false;
  for (std::size_t f = 0; f < 6; ++f) {
    const Pose& arm = mounted.value().objects[2].poseAt(f);
    EXPECT_LT((arm.matrix() - free.value().objects[2].poseAt(f).matrix()).cwiseAbs().maxCoeff(),
              1e-12)
        << "frame " << f;
    expectNear(mounted.value().objects[3].poseAt(f), arm * tip, "tip");
    hub_moves |= f > 0 && !mounted.value().objects[1].poseAt(f).isApprox(
                              mounted.value().objects[1].poseAt(0), 1e-9);
  }
  EXPECT_TRUE(hub_moves);
  EXPECT_EQ(mounted.value().subtree(1), (std::vector<std::size_t>{1, 2, 3}));
}

// An object mounted on a tracked one moves with the fit's error: its spread is the fit's
// covariance carried to its own corners (J C Jᵀ, J = [-[R p]x, I] for a corner p in the tracked
// object's frame), larger than the carrier's own since it lies further from the markers; a
// grandchild inherits it too, and at the true poses no tracking moves anything.
TEST(SceneHierarchy, ObjectsOnATrackedObjectSpreadWithItsFit) {
  const Result<Scene> loaded = parseHierarchyText(R"({"frames": 3, "objects": [
    {"name": "carrier", "shape": {"generator": "sphere", "radius": 0.3, "slices": 8, "stacks": 4},
     "motion": {"linear": {"from": {"translation": [-1, 0, 0]}, "to": {"translation": [1, 0, 0]}}},
     "markers": {"layout": {"1": [0.2, 0.2, 0.2], "2": [-0.2, 0.2, -0.2], "3": [0.2, -0.2, -0.2],
                            "4": [-0.2, -0.2, 0.2]},
                 "generate": {"noise": 0.01, "seed": 5}}},
    {"name": "boom", "parent": "carrier", "shape": {"generator": "box", "size": [0.2, 0.2, 2]},
     "pose": {"translation": [0, 0, 1.3]}},
    {"name": "tip", "parent": "boom", "shape": {"generator": "box", "size": [0.1, 0.1, 0.1]},
     "pose": {"translation": [0, 0, 1.1], "rotation": {"axis": [0, 1, 0], "degrees": 25}}}],
    "queries": [{"a": "carrier", "b": "tip", "kind": "boolean"}]})");
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  const Scene& scene = loaded.value();
  EXPECT_EQ(scene.objects[1].tracked_ancestor, std::optional<std::size_t>(0));
  EXPECT_EQ(scene.objects[2].tracked_ancestor, std::optional<std::size_t>(0));
  const auto by_hand = [&](std::size_t object, std::size_t frame) {
    const SceneObject& carrier = scene.objects[0];
    const pose::PoseEstimate& fit = carrier.tracking->frames[frame].estimate;
    const Pose to_carrier = carrier.poseAt(frame).inverse() * scene.objects[object].poseAt(frame);
    const Eigen::Vector3d low = scene.objects[object].mesh->vertices.rowwise().minCoeff();
    const Eigen::Vector3d high = scene.objects[object].mesh->vertices.rowwise().maxCoeff();
    double widest = 0.0;
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector3d p =
          to_carrier * Eigen::Vector3d((k & 1) ? high.x() : low.x(), (k & 2) ? high.y() : low.y(),
                                       (k & 4) ? high.z() : low.z());
      const Eigen::Vector3d r = fit.pose.linear() * p;
      Eigen::Matrix<double, 3, 6> j;
      j << 0, r.z(), -r.y(), 1, 0, 0,  //
          -r.z(), 0, r.x(), 0, 1, 0,   //
          r.y(), -r.x(), 0, 0, 0, 1;
      widest = std::max(widest, std::sqrt((j * fit.covariance * j.transpose()).trace() / 3.0));
    }
    return widest;
  };
  for (std::size_t f = 0; f < scene.frames; ++f) {
    ASSERT_EQ(scene.objects[0].tracking->frames[f].estimate.covariance.rows(), 6) << f;
    const double own = scene.trackingSpreadAt(0, *scene.objects[0].mesh, f);
    const double boom = scene.trackingSpreadAt(1, *scene.objects[1].mesh, f);
    const double tip = scene.trackingSpreadAt(2, *scene.objects[2].mesh, f);
    EXPECT_EQ(own, scene.objects[0].tracking->frames[f].sigma);
    EXPECT_NEAR(boom, by_hand(1, f), 1e-12 * boom);
    EXPECT_NEAR(tip, by_hand(2, f), 1e-12 * tip);
    EXPECT_GT(boom, own) << "frame " << f << ": the boom reaches further from the markers";
    EXPECT_GT(tip, own) << "frame " << f;
  }
  const Scene truth = scene.withTruePoses();
  for (std::size_t object = 0; object < 3; ++object)
    EXPECT_EQ(truth.trackingSpreadAt(object, *truth.objects[object].mesh, 1), 0.0) << object;
}

// Module A with a panel against module B with an arm: the subtree query asks exactly the pairs
// across the two sets, and its answers in every frame are the sums of the four pairwise ones.
const char* const kModules = R"({"frames": 9, "objects": [
  {"name": "module_a", "shape": {"generator": "sphere", "radius": 1, "slices": 16, "stacks": 8}},
  {"name": "panel_a", "parent": "module_a", "shape": {"generator": "box", "size": [3, 0.05, 0.8]},
   "pose": {"translation": [2.2, 0, 0]}},
  {"name": "module_b", "shape": {"generator": "sphere", "radius": 1, "slices": 16, "stacks": 8},
   "motion": {"linear": {"from": {"translation": [6, 0.5, 0]}, "to": {"translation": [1.2, 0.5, 0]}}}},
  {"name": "arm", "parent": "module_b",
   "shape": {"generator": "torus", "major_radius": 0.4, "minor_radius": 0.1, "major_segments": 16, "minor_segments": 8},
   "pose": {"translation": [-1.2, -0.5, 0]},
   "motion": {"joint": {"axis": [0, 0, 1], "origin": [1.2, 0.5, 0],
                        "keys": [{"frame": 0, "degrees": 0}, {"frame": 8, "degrees": 60}]}}}],
  "queries": [
    {"name": "subtrees", "a": {"subtree": "module_a"}, "b": {"subtree": "module_b"}, "kind": "all_pairs"},
    {"a": "module_a", "b": "module_b", "kind": "all_pairs"},
    {"a": "module_a", "b": "arm", "kind": "all_pairs"},
    {"a": "panel_a", "b": "module_b", "kind": "all_pairs"},
    {"a": "panel_a", "b": "arm", "kind": "all_pairs"}]})";

TEST(SceneHierarchy, ASubtreeQueryAnswersTheUnionOfItsPairs) {
  const Result<Scene> loaded = parseHierarchyText(kModules);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  const Scene& scene = loaded.value();
  const SceneQuery& subtrees = scene.queries[0];
  ASSERT_TRUE(subtrees.isGroup());
  EXPECT_EQ(subtrees.among, (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(subtrees.side_b, (std::vector<std::size_t>{2, 3}));
  EXPECT_FALSE(subtrees.asksPair(0, 1));
  EXPECT_FALSE(subtrees.asksPair(2, 3));
  EXPECT_TRUE(subtrees.asksPair(3, 1));
  EXPECT_EQ(scene.queries[1].name, "module_a-module_b all_pairs");

  const RunReport report = test::runPlugin(scene, "obbtree", "obbtree", test::repeated(1));
  ASSERT_EQ(report.measurements.size(), 5u);
  for (const QueryMeasurement& m : report.measurements)
    ASSERT_TRUE(m.ok()) << m.status;
  const BroadPhase broad_phase(scene, subtrees);
  std::size_t total = 0;
  for (std::size_t f = 0; f < scene.frames; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    for (const auto& [i, j] : broad_phase.pairsAt(f))
      EXPECT_TRUE(subtrees.asksPair(i, j)) << i << ", " << j;
    std::size_t oracle = 0;
    std::size_t reported = 0;
    bool any = false;
    for (std::size_t q = 1; q < 5; ++q) {
      const FrameRecord& pair = report.measurements[q].frames[f];
      oracle += pair.oracle_pairs;
      reported += pair.reported_pairs;
      any |= pair.oracle_intersecting;
    }
    const FrameRecord& group = report.measurements[0].frames[f];
    EXPECT_EQ(group.oracle_pairs, oracle);
    EXPECT_EQ(group.reported_pairs, reported);
    EXPECT_EQ(group.matched_pairs, group.oracle_pairs);
    EXPECT_EQ(group.oracle_intersecting, any);
    total += oracle;
  }
  EXPECT_GT(total, 0u) << "the scene should bring the subtrees into contact";
}

TEST(SceneHierarchy, AmongTakesSubtrees) {
  std::string text = kModules;
  const std::size_t at = text.find(R"({"name": "subtrees")");
  text.insert(
      at,
      R"({"name": "pile", "among": [{"subtree": "module_b"}, "panel_a"], "kind": "all_pairs"},)");
  const Result<Scene> loaded = parseHierarchyText(text);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  const SceneQuery& pile = loaded.value().queries[0];
  EXPECT_EQ(pile.among, (std::vector<std::size_t>{1, 2, 3}));
  EXPECT_TRUE(pile.side_b.empty());
  EXPECT_TRUE(pile.asksPair(2, 3));
}

}  // namespace
}  // namespace collido
