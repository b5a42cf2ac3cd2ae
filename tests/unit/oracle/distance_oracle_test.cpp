// The reference distance: closest points of triangles against dense sampling, the exact mesh
// distance against analytic cases and the peer case's exact distances for FCL's env/rob poses.
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/mesh/mesh_io.h>
#include <collido/mesh/procedural.h>
#include <collido/oracle/distance_oracle.h>
#include <collido/oracle/triangle_distance.h>

#include "support/test_paths.h"
#include "unit/oracle/peer_poses.h"

namespace collido {
namespace {

using Json = nlohmann::json;
using Triangle = std::array<Eigen::Vector3d, 3>;

using test::jsonVector;

Triangle randomTriangle(std::mt19937_64& rng, double spread) {
  std::uniform_real_distribution<double> u(-spread, spread);
  Triangle t;
  for (auto& p : t)
    p = Eigen::Vector3d(u(rng), u(rng), u(rng));
  return t;
}

Eigen::Vector3d pointOf(const Triangle& t, double s, double r) {
  return t[0] + s * (t[1] - t[0]) + r * (t[2] - t[0]);
}

// Dense barycentric sampling: an upper bound on the distance close to it.
double sampledDistance(const Triangle& a, const Triangle& b, int n) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector3d> pa;
  std::vector<Eigen::Vector3d> pb;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      pa.push_back(pointOf(a, static_cast<double>(i) / n, static_cast<double>(j) / n));
      pb.push_back(pointOf(b, static_cast<double>(i) / n, static_cast<double>(j) / n));
    }
  }
  for (const auto& x : pa) {
    for (const auto& y : pb)
      best = std::min(best, (x - y).norm());
  }
  return best;
}

TriangleMesh singleTriangle(const Triangle& t) {
  TriangleMesh mesh;
  mesh.vertices.resize(3, 3);
  for (int k = 0; k < 3; ++k)
    mesh.vertices.col(k) = t[static_cast<std::size_t>(k)];
  mesh.triangles = Eigen::Matrix3Xi(3, 1);
  mesh.triangles.col(0) << 0, 1, 2;
  return mesh;
}

TEST(TriangleDistance, NeverAboveSamplingAndMatchesTheExactDistance) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const Triangle a = randomTriangle(rng, 1.0);
    Triangle b = randomTriangle(rng, 1.0);
    const Eigen::Vector3d shift(1.5 * (trial % 3), 0.3, -0.2);
    for (auto& p : b)
      p += shift;
    const TriangleClosestPoints closest = closestPointsOfTriangles(a, b);
    EXPECT_NEAR((closest.point_a - closest.point_b).norm(), closest.distance, 1e-12);
    EXPECT_NEAR((closestPointOnTriangle(closest.point_a, a) - closest.point_a).norm(), 0.0, 1e-12);
    EXPECT_NEAR((closestPointOnTriangle(closest.point_b, b) - closest.point_b).norm(), 0.0, 1e-12);
    EXPECT_LE(closest.distance, sampledDistance(a, b, 24) + 1e-12) << "trial " << trial;
    const TriangleMesh ma = singleTriangle(a);
    const TriangleMesh mb = singleTriangle(b);
    const double exact =
        std::sqrt(exactPairSquaredDistance(ma, Pose::Identity(), mb, Pose::Identity(), {0, 0}));
    EXPECT_NEAR(closest.distance, exact, 1e-12) << "trial " << trial;
  }
}

TEST(TriangleDistance, CrossingTrianglesAreAtZeroAtThePiercingPoint) {
  const Triangle a{Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(2, -1, 0),
                   Eigen::Vector3d(-1, 2, 0)};
  const Triangle b{Eigen::Vector3d(0.2, 0.2, -1), Eigen::Vector3d(0.2, 0.3, 1),
                   Eigen::Vector3d(0.3, 0.2, 1)};
  const TriangleClosestPoints closest = closestPointsOfTriangles(a, b);
  EXPECT_EQ(closest.distance, 0.0);
  EXPECT_NEAR(closest.point_a.z(), 0.0, 1e-15);
}

