// Tree-tree collision against the exact oracle: the set of intersecting triangle pairs must equal
// the oracle's exactly (interlocked and touching tori, random poses, sphere vs gear, bunnies,
// meshing gears, several leaf sizes, far from the origin), the boolean query must agree with it
// and give a true witness, max_pairs must truncate honestly, A-B must mirror B-A, and the 40
// published env/rob poses must give their listed pair sets.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <collido/mesh/mesh_io.h>
#include <collido/mesh/procedural.h>
#include <collido/obbtree/collide.h>
#include <collido/oracle/exact_oracle.h>

#include "collide_check.h"

namespace collido::obbtree {
namespace {

ObbTree treeOf(const TriangleMesh& mesh, int max_leaf) {
  return ObbTree::build(mesh.vertices, mesh.triangles, {max_leaf});
}

// Meshes and trees used by several tests, built once (tree building dominates Debug run time).
const TriangleMesh& bunny() {
  static const TriangleMesh mesh = unwrap(loadMesh("scenes/meshes/bunny.obj"), "bunny.obj");
  return mesh;
}
const ObbTree& bunnyTree(int max_leaf) {
  static const ObbTree leaf1 = treeOf(bunny(), 1);
  static const ObbTree leaf4 = treeOf(bunny(), 4);
  return max_leaf == 1 ? leaf1 : leaf4;
}
const TriangleMesh& torus() {
  static const TriangleMesh mesh = [] {
    TorusParams params;
    params.major_segments = 32;
    params.minor_segments = 16;
    return unwrap(makeTorus(params), "torus");
  }();
  return mesh;
}
const ObbTree& torusTree(int max_leaf) {
  static const ObbTree leaf1 = treeOf(torus(), 1);
  static const ObbTree leaf8 = treeOf(torus(), 8);
  return max_leaf == 1 ? leaf1 : leaf8;
}

// ---------------------------------------------------------------------------------------------

// Two interlocked links (even one in xy, odd one in xz), both at the identity: intersecting,
// touching exactly at coincident vertices (clearance 0), or apart.
TEST(Collide, InterlockedTori) {
  const double clearances[] = {-0.05, -0.001, 0.0, 0.001, 0.05};
  const int leaf_sizes[][2] = {{1, 16}, {4, 1}, {1, 1}, {16, 4}, {2, 2}};
  for (int i = 0; i < 5; ++i) {
    const double clearance = clearances[i];
    ChainParams params;
    params.links = 2;
    params.link.major_segments = 24;
    params.link.minor_segments = 12;
    params.clearance = clearance;
    const TriangleMesh chain = unwrap(makeChain(params), "chain");
    const TriangleMesh a = chainLink(chain, 2, 0);
    const TriangleMesh b = chainLink(chain, 2, 1);
    ASSERT_EQ(a.triangleCount() + b.triangleCount(), chain.triangleCount());
    {
      const int leaf_a = leaf_sizes[i][0];
      const int leaf_b = leaf_sizes[i][1];
      const std::string label = "clearance " + std::to_string(clearance) + ", max_leaf " +
                                std::to_string(leaf_a) + "/" + std::to_string(leaf_b);
      const Outcome o = checkQuery(a, treeOf(a, leaf_a), Pose::Identity(), b, treeOf(b, leaf_b),
                                   Pose::Identity(), label);
      // The scenario is what it claims: contact for clearance <= 0, none for > 0.
      EXPECT_EQ(o.truth.empty(), clearance > 0.0) << label;
      if (HasFailure()) return;
    }
  }
}

// A deforming link refit frame after frame with rebuilds on (every subtree whose box more
// than doubled is rebuilt over its current triangles): the trees stay valid and every answer
// equals the oracle's on the deformed mesh.
TEST(Collide, RebuiltSubtreesAfterDeformationMatchTheOracle) {
  ChainParams params;
  params.links = 2;
  params.link.major_segments = 32;
  params.link.minor_segments = 12;
  const TriangleMesh chain = unwrap(makeChain(params), "chain");
  const TriangleMesh a = chainLink(chain, 2, 0);
  const TriangleMesh b = chainLink(chain, 2, 1);
  for (const bool float_boxes : {false, true}) {
    BuildOptions options;
    options.max_leaf_triangles = 4;
    options.float_boxes = float_boxes;
    options.deformable = true;
    options.rebuild_ratio = 2.0;
    ObbTree tree_a = ObbTree::build(a.vertices, a.triangles, options);
    const ObbTree tree_b = ObbTree::build(b.vertices, b.triangles, options);
    std::size_t rebuilt = 0;
    for (int frame = 1; frame <= 6; ++frame) {
      // Twist about x by up to 90 degrees across the link and stretch it along z.
      TriangleMesh moved = a;
      for (Eigen::Index v = 0; v < moved.vertices.cols(); ++v) {
        const Eigen::Vector3d p = a.vertices.col(v);
        const double angle = 0.25 * frame * p.x();
        moved.vertices.col(v) = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()) *
                                Eigen::Vector3d(p.x(), p.y(), p.z() * (1.0 + 0.3 * frame));
      }
      const RefitReport report = tree_a.refit(moved.vertices);
      rebuilt += report.subtrees_rebuilt;
      const std::string label =
          std::string(float_boxes ? "float" : "double") + " boxes, frame " + std::to_string(frame);
      ASSERT_EQ(tree_a.validate(), "") << label;
      checkQuery(moved, tree_a, Pose::Identity(), b, tree_b, Pose::Identity(), label);
      if (HasFailure()) return;
    }
    EXPECT_GT(rebuilt, 0u);
  }
}

// The same touching pair of links under one shared rigid motion: the exact contact at the
// coincident vertices survives in the world frame (the same exact map on both), and the tree
// must still find it.
TEST(Collide, TouchingToriUnderASharedPose) {
  ChainParams params;
  params.links = 2;
  params.link.major_segments = 32;
  params.link.minor_segments = 16;
  params.clearance = 0.0;
  const TriangleMesh chain = unwrap(makeChain(params), "chain");
  const TriangleMesh a = chainLink(chain, 2, 0);
  const TriangleMesh b = chainLink(chain, 2, 1);
  const ObbTree tree_a = treeOf(a, 4);
  const ObbTree tree_b = treeOf(b, 4);
  // Translations by exact dyadic offsets keep every coordinate exact; quarter turns too.
  Eigen::Matrix3d quarter;
  quarter << 0, -1, 0,  //
      1, 0, 0,          //
      0, 0, 1;
  const Pose shared[] = {makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, -2, 8)),
                         makePose(quarter, Eigen::Vector3d(1024, 0.25, -3)),
                         makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1e6, -1e6, 1e6))};
  for (const Pose& pose : shared) {
    std::ostringstream label;
    label << "shared pose t = " << pose.translation().transpose();
    const Outcome o = checkQuery(a, tree_a, pose, b, tree_b, pose, label.str());
    EXPECT_FALSE(o.truth.empty()) << label.str();
  }
}

