// The OBB tree's distance against the exact reference distance: random poses, near contact far
// from the origin, touching exactly, tolerances honoured, float boxes, and the certified bound.
#include <cmath>
#include <fstream>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/mesh/procedural.h>
#include <collido/obbtree/distance.h>
#include <collido/oracle/distance_oracle.h>
#include <collido/oracle/triangle_distance.h>

#include "collide_check.h"

namespace collido::obbtree {
namespace {

TriangleMesh torusMesh() {
  TorusParams params;
  params.major_segments = 32;
  params.minor_segments = 12;
  return unwrap(makeTorus(params), "torus");
}

// Checks one answer against the reference: distance within rounding below and tolerance above,
// points on their triangles and the distance apart, the lower bound at most the exact distance.
void expectAnswer(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                  const Pose& pose_b, const DistanceRequest& request, const DistanceAnswer& got,
                  const std::string& label) {
  const MeshDistance exact = exactMeshDistance(a, pose_a, b, pose_b);
  const double rounding =
      1e-12 * std::max({1.0, pose_a.translation().norm(), pose_b.translation().norm()});
  const double allowed =
      std::max(request.abs_tolerance, request.rel_tolerance * exact.distance) + rounding;
  EXPECT_GE(got.distance, exact.distance - rounding) << label;
  EXPECT_LE(got.distance, exact.distance + allowed) << label;
  EXPECT_EQ(got.distance == 0.0, exact.distance == 0.0) << label << ": contact decided exactly";
  EXPECT_LE(got.lower_bound, exact.distance + rounding) << label;
  EXPECT_NEAR((got.point_b - got.point_a).norm(), got.distance, rounding) << label;
  ASSERT_GE(got.triangle_a, 0);
  ASSERT_GE(got.triangle_b, 0);
  const auto corners = [](const TriangleMesh& m, const Pose& pose, std::int32_t t) {
    std::array<Eigen::Vector3d, 3> c;
    for (int k = 0; k < 3; ++k)
      c[static_cast<std::size_t>(k)] = pose * m.corner(static_cast<std::size_t>(t), k);
    return c;
  };
  const auto on = [&](const Eigen::Vector3d& p, const std::array<Eigen::Vector3d, 3>& t) {
    return (closestPointOnTriangle(p, t) - p).norm();
  };
  EXPECT_LE(on(got.point_a, corners(a, pose_a, got.triangle_a)), rounding) << label;
  EXPECT_LE(on(got.point_b, corners(b, pose_b, got.triangle_b)), rounding) << label;
}

TEST(Distance, ToriAtRandomPosesMatchTheExactDistance) {
  const TriangleMesh torus = torusMesh();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int apart = 0;
  for (int trial = 0; trial < 40; ++trial) {
    BuildOptions options;
    options.max_leaf_triangles = trial % 2 == 0 ? 1 : 4;
    options.float_boxes = trial % 3 == 0;
    const ObbTree tree = ObbTree::build(torus.vertices, torus.triangles, options);
    const double reach = trial < 20 ? 1.5 : 4.0;
    const Pose pose_a = makePose(randomRotation(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const Pose pose_b =
        makePose(randomRotation(rng),
                 pose_a.translation() + reach * Eigen::Vector3d(u(rng), u(rng), u(rng)));
    DistanceAnswer answer;
    distance(tree, pose_a, tree, pose_b, DistanceRequest{}, answer);
    expectAnswer(torus, pose_a, torus, pose_b, DistanceRequest{}, answer,
                 "trial " + std::to_string(trial));
    apart += answer.distance > 0.0 ? 1 : 0;
    if (HasFailure()) return;
  }
  EXPECT_GE(apart, 10);
  EXPECT_LE(apart, 35);
}

TEST(Distance, TolerancesTradeAccuracyForWork) {
  const TriangleMesh torus = torusMesh();
  const ObbTree tree = ObbTree::build(torus.vertices, torus.triangles);
  const Pose pose_a = Pose::Identity();
  const Pose pose_b = makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.7, 0.4, 0.3));
  DistanceAnswer exact;
  distance(tree, pose_a, tree, pose_b, DistanceRequest{}, exact);
  for (const DistanceRequest request : {DistanceRequest{0.05, 0.0}, DistanceRequest{0.0, 0.2}}) {
    DistanceAnswer loose;
    distance(tree, pose_a, tree, pose_b, request, loose);
    expectAnswer(torus, pose_a, torus, pose_b, request, loose, "tolerance");
    EXPECT_LE(loose.triangle_tests, exact.triangle_tests);
  }
}

// FCL's tilted cubes "kissing" face to face at +-1e-15 of their size (0.01 to 1000;
// tests/data/peer_cases/fcl_signed_distance.json): 0 exactly where they overlap, a positive
// distance where they are apart, every answer against the exact reference.
TEST(Distance, FclsKissingCubes) {
  std::ifstream in("tests/data/peer_cases/fcl_signed_distance.json");
  ASSERT_TRUE(in) << "run from the repository root";
  const nlohmann::json cases = nlohmann::json::parse(in)["cases"];
  int boxes = 0;
  for (const nlohmann::json& c : cases) {
    if (c["shapes"][0]["type"] != "box") continue;
    Pose poses[2];
    TriangleMesh meshes[2];
    for (int k = 0; k < 2; ++k) {
      const nlohmann::json& s = c["shapes"][k];
      poses[k] = Pose::Identity();
      for (int r = 0; r < 3; ++r) {
        for (int q = 0; q < 3; ++q)
          poses[k].linear()(r, q) = s["R"][r][q].get<double>();
        poses[k].translation()[r] = s["t"][r].get<double>();
      }
      const Eigen::Vector3d size(s["size"][0].get<double>(), s["size"][1].get<double>(),
                                 s["size"][2].get<double>());
      meshes[k] = unwrap(makeBox(BoxParams{size}), "box");
    }
    const ObbTree tree_a = ObbTree::build(meshes[0].vertices, meshes[0].triangles);
    const ObbTree tree_b = ObbTree::build(meshes[1].vertices, meshes[1].triangles);
    DistanceAnswer answer;
    distance(tree_a, poses[0], tree_b, poses[1], DistanceRequest{}, answer);
    const std::string id = c["id"];
    expectAnswer(meshes[0], poses[0], meshes[1], poses[1], DistanceRequest{}, answer, id);
    EXPECT_EQ(answer.distance == 0.0, c["oracle"]["signed_distance"].get<double>() < 0.0) << id;
    ++boxes;
  }
  EXPECT_EQ(boxes, 10);
}

// Two links of a chain at clearance 0 touch at a coincident vertex; under a shared exact pose
// the distance must be exactly 0, and at a small clearance far from the origin, that clearance.
TEST(Distance, TouchingAndNearlyTouchingLinks) {
  for (const double clearance : {0.0, 1e-6}) {
    ChainParams params;
    params.links = 2;
    params.link.major_segments = 32;
    params.link.minor_segments = 16;
    params.clearance = clearance;
    const TriangleMesh chain = unwrap(makeChain(params), "chain");
    const TriangleMesh a = chainLink(chain, 2, 0);
    const TriangleMesh b = chainLink(chain, 2, 1);
    const ObbTree tree_a = ObbTree::build(a.vertices, a.triangles);
    const ObbTree tree_b = ObbTree::build(b.vertices, b.triangles);
    const Pose shared = makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1e4, -3e3, 0.5));
    DistanceAnswer answer;
    distance(tree_a, shared, tree_b, shared, DistanceRequest{}, answer);
    expectAnswer(a, shared, b, shared, DistanceRequest{}, answer,
                 "clearance " + std::to_string(clearance));
    if (clearance == 0.0) {
      EXPECT_EQ(answer.distance, 0.0);
      // One pose for both: the map into A's frame is exactly the identity, and the certified
      // double-precision test decides the coincident vertex with exact predicates.
      EXPECT_EQ(answer.exact_tests, 0u);
    }
  }
}

// Shapes that cross through each other at a tilted pose: contact is certified in double
// precision by the filtered triangle test, without exact arithmetic.
TEST(Distance, CrossingShapesNeedNoExactArithmetic) {
  const TriangleMesh torus = torusMesh();
  const ObbTree tree = ObbTree::build(torus.vertices, torus.triangles);
  const Pose pose_a = makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(3.0, -2.0, 1.0));
  const Pose pose_b = makePose(
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, 1.0, 0.2).normalized()).toRotationMatrix(),
      Eigen::Vector3d(3.4, -1.7, 1.2));
  DistanceAnswer answer;
  distance(tree, pose_a, tree, pose_b, DistanceRequest{}, answer);
  expectAnswer(torus, pose_a, torus, pose_b, DistanceRequest{}, answer, "crossing tori");
  EXPECT_EQ(answer.distance, 0.0);
  EXPECT_EQ(answer.exact_tests, 0u);
}

}  // namespace
}  // namespace collido::obbtree
