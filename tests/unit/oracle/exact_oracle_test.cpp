#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/mesh/mesh_io.h>
#include <collido/oracle/exact_oracle.h>

#include "support/test_paths.h"
#include "unit/oracle/peer_poses.h"

namespace collido {
namespace {

using Json = nlohmann::json;
using Triangle = std::array<Eigen::Vector3d, 3>;

Json readJson(const std::string& relative) {
  std::ifstream in(test::sourcePath(relative));
  EXPECT_TRUE(in.good()) << relative;
  return Json::parse(in);
}

using test::jsonVector;

Triangle triangle(const Json& j) {
  return {jsonVector(j[0]), jsonVector(j[1]), jsonVector(j[2])};
}

TriangleMesh meshOf(const std::vector<Triangle>& triangles) {
  TriangleMesh mesh;
  mesh.vertices.resize(3, static_cast<Eigen::Index>(3 * triangles.size()));
  mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      mesh.vertices.col(static_cast<Eigen::Index>(3 * t + k)) = triangles[t][k];
    }
    const int base = static_cast<int>(3 * t);
    mesh.triangles.col(static_cast<Eigen::Index>(t)) << base, base + 1, base + 2;
  }
  return mesh;
}

Pose translation(const Eigen::Vector3d& t) {
  Pose pose = Pose::Identity();
  pose.translation() = t;
  return pose;
}

TEST(ExactOracle, AgreesWithEveryPeerTriangleCase) {
  const Json cases = readJson("tests/data/peer_cases/triangle_triangle.json")["cases"];
  ASSERT_EQ(cases.size(), 23u);
  for (const Json& c : cases) {
    const Triangle t1 = triangle(c["tri1"]);
    const Triangle t2 = triangle(c["tri2"]);
    const bool expected = c["oracle"]["intersect"].get<bool>();
    EXPECT_EQ(exactTrianglesIntersect(t1, t2), expected) << c["id"];
    EXPECT_EQ(exactTrianglesIntersect(t2, t1), expected) << c["id"] << " (swapped)";
  }
}

TEST(ExactOracle, GivesTheListedPairsForTheFortyEnvRobPoses) {
  Result<TriangleMesh> env = loadMesh(test::sourcePath("scenes/meshes/env.obj"));
  Result<TriangleMesh> rob = loadMesh(test::sourcePath("scenes/meshes/rob.obj"));
  ASSERT_TRUE(env.ok()) << env.status().message();
  ASSERT_TRUE(rob.ok()) << rob.status().message();
  const Json cases = readJson("tests/data/peer_cases/fcl_env_rob_poses.json")["cases"];
  ASSERT_EQ(cases.size(), 40u);
  int colliding = 0;
  for (const Json& c : cases) {
    const Pose pose = test::peerCasePose(c);
    std::vector<TrianglePair> expected;
    for (const Json& p : c["intersecting_pairs_env_rob"]) {
      expected.push_back(TrianglePair{p[0].get<int>(), p[1].get<int>()});
    }
    std::sort(expected.begin(), expected.end());
    const OracleAnswer answer =
        exactIntersectingPairs(env.value(), pose, rob.value(), Pose::Identity());
    EXPECT_EQ(answer.intersecting, c["collide"].get<bool>()) << c["id"];
    EXPECT_EQ(answer.pairs, expected)
        << c["id"] << ": " << answer.pairs.size() << " pairs vs " << expected.size() << " listed";
    colliding += answer.intersecting ? 1 : 0;
  }
  EXPECT_EQ(colliding, 17);
}

// The oracle poses vertices exactly: a vertex 1e-20 above a plane at z = 1 stays above it,
// although 1 + 1e-20 rounds to 1 in double precision.
TEST(ExactOracle, PosesVerticesInExactArithmetic) {
  const TriangleMesh floor = meshOf(
      {Triangle{Eigen::Vector3d(-1, -1, 1), Eigen::Vector3d(3, -1, 1), Eigen::Vector3d(-1, 3, 1)}});
  // Lowest corner at z = tiny in the model frame, the rest well above.
  for (const double tiny : {1e-20, -1e-20}) {
    const TriangleMesh tooth =
        meshOf({Triangle{Eigen::Vector3d(0.2, 0.2, tiny), Eigen::Vector3d(0.4, 0.2, 0.5),
                         Eigen::Vector3d(0.2, 0.4, 0.5)}});
    const Pose lift = translation(Eigen::Vector3d(0, 0, 1));
    ASSERT_EQ(1.0 + tiny, 1.0);  // the rounded pose would make the corner touch the floor
    const OracleAnswer answer = exactIntersectingPairs(tooth, lift, floor, Pose::Identity());
    EXPECT_EQ(answer.intersecting, tiny < 0.0) << "corner offset " << tiny;
  }
}