// KNOWN LIMITATION (disabled until collide decides near-degenerate pairs exactly on the exact world
// coordinates: the robustness work, issue 5): two triangles sharing the corner (1, 0, 0), posed by
// one and the same rotation. The oracle evaluates R v exactly, so the shared corner stays shared
// and the pair touches; collide maps B into A's frame by the rounded R^T R != I, which moves the
// corner by ~1e-16 and loses the contact (or, elsewhere, invents overlap: the touching chain links
// of TouchingToriUnderASharedPose give 0 or 10-12 pairs instead of 6 under most random shared
// rotations).
TEST(Collide, TouchingPairUnderASharedRotation) {
  TriangleMesh a;
  a.vertices.resize(3, 3);
  a.vertices << 0, 1, 0,  //
      0, 0, 1,            //
      0, 0, 0;
  a.triangles.resize(3, 1);
  a.triangles << 0, 1, 2;
  TriangleMesh b;
  b.vertices.resize(3, 3);
  b.vertices << 1, 2, 2,  //
      0, 1, -1,           //
      0, 1, 1;
  b.triangles = a.triangles;
  Eigen::Matrix3d r;  // AngleAxisd(0.1, (1, 2, 3) / |(1, 2, 3)|), as Eigen computes it
  r << 0.99536101061530968, -0.079331118077607649, 0.0544337418466352,   //
      0.080758499426743124, 0.99643154662716127, -0.024540530893688576,  //
      -0.052292669822931986, 0.028822674941095017, 0.99821577331358069;
  const Pose pose = makePose(r, Eigen::Vector3d::Zero());
  ASSERT_EQ(exactIntersectingPairs(a, Pose::Identity(), b, Pose::Identity()).pairs.size(), 1u);
  ASSERT_EQ(exactIntersectingPairs(a, pose, b, pose).pairs.size(), 1u);
  CollideResult result;
  collide(treeOf(a, 1), pose, treeOf(b, 1), pose, CollideRequest{}, result);
  EXPECT_EQ(result.pairs.size(), 1u) << "the shared corner's contact is lost";
}

