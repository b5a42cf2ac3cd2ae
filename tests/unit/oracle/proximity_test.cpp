// meshesWithinDistance: the distance between posed meshes against a margin, for triangles,
// for the segments and points degenerate triangles are, and at distance 0 the exact answer.
#include <collido/oracle/proximity.h>

#include <cmath>

#include <gtest/gtest.h>

#include <collido/mesh/procedural.h>

namespace collido {
namespace {

TriangleMesh triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                      const Eigen::Vector3d& c) {
  TriangleMesh mesh;
  mesh.vertices.resize(3, 3);
  mesh.vertices << a, b, c;
  mesh.triangles.resize(3, 1);
  mesh.triangles << 0, 1, 2;
  return mesh;
}

Pose shifted(double x, double y, double z) {
  Pose pose = Pose::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

TEST(Proximity, ParallelTrianglesHalfApart) {
  const TriangleMesh t = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const ProximityAnswer near =
      meshesWithinDistance(t, Pose::Identity(), t, shifted(0, 0, 0.5), 0.6);
  EXPECT_TRUE(near.within);
  EXPECT_NEAR(near.closest, 0.5, 1e-12);
  // Corner (0.6, 0.6) of the shifted copy faces the hypotenuse x + y = 1 at 0.2 / sqrt(2):
  // the boxes meet within 0.1, the triangles do not.
  const ProximityAnswer corner =
      meshesWithinDistance(t, Pose::Identity(), t, shifted(0.6, 0.6, 0), 0.1);
  EXPECT_FALSE(corner.within);
  EXPECT_GT(corner.candidate_pairs, 0u);
  EXPECT_NEAR(corner.closest, 0.2 / std::sqrt(2.0), 1e-12);
  // Beside each other in x: boxes apart by more than the margin, no candidate at all.
  const ProximityAnswer apart = meshesWithinDistance(t, Pose::Identity(), t, shifted(3, 0, 0), 0.5);
  EXPECT_FALSE(apart.within);
  EXPECT_EQ(apart.candidate_pairs, 0u);
  EXPECT_TRUE(std::isinf(apart.closest));
}

TEST(Proximity, DegenerateTrianglesAreSegmentsAndPoints) {
  const TriangleMesh t = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const TriangleMesh segment = triangle({0.2, 0.2, 0.3}, {0.4, 0.2, 0.3}, {0.8, 0.2, 0.3});
  const TriangleMesh point = triangle({0.1, 0.1, -0.2}, {0.1, 0.1, -0.2}, {0.1, 0.1, -0.2});
  EXPECT_NEAR(meshesWithinDistance(t, Pose::Identity(), segment, Pose::Identity(), 1.0).closest,
              0.3, 1e-12);
  EXPECT_FALSE(meshesWithinDistance(t, Pose::Identity(), segment, Pose::Identity(), 0.29).within);
  EXPECT_NEAR(meshesWithinDistance(point, Pose::Identity(), t, Pose::Identity(), 1.0).closest, 0.2,
              1e-12);
  EXPECT_NEAR(meshesWithinDistance(point, Pose::Identity(), segment, Pose::Identity(), 1.0).closest,
              std::sqrt(0.1 * 0.1 + 0.1 * 0.1 + 0.5 * 0.5), 1e-12);
  // A segment piercing the triangle is at distance 0.
  const TriangleMesh piercing = triangle({0.2, 0.2, -1}, {0.2, 0.2, 0}, {0.2, 0.2, 1});
  EXPECT_EQ(meshesWithinDistance(t, Pose::Identity(), piercing, Pose::Identity(), 0.01).closest,
            0.0);
}

TEST(Proximity, SpheresAtAGapAndAtDistanceZero) {
  const TriangleMesh sphere = makeSphere(SphereParams{1.0, 24, 12}).value();
  // Centres 2.1 apart: a gap of a little more than 0.1 (the facets lie inside the sphere).
  EXPECT_TRUE(
      meshesWithinDistance(sphere, Pose::Identity(), sphere, shifted(2.1, 0, 0), 0.2).within);
  EXPECT_FALSE(
      meshesWithinDistance(sphere, Pose::Identity(), sphere, shifted(2.1, 0, 0), 0.09).within);
  // Distance 0 is the exact oracle: overlap counts, and touching at a shared vertex.
  EXPECT_TRUE(
      meshesWithinDistance(sphere, Pose::Identity(), sphere, shifted(1.9, 0, 0), 0.0).within);
  const TriangleMesh t = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_TRUE(meshesWithinDistance(t, Pose::Identity(), t, shifted(1, 0, 0), 0.0).within);
  EXPECT_FALSE(
      meshesWithinDistance(sphere, Pose::Identity(), sphere, shifted(2.1, 0, 0), 0.0).within);
}

}  // namespace
}  // namespace collido