TEST(ExactOracle, TouchingCountsAsIntersecting) {
  // Two unit squares (two triangles each) sharing only the edge x = 1.
  const auto square = [](double x0) {
    return meshOf({Triangle{Eigen::Vector3d(x0, 0, 0), Eigen::Vector3d(x0 + 1, 0, 0),
                            Eigen::Vector3d(x0 + 1, 1, 0)},
                   Triangle{Eigen::Vector3d(x0, 0, 0), Eigen::Vector3d(x0 + 1, 1, 0),
                            Eigen::Vector3d(x0, 1, 0)}});
  };
  const OracleAnswer touching =
      exactIntersectingPairs(square(0.0), Pose::Identity(), square(1.0), Pose::Identity());
  EXPECT_TRUE(touching.intersecting);
  // Square 0's triangle 0 owns the edge x = 1 (from (1,0) to (1,1)); square 1's triangle 1 owns
  // the edge x = 1 too; the other two triangles meet them only at corners (1,0) and (1,1).
  const std::vector<TrianglePair> expected = {{0, 0}, {0, 1}, {1, 1}};
  EXPECT_EQ(touching.pairs, expected);
  const OracleAnswer apart =
      exactIntersectingPairs(square(0.0), Pose::Identity(), square(1.0 + 1e-15), Pose::Identity());
  EXPECT_FALSE(apart.intersecting);
}

TEST(ExactOracle, DecidesDegenerateTrianglesAsSegmentsAndPoints) {
  const Triangle face{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(0, 2, 0)};
  // A segment (collinear corners) piercing the face, and one passing beside it.
  const Triangle piercing{Eigen::Vector3d(0.5, 0.5, -1), Eigen::Vector3d(0.5, 0.5, 0.0),
                          Eigen::Vector3d(0.5, 0.5, 1)};
  const Triangle beside{Eigen::Vector3d(1.5, 1.5, -1), Eigen::Vector3d(1.5, 1.5, 0.0),
                        Eigen::Vector3d(1.5, 1.5, 1)};
  EXPECT_TRUE(exactTrianglesIntersect(face, piercing));
  EXPECT_FALSE(exactTrianglesIntersect(face, beside));
  // A point (three equal corners) on the hypotenuse, and just off it.
  const Triangle on_edge{Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(1, 1, 0),
                         Eigen::Vector3d(1, 1, 0)};
  const Triangle off_edge{Eigen::Vector3d(1, 1 + 0x1p-40, 0), Eigen::Vector3d(1, 1 + 0x1p-40, 0),
                          Eigen::Vector3d(1, 1 + 0x1p-40, 0)};
  EXPECT_TRUE(exactTrianglesIntersect(face, on_edge));
  EXPECT_FALSE(exactTrianglesIntersect(face, off_edge));
  EXPECT_TRUE(exactTrianglesIntersect(on_edge, on_edge));
  EXPECT_FALSE(exactTrianglesIntersect(on_edge, off_edge));
  // Collinear segments that overlap, and that only nearly meet.
  const Triangle left{Eigen::Vector3d(0, 0, 5), Eigen::Vector3d(1, 1, 5), Eigen::Vector3d(2, 2, 5)};
  const Triangle right{Eigen::Vector3d(2, 2, 5), Eigen::Vector3d(3, 3, 5),
                       Eigen::Vector3d(4, 4, 5)};
  const Triangle further{Eigen::Vector3d(2.5, 2.5, 5), Eigen::Vector3d(3, 3, 5),
                         Eigen::Vector3d(4, 4, 5)};
  EXPECT_TRUE(exactTrianglesIntersect(left, right));
  EXPECT_FALSE(exactTrianglesIntersect(left, further));
}

std::vector<Triangle> randomSoup(std::mt19937_64& rng, int count, double spread, double size,
                                 bool flat) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Triangle> soup;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d c(spread * u(rng), spread * u(rng), flat ? 0.0 : spread * u(rng));
    // Every tenth triangle is large, so cells hold very different amounts.
    const double s = (i % 10 == 0) ? 10.0 * size : size;
    Triangle t;
    for (auto& corner : t) {
      corner = c + s * Eigen::Vector3d(u(rng), u(rng), flat ? 0.0 : u(rng));
    }
    soup.push_back(t);
  }
  return soup;
}

// The grid only prunes: it must find exactly what testing every pair finds.
TEST(ExactOracle, GridPrefilterLosesNoPair) {
  std::mt19937_64 rng(42);
  for (int trial = 0; trial < 12; ++trial) {
    const bool flat = trial % 3 == 0;
    const std::vector<Triangle> a = randomSoup(rng, 60, 2.0, 0.3, flat);
    const std::vector<Triangle> b = randomSoup(rng, 50, 2.0, 0.3, flat);
    std::vector<TrianglePair> brute;
    for (std::size_t i = 0; i < a.size(); ++i) {
      for (std::size_t j = 0; j < b.size(); ++j) {
        if (exactTrianglesIntersect(a[i], b[j])) {
          brute.push_back(TrianglePair{static_cast<int>(i), static_cast<int>(j)});
        }
      }
    }
    const OracleAnswer answer =
        exactIntersectingPairs(meshOf(a), Pose::Identity(), meshOf(b), Pose::Identity());
    EXPECT_EQ(answer.pairs, brute) << "trial " << trial;
    EXPECT_FALSE(brute.empty()) << "trial " << trial << " has no pairs to lose";
  }
}