TEST(TriangleDistance, DegenerateTrianglesCountAsSegmentsAndPoints) {
  const Triangle face{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  // A segment (collinear corners) above the face, and a point (three equal corners).
  const Triangle segment{Eigen::Vector3d(0.2, 0.2, 0.5), Eigen::Vector3d(0.2, 0.2, 1.5),
                         Eigen::Vector3d(0.2, 0.2, 1.0)};
  EXPECT_NEAR(closestPointsOfTriangles(face, segment).distance, 0.5, 1e-15);
  EXPECT_NEAR(closestPointsOfTriangles(segment, face).distance, 0.5, 1e-15);
  const Triangle point{Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(2, 0, 0),
                       Eigen::Vector3d(2, 0, 0)};
  EXPECT_NEAR(closestPointsOfTriangles(face, point).distance, 1.0, 1e-15);
  const TriangleMesh mf = singleTriangle(face);
  const TriangleMesh ms = singleTriangle(segment);
  EXPECT_EQ(exactPairSquaredDistance(mf, Pose::Identity(), ms, Pose::Identity(), {0, 0}), 0.25);
}

// The exact closest points against CGAL's exact squared distance (the same value, rounded the
// same way), on random, sliver, near-parallel, crossing and degenerate pairs under random poses:
// each point on its triangle (decided exactly) and the two the distance apart.
TEST(ExactClosestPoints, MatchTheExactSquaredDistanceWithPointsOnTheTriangles) {
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto pose = [&]() {
    const Eigen::Quaterniond q(u(rng), u(rng), u(rng), u(rng));
    Pose p = Pose::Identity();
    p.linear() = q.normalized().toRotationMatrix();
    p.translation() = Eigen::Vector3d(100.0 * u(rng), u(rng), u(rng));
    return p;
  };
  int touching = 0;
  for (int trial = 0; trial < 120; ++trial) {
    Triangle a = randomTriangle(rng, 1.0);
    Triangle b = randomTriangle(rng, 1.0);
    switch (trial % 6) {
      case 1:  // a sliver
        a[2] = 0.5 * (a[0] + a[1]) + 1e-9 * Eigen::Vector3d(u(rng), u(rng), u(rng));
        break;
      case 2:  // b nearly parallel to a, a little apart
        for (int k = 0; k < 3; ++k)
          b[static_cast<std::size_t>(k)] =
              a[static_cast<std::size_t>(k)] + Eigen::Vector3d(0.3, 0.1, 1e-7 * (1 + k));
        break;
      case 3:  // b a segment, then a point
        b[2] = 0.25 * b[0] + 0.75 * b[1];
        break;
      case 4:
        b[1] = b[0];
        b[2] = b[0];
        break;
      default:
        break;
    }
    const Pose pose_a = trial % 2 == 0 ? Pose::Identity() : pose();
    const Pose pose_b = trial % 3 == 0 ? pose_a : pose();
    const ExactClosestPoints got = exactPosedClosestPoints(a, pose_a, b, pose_b);
    const double exact =
        exactPairSquaredDistance(singleTriangle(a), pose_a, singleTriangle(b), pose_b, {0, 0});
    const std::string label = "trial " + std::to_string(trial);
    EXPECT_EQ(got.squared_distance.nearest, exact) << label;
    EXPECT_LE(got.squared_distance.lower, exact) << label;
    EXPECT_GE(got.squared_distance.upper, exact) << label;
    touching += exact == 0.0 ? 1 : 0;
    const double allowed =
        1e-13 * (1.0 + pose_a.translation().norm() + pose_b.translation().norm());
    for (const auto& [point, triangle, posed] :
         {std::make_tuple(got.point_a, a, pose_a), std::make_tuple(got.point_b, b, pose_b)}) {
      const double off =
          exactPosedClosestPoints({point, point, point}, Pose::Identity(), triangle, posed)
              .squared_distance.upper;
      EXPECT_LE(std::sqrt(off), allowed) << label << ": a point off its triangle";
    }
    EXPECT_NEAR((got.point_b - got.point_a).norm(), std::sqrt(exact), allowed) << label;
  }
  EXPECT_GT(touching, 0);
}

TEST(MeshDistance, SpheresAtKnownGapsAndTouching) {
  SphereParams params;
  params.slices = 16;
  params.stacks = 8;  // the equator is a ring, (1, 0, 0) a vertex
  const TriangleMesh sphere = makeSphere(params).value();
  // Its mirror image in x: vertex (1, 0, z) of one meets vertex (-1, 0, z) of the other exactly
  // at gap 0 (a rotation by pi would not be exact: sin(pi) is not 0 in double).
  TriangleMesh mirrored = sphere;
  mirrored.vertices.row(0) *= -1.0;
  for (const double gap : {1.0, 1e-3, 1e-9, 0.0, -0.25}) {
    Pose pose = Pose::Identity();
    pose.translation() = Eigen::Vector3d(2.0 + gap, 0, 0);
    const MeshDistance d = exactMeshDistance(sphere, Pose::Identity(), mirrored, pose);
    // Vertex (1, 0, z) faces its mirror image across the gap.
    EXPECT_NEAR(d.distance, std::max(gap, 0.0), 1e-15 + 1e-12 * std::abs(gap)) << gap;
    EXPECT_EQ(d.distance == 0.0, gap <= 0.0) << gap;
    EXPECT_NEAR((d.point_b - d.point_a).norm(), d.distance, 1e-12);
  }
}

// Every non-colliding pose of the peer case has its exact minimum distance listed; colliding
// ones are at 0.
TEST(MeshDistance, MatchesTheExactDistancesOfTheFortyEnvRobPoses) {
  Result<TriangleMesh> env = loadMesh(test::sourcePath("scenes/meshes/env.obj"));
  Result<TriangleMesh> rob = loadMesh(test::sourcePath("scenes/meshes/rob.obj"));
  ASSERT_TRUE(env.ok() && rob.ok());
  std::ifstream in(test::sourcePath("tests/data/peer_cases/fcl_env_rob_poses.json"));
  const Json cases = Json::parse(in)["cases"];
  int separated = 0;
  for (const Json& c : cases) {
    const Pose pose = test::peerCasePose(c);
    const MeshDistance d = exactMeshDistance(env.value(), pose, rob.value(), Pose::Identity());
    if (c["collide"].get<bool>()) {
      EXPECT_EQ(d.distance, 0.0) << c["id"];
      continue;
    }
    ++separated;
    const double listed = c["min_distance"].get<double>();
    EXPECT_NEAR(d.distance, listed, 4e-16 * listed) << c["id"];
    // The listed closest pair is at the same exact distance (ties are allowed).
    const TrianglePair pair{c["closest_pair_env_rob"][0].get<int>(),
                            c["closest_pair_env_rob"][1].get<int>()};
    EXPECT_EQ(exactPairSquaredDistance(env.value(), pose, rob.value(), Pose::Identity(), pair),
              exactPairSquaredDistance(env.value(), pose, rob.value(), Pose::Identity(), d.pair))
        << c["id"];
    EXPECT_NEAR((d.point_a - jsonVector(c["closest_points_world"][0])).norm() +
                    (d.point_b - jsonVector(c["closest_points_world"][1])).norm(),
                0.0, d.pair == pair ? 1e-9 : 1e300)
        << c["id"];
  }
  EXPECT_EQ(separated, 23);
}

// FCL's tilted cubes "kissing" face to face at +-1e-15 of their size (0.01 to 1000), with the
// exact signed distance of the listed doubles (60-digit arithmetic): the exact mesh distance is
// that distance where they are apart, and 0 where they overlap (their surfaces cross).
TEST(MeshDistance, MatchesFclsKissingCubesAtOneEMinus15) {
  std::ifstream in(test::sourcePath("tests/data/peer_cases/fcl_signed_distance.json"));
  const Json cases = Json::parse(in)["cases"];
  int boxes = 0;
  for (const Json& c : cases) {
    if (c["shapes"][0]["type"] != "box") continue;
    SCOPED_TRACE(c["id"].get<std::string>());
    Result<TriangleMesh> a = makeBox(BoxParams{jsonVector(c["shapes"][0]["size"])});
    Result<TriangleMesh> b = makeBox(BoxParams{jsonVector(c["shapes"][1]["size"])});
    ASSERT_TRUE(a.ok() && b.ok());
    const Pose pose_a = test::peerCasePose(c["shapes"][0]);
    const Pose pose_b = test::peerCasePose(c["shapes"][1]);
    const double truth = c["oracle"]["signed_distance"].get<double>();
    const MeshDistance d = exactMeshDistance(a.value(), pose_a, b.value(), pose_b);
    if (truth < 0.0) {
      EXPECT_EQ(d.distance, 0.0);
    } else {
      EXPECT_NEAR(d.distance, truth, 4e-16 * truth);
    }
    ++boxes;
  }
  EXPECT_EQ(boxes, 10);
}

// A thin gap far from the origin: the search must find the one pair 1e-7 apart among many
// pairs a little further.
TEST(MeshDistance, FindsTheClosestPairOfParallelSheetsFarFromTheOrigin) {
  GridSheetParams params;
  params.cells_x = 16;
  params.cells_y = 16;
  const TriangleMesh sheet = makeGridSheet(params).value();
  TriangleMesh bumped = sheet;
  bumped.vertices(2, 100) -= 0.5 - 1e-7;  // one vertex dips towards the lower sheet
  Pose lower = Pose::Identity();
  lower.translation() = Eigen::Vector3d(1e5, -2e5, 3e4);
  Pose upper = lower;
  upper.translation().z() += 0.5;
  const MeshDistance d = exactMeshDistance(sheet, lower, bumped, upper);
  EXPECT_NEAR(d.distance, 1e-7, 1e-11);
  EXPECT_EQ(bumped.triangles.col(d.pair.b).cwiseEqual(100).any(), true);
}

}  // namespace
}  // namespace collido