TEST(Collide, ToriAtRandomPoses) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int trial = 0; trial < 16; ++trial) {
    const Pose pose_a = makePose(randomRotation(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const Pose pose_b = makePose(randomRotation(rng),
                                 pose_a.translation() + Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const ObbTree& tree_a = torusTree(trial % 2 == 0 ? 1 : 8);
    const ObbTree& tree_b = torusTree(trial % 3 == 0 ? 1 : 8);
    const Outcome o = checkQuery(torus(), tree_a, pose_a, torus(), tree_b, pose_b,
                                 "trial " + std::to_string(trial));
    hits += o.truth.empty() ? 0 : 1;
    if (HasFailure()) return;
  }
  EXPECT_GE(hits, 8);  // mostly overlapping poses, a few apart
}

TEST(Collide, SphereAgainstGear) {
  SphereParams sphere_params;
  sphere_params.radius = 0.3;
  sphere_params.slices = 24;
  sphere_params.stacks = 12;
  const TriangleMesh sphere = unwrap(makeSphere(sphere_params), "sphere");
  const TriangleMesh gear = unwrap(makeGear(GearParams{}), "gear");  // pitch radius 1
  const ObbTree sphere_tree = treeOf(sphere, 2);
  const ObbTree gear_tree = treeOf(gear, 2);
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int trial = 0; trial < 6; ++trial) {
    // The sphere centred near the tooth ring (radius ~1), the gear turned at random.
    const double angle = 3.14159 * u(rng);
    const Eigen::Vector3d centre(std::cos(angle), std::sin(angle), 0.1 * u(rng));
    const Pose gear_pose = makePose(randomRotation(rng), Eigen::Vector3d(0.1, 0.2, 0.3));
    const Pose sphere_pose = makePose(randomRotation(rng), gear_pose * centre);
    const Outcome o = checkQuery(sphere, sphere_tree, sphere_pose, gear, gear_tree, gear_pose,
                                 "trial " + std::to_string(trial));
    hits += o.truth.empty() ? 0 : 1;
    if (HasFailure()) return;
  }
  EXPECT_EQ(hits, 6);
}

// Two gears at their working centre distance: a tooth of the second centred in a gap of the
// first (touching in the ideal profile; the sampled flanks leave a tiny gap), then turned into
// the first by small angles (interpenetrating).
TEST(Collide, MeshingGears) {
  GearParams p1;
  p1.teeth = 20;
  GearParams p2;
  p2.teeth = 13;
  const TriangleMesh g1 = unwrap(makeGear(p1), "gear 20");
  const TriangleMesh g2 = unwrap(makeGear(p2), "gear 13");
  const ObbTree t1 = treeOf(g1, 4);
  const ObbTree t2 = treeOf(g2, 1);
  const double distance = p1.module * (p1.teeth + p2.teeth) / 2.0;
  const double pi = 3.14159265358979323846;
  int hits = 0;
  for (double extra : {0.0, 0.002, 0.01, 0.05}) {
    // Gear 1 puts tooth 0 on +x; gear 2 at (distance, 0, 0) turned by pi so tooth 0 faces -x,
    // plus half a pitch so a gap faces gear 1's tooth, plus `extra`.
    const Pose pose1 = Pose::Identity();
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(pi + pi / p2.teeth + extra, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Pose pose2 = makePose(turn, Eigen::Vector3d(distance, 0, 0));
    const Outcome o = checkQuery(g1, t1, pose1, g2, t2, pose2, "extra " + std::to_string(extra));
    hits += o.truth.empty() ? 0 : 1;
    if (HasFailure()) return;
  }
  EXPECT_GE(hits, 2);  // the larger turns interpenetrate
}

// Bunnies at random rotations with centres a fraction of their size apart: dense overlaps.
TEST(Collide, BunnyAgainstBunny) {
  std::mt19937_64 rng(51);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::size_t most = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const Pose pose_a = makePose(randomRotation(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const Pose pose_b = makePose(
        randomRotation(rng), pose_a.translation() + 3.0 * Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const Outcome o = checkQuery(bunny(), bunnyTree(trial % 2 == 0 ? 1 : 4), pose_a, bunny(),
                                 bunnyTree(4), pose_b, "trial " + std::to_string(trial));
    most = std::max(most, o.truth.size());
    if (HasFailure()) return;
  }
  EXPECT_GT(most, 200u);  // dense contact in at least one pose
}

// Two bunnies at random poses, their centres within 2 units on each axis, with the tree of the
// given leaf size and the oracle's pairs.
struct BunnyOverlap {
  Pose pose_a;
  Pose pose_b;
  const ObbTree& tree;
  Pairs truth;
};
BunnyOverlap randomBunnyOverlap(std::mt19937_64& rng, int max_leaf) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Pose pose_a = makePose(randomRotation(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)));
  const Pose pose_b = makePose(
      randomRotation(rng), pose_a.translation() + 2.0 * Eigen::Vector3d(u(rng), u(rng), u(rng)));
  return BunnyOverlap{pose_a, pose_b, bunnyTree(max_leaf),
                      exactIntersectingPairs(bunny(), pose_a, bunny(), pose_b).pairs};
}

// All pairs on several threads: the oracle's pairs, each once, the same work as one thread does
// (the same node pairs are tested, only shared out), and the same answer for every repetition
// (the order of the pairs does not depend on the scheduling).
TEST(Collide, ThreadsGiveTheSameAnswer) {
  std::mt19937_64 rng(52);
  for (int trial = 0; trial < 4; ++trial) {
    const BunnyOverlap overlap = randomBunnyOverlap(rng, trial % 2 == 0 ? 1 : 4);
    const Pose& pose_a = overlap.pose_a;
    const Pose& pose_b = overlap.pose_b;
    const ObbTree& tree = overlap.tree;
    const Pairs& truth = overlap.truth;
    CollideResult one;
    collide(tree, pose_a, tree, pose_b, CollideRequest{}, one);
    for (int threads : {2, 3, 8}) {
      CollideRequest request;
      request.threads = threads;
      CollideResult first;
      collide(tree, pose_a, tree, pose_b, request, first);
      const std::string label =
          "trial " + std::to_string(trial) + ", " + std::to_string(threads) + " threads";
      EXPECT_EQ(differences(sorted(first.pairs), truth), "") << label;
      EXPECT_EQ(first.box_tests, one.box_tests) << label;
      EXPECT_EQ(first.triangle_tests, one.triangle_tests) << label;
      CollideResult again;
      collide(tree, pose_a, tree, pose_b, request, again);
      ASSERT_EQ(again.pairs.size(), first.pairs.size()) << label;
      for (std::size_t k = 0; k < first.pairs.size(); ++k) {
        EXPECT_TRUE(again.pairs[k].a == first.pairs[k].a && again.pairs[k].b == first.pairs[k].b)
            << label << ": pair " << k << " differs between runs";
      }
    }
  }
}

// The descent's scalar box tests (vector_box_tests = false, the path of CPUs without AVX2)
// answer as the oracle does, all pairs and first hit, as the vector ones do.
TEST(Collide, ScalarAndVectorBoxTestsGiveTheOraclesPairs) {
  std::mt19937_64 rng(57);
  for (int trial = 0; trial < 4; ++trial) {
    const BunnyOverlap o = randomBunnyOverlap(rng, trial % 2 == 0 ? 1 : 4);
    for (bool vector_box_tests : {false, true}) {
      const std::string label = "trial " + std::to_string(trial) +
                                (vector_box_tests ? ", vector box tests" : ", scalar box tests");
      CollideRequest request;
      request.vector_box_tests = vector_box_tests;
      CollideResult all;
      collide(o.tree, o.pose_a, o.tree, o.pose_b, request, all);
      EXPECT_EQ(differences(sorted(all.pairs), o.truth), "") << label;
      request.mode = CollideMode::kFirstHit;
      CollideResult first;
      collide(o.tree, o.pose_a, o.tree, o.pose_b, request, first);
      EXPECT_EQ(first.pairs.empty(), o.truth.empty()) << label;
    }
  }
}

// Float boxes answer exactly as double boxes do: the same pairs as the oracle, alone or mixed
// with a double-box tree, on dense bunny overlaps and on tori.
TEST(Collide, FloatBoxesMatchTheOracle) {
  const ObbTree bunny_floats = ObbTree::build(bunny().vertices, bunny().triangles, {1, true});
  const ObbTree torus_floats = ObbTree::build(torus().vertices, torus().triangles, {4, true});
  std::mt19937_64 rng(61);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::size_t most = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const Pose pose_a = makePose(randomRotation(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const Pose pose_b = makePose(
        randomRotation(rng), pose_a.translation() + 3.0 * Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const ObbTree& tree_b = trial % 2 == 0 ? bunny_floats : bunnyTree(4);
    const Outcome o = checkQuery(bunny(), bunny_floats, pose_a, bunny(), tree_b, pose_b,
                                 "bunny trial " + std::to_string(trial));
    most = std::max(most, o.truth.size());
    const Pose torus_b = makePose(randomRotation(rng),
                                  pose_a.translation() + Eigen::Vector3d(u(rng), u(rng), u(rng)));
    checkQuery(torus(), torusTree(1), pose_a, torus(), torus_floats, torus_b,
               "torus trial " + std::to_string(trial));
    if (HasFailure()) return;
  }
  EXPECT_GT(most, 200u);
}

// max_pairs: truncated iff more pairs exist than the limit; the pairs returned are exact pairs.
TEST(Collide, MaxPairsTruncatesHonestly) {
  const ObbTree& tree = bunnyTree(4);
  std::mt19937_64 rng(61);
  const Pose pose_a = makePose(randomRotation(rng), Eigen::Vector3d(0.1, 0.2, 0.3));
  const Pose pose_b = makePose(randomRotation(rng), Eigen::Vector3d(0.6, 1.2, -0.4));
  const Pairs truth = exactIntersectingPairs(bunny(), pose_a, bunny(), pose_b).pairs;
  const std::size_t n = truth.size();
  ASSERT_GT(n, 10u);
  for (std::size_t limit : {std::size_t{1}, std::size_t{2}, n / 2, n - 1, n, n + 1, 10 * n}) {
    CollideResult result;
    collide(tree, pose_a, tree, pose_b, CollideRequest{CollideMode::kAllPairs, limit}, result);
    const Pairs got = sorted(result.pairs);
    EXPECT_EQ(result.truncated, n > limit) << "limit " << limit << " of " << n;
    EXPECT_EQ(got.size(), std::min(limit, n)) << "limit " << limit;
    EXPECT_TRUE(std::includes(truth.begin(), truth.end(), got.begin(), got.end()))
        << "limit " << limit << ": pairs not in the exact set:" << [&] {
             Pairs extra;
             std::set_difference(got.begin(), got.end(), truth.begin(), truth.end(),
                                 std::back_inserter(extra));
             return listPairs(extra);
           }();
    EXPECT_EQ(std::adjacent_find(got.begin(), got.end()), got.end()) << "limit " << limit;
  }
  // A result object is overwritten, not appended to.
  CollideResult reused;
  collide(tree, pose_a, tree, pose_b, CollideRequest{CollideMode::kAllPairs, 1}, reused);
  collide(tree, pose_a, tree, pose_b, CollideRequest{}, reused);
  EXPECT_FALSE(reused.truncated);
  EXPECT_EQ(sorted(reused.pairs), truth);
}

// Far from the origin: both poses moved by (1e6, -1e6, 1e6); the oracle answers for the poses
// as given (the moved ones), and the tree must agree with it there too.
TEST(Collide, PosesFarFromTheOrigin) {
  const Eigen::Vector3d far(1e6, -1e6, 1e6);
  std::mt19937_64 rng(71);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 4; ++trial) {
    const Pose pose_a =
        makePose(randomRotation(rng), far + Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const Pose pose_b =
        makePose(randomRotation(rng), far + Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const std::string label = "trial " + std::to_string(trial);
    const Outcome tori =
        checkQuery(torus(), torusTree(8), pose_a, torus(), torusTree(1), pose_b, "tori, " + label);
    const Pose bunny_b =
        makePose(pose_b.linear(), pose_a.translation() + 3.0 * (pose_b.translation() - far));
    const Outcome bunnies = checkQuery(bunny(), bunnyTree(4), pose_a, bunny(), bunnyTree(1),
                                       bunny_b, "bunnies, " + label);
    EXPECT_FALSE(tori.truth.empty() && bunnies.truth.empty()) << label;
    if (HasFailure()) return;
  }
}

TEST(Collide, EmptyTreesCollideWithNothing) {
  const ObbTree& tree = torusTree(8);
  const ObbTree empty = ObbTree::build(Eigen::Matrix3Xd(3, 0), Eigen::Matrix3Xi(3, 0));
  CollideResult result;
  result.pairs.push_back({1, 2});
  result.truncated = true;
  collide(tree, Pose::Identity(), empty, Pose::Identity(), CollideRequest{}, result);
  EXPECT_TRUE(result.pairs.empty());
  EXPECT_FALSE(result.truncated);
  collide(empty, Pose::Identity(), tree, Pose::Identity(), CollideRequest{}, result);
  EXPECT_TRUE(result.pairs.empty());
}

// The 40 FCL env/rob poses (env posed by (R, t) as A, rob at the identity as B): the pair sets
// must be exactly the published ones, and the boolean answer their emptiness.
TEST(Collide, FclEnvRobPosesGiveThePublishedPairs) {
  std::ifstream file("tests/data/peer_cases/fcl_env_rob_poses.json");
  ASSERT_TRUE(file) << "tests/data/peer_cases/fcl_env_rob_poses.json (run from the source root)";
  const nlohmann::json doc = nlohmann::json::parse(file);
  const TriangleMesh env = unwrap(loadMesh("scenes/meshes/env.obj"), "env.obj");
  const TriangleMesh rob = unwrap(loadMesh("scenes/meshes/rob.obj"), "rob.obj");
  ASSERT_EQ(env.triangleCount(), 2180u);
  ASSERT_EQ(rob.triangleCount(), 216u);
  const ObbTree env_tree = treeOf(env, 1);
  const ObbTree rob_tree = treeOf(rob, 4);
  const auto& cases = doc.at("cases");
  ASSERT_EQ(cases.size(), 40u);
  int colliding = 0;
  for (const auto& c : cases) {
    const std::string id = c.at("id").get<std::string>();
    Eigen::Matrix3d r;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        r(i, j) =
            c.at("R").at(static_cast<std::size_t>(i)).at(static_cast<std::size_t>(j)).get<double>();
      }
    }
    const Eigen::Vector3d t(c.at("t").at(0).get<double>(), c.at("t").at(1).get<double>(),
                            c.at("t").at(2).get<double>());
    Pairs expected;
    for (const auto& pair : c.at("intersecting_pairs_env_rob")) {
      expected.push_back(
          collido::TrianglePair{pair.at(0).get<std::int32_t>(), pair.at(1).get<std::int32_t>()});
    }
    std::sort(expected.begin(), expected.end());
    ASSERT_EQ(expected.size(), c.at("num_intersecting_triangle_pairs").get<std::size_t>()) << id;
    ASSERT_EQ(!expected.empty(), c.at("collide").get<bool>()) << id;
    colliding += expected.empty() ? 0 : 1;

    CollideResult result;
    collide(env_tree, makePose(r, t), rob_tree, Pose::Identity(), CollideRequest{}, result);
    EXPECT_EQ(differences(sorted(result.pairs), expected), "") << id;
    CollideResult first;
    collide(env_tree, makePose(r, t), rob_tree, Pose::Identity(),
            CollideRequest{CollideMode::kFirstHit, 0}, first);
    EXPECT_EQ(first.pairs.empty(), expected.empty()) << id << ": boolean answer";
    if (!first.pairs.empty()) {
      const collido::TrianglePair witness{first.pairs[0].a, first.pairs[0].b};
      EXPECT_TRUE(std::binary_search(expected.begin(), expected.end(), witness)) << id;
    }
  }
  EXPECT_GT(colliding, 10);
}

}  // namespace
}  // namespace collido::obbtree