TEST(ExactOracle, FirstPairModeGivesOneRealPair) {
  std::mt19937_64 rng(43);
  const TriangleMesh a = meshOf(randomSoup(rng, 80, 1.0, 0.3, false));
  const TriangleMesh b = meshOf(randomSoup(rng, 80, 1.0, 0.3, false));
  const OracleAnswer all = exactIntersectingPairs(a, Pose::Identity(), b, Pose::Identity());
  const OracleAnswer first =
      exactIntersectingPairs(a, Pose::Identity(), b, Pose::Identity(), OracleMode::kFirstPair);
  ASSERT_GT(all.pairs.size(), 1u);
  ASSERT_EQ(first.pairs.size(), 1u);
  EXPECT_TRUE(first.intersecting);
  EXPECT_TRUE(std::binary_search(all.pairs.begin(), all.pairs.end(), first.pairs[0]));
  EXPECT_TRUE(exactPairIntersects(a, Pose::Identity(), b, Pose::Identity(), first.pairs[0]));

  const OracleAnswer apart = exactIntersectingPairs(
      a, Pose::Identity(), b, translation(Eigen::Vector3d(100, 0, 0)), OracleMode::kFirstPair);
  EXPECT_FALSE(apart.intersecting);
  EXPECT_TRUE(apart.pairs.empty());
}

}  // namespace
}  // namespace collido

namespace collido {
namespace {

// Whether `p` lies on triangle `t` of `mesh` posed by `pose`, to within `allowed` (decided
// exactly: the point as a zero-area triangle against the posed one).
bool onTriangle(const Eigen::Vector3d& p, const TriangleMesh& mesh, const Pose& pose,
                std::int32_t t, double allowed) {
  std::array<Eigen::Vector3d, 3> corners;
  for (int k = 0; k < 3; ++k)
    corners[static_cast<std::size_t>(k)] = mesh.corner(static_cast<std::size_t>(t), k);
  return std::sqrt(exactPosedClosestPoints({p, p, p}, Pose::Identity(), corners, pose)
                       .squared_distance.upper) <= allowed;
}

// The exact intersection of a pair: a segment for crossing triangles, a polygon for coplanar
// overlapping ones, a point for corner contact, nothing for disjoint ones; every point on both
// triangles to rounding, under random poses too.
TEST(ExactIntersectionSet, ShapesOfCrossingCoplanarTouchingAndDisjointPairs) {
  const Triangle floor_triangle{Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(2, -1, 0),
                                Eigen::Vector3d(-1, 2, 0)};
  const Triangle crossing{Eigen::Vector3d(0.2, 0.2, -1), Eigen::Vector3d(0.2, 0.3, 1),
                          Eigen::Vector3d(0.3, 0.2, 1)};
  const Triangle coplanar{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3, 0, 0),
                          Eigen::Vector3d(0, 3, 0)};
  const Triangle corner{Eigen::Vector3d(2, -1, 0), Eigen::Vector3d(3, -1, 1),
                        Eigen::Vector3d(3, 0, 1)};
  const Triangle apart{Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1),
                       Eigen::Vector3d(0, 1, 1)};
  const struct {
    const Triangle* other;
    ExactIntersection::Shape shape;
    const char* label;
  } cases[] = {{&crossing, ExactIntersection::Shape::kSegment, "crossing"},
               {&coplanar, ExactIntersection::Shape::kPolygon, "coplanar"},
               {&corner, ExactIntersection::Shape::kPoint, "corner"},
               {&apart, ExactIntersection::Shape::kEmpty, "apart"}};
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int posed = 0; posed < 2; ++posed) {
    Pose pose = Pose::Identity();
    if (posed == 1) {
      pose.linear() =
          Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
      pose.translation() = Eigen::Vector3d(1e3 * u(rng), u(rng), u(rng));
    }
    const TriangleMesh a = meshOf({floor_triangle});
    for (const auto& c : cases) {
      const TriangleMesh b = meshOf({*c.other});
      const ExactIntersection got = exactPairIntersection(a, pose, b, pose, {0, 0});
      EXPECT_EQ(got.shape, c.shape) << c.label << " posed " << posed;
      const std::size_t expected = c.shape == ExactIntersection::Shape::kEmpty     ? 0u
                                   : c.shape == ExactIntersection::Shape::kPoint   ? 1u
                                   : c.shape == ExactIntersection::Shape::kSegment ? 2u
                                                                                   : 3u;
      EXPECT_GE(got.points.size(), expected) << c.label;
      const double allowed = 1e-13 * (1.0 + pose.translation().norm());
      for (const Eigen::Vector3d& p : got.points) {
        EXPECT_TRUE(onTriangle(p, a, pose, 0, allowed)) << c.label << " posed " << posed;
        EXPECT_TRUE(onTriangle(p, b, pose, 0, allowed)) << c.label << " posed " << posed;
      }
    }
  }
}

}  // namespace
}  // namespace collido
