// The OBB tree's distance at contact scale, against the exact reference distance: cubes apart
// by one ulp to 1e-9 far from the origin, sliver triangles crossing at a tiny angle or shifted
// by 2^-30 to 2^-50, and zero-area triangles on, just off and just inside a cube's face, edge
// and corner. Every answer is 0 exactly when the meshes touch, its interval holds the exact
// distance, and its value is within the documented relative width of it.
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <collido/mesh/procedural.h>
#include <collido/obbtree/distance.h>
#include <collido/oracle/distance_oracle.h>

#include "collide_check.h"

namespace collido::obbtree {
namespace {

constexpr double kU = 0x1p-53;

TriangleMesh singleTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                            const Eigen::Vector3d& r) {
  TriangleMesh mesh;
  mesh.vertices.resize(3, 3);
  mesh.vertices << p, q, r;
  mesh.triangles.resize(3, 1);
  mesh.triangles << 0, 1, 2;
  return mesh;
}

// The answer against the exact distance (the reference is within two ulps of it).
void expectCertified(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                     const Pose& pose_b, const std::string& label) {
  const ObbTree tree_a = ObbTree::build(a.vertices, a.triangles);
  const ObbTree tree_b = ObbTree::build(b.vertices, b.triangles);
  DistanceAnswer got;
  distance(tree_a, pose_a, tree_b, pose_b, DistanceRequest{}, got);
  const double exact = exactMeshDistance(a, pose_a, b, pose_b).distance;
  EXPECT_EQ(got.distance == 0.0, exact == 0.0) << label << ": " << got.distance << " vs " << exact;
  EXPECT_LE(got.lower_bound, exact * (1.0 + 4.0 * kU)) << label;
  EXPECT_GE(got.upper_bound, exact * (1.0 - 4.0 * kU)) << label;
  EXPECT_LE(got.lower_bound, got.distance) << label;
  EXPECT_LE(got.distance, got.upper_bound) << label;
  EXPECT_LE(std::abs(got.distance - exact), (0x1p-19 + 8.0 * kU) * exact) << label;
}

std::string describe(const char* what, double x, double y) {
  std::ostringstream out;
  out << what << " " << x << " " << y;
  return out.str();
}

// A unit cube's mesh with its vertices moved by `offset` (the coordinates themselves far from
// the origin, not only the pose).
TriangleMesh cubeAt(const Eigen::Vector3d& offset) {
  TriangleMesh cube = unwrap(makeBox(BoxParams{}), "box");
  cube.vertices.colwise() += offset;
  return cube;
}

TEST(DistanceAtContactScale, CubesTouchingAndApartFarFromTheOrigin) {
  std::mt19937_64 rng(26);
  for (const double at : {0.0, 1.0, 1e3, 1e6, 1e8}) {
    const double touching = at + 1.0;
    for (const double gap : {0.0, -1.0, 1e-12, 1e-9}) {
      // gap -1: the next double after touching, one ulp apart.
      const double shifted =
          gap < 0.0 ? std::nextafter(touching, 2.0 * touching + 1.0) : touching + gap;
      const std::string label = describe("cubes at", at, gap);
      // Apart along x in the poses, the meshes at the origin.
      const TriangleMesh cube = cubeAt(Eigen::Vector3d::Zero());
      expectCertified(cube, makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(at, 0.0, 0.0)),
                      cube,
                      makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(shifted, 0.25, -0.125)),
                      label + " (poses)");
      // The same in the meshes' coordinates, under the identity and under one shared turn.
      const TriangleMesh a = cubeAt(Eigen::Vector3d(at, 0.0, 0.0));
      const TriangleMesh b = cubeAt(Eigen::Vector3d(shifted, 0.25, -0.125));
      expectCertified(a, Pose::Identity(), b, Pose::Identity(), label + " (coordinates)");
      const Pose turned = makePose(randomRotation(rng), Eigen::Vector3d(-at, 3.0, 0.5));
      expectCertified(a, turned, b, turned, label + " (turned)");
    }
  }
}

TEST(DistanceAtContactScale, SliverTrianglesCrossingAndApart) {
  const double width = 0x1p-21;
  const TriangleMesh sliver =
      singleTriangle(Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(1.0, 0.0, 0.0),
                     Eigen::Vector3d(0.5, width, 0.0));
  const double angle = 3e-7;
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()).toRotationMatrix();
  for (const double shift : {0.0, 0x1p-30, 0x1p-40, 0x1p-50, -0x1p-40}) {
    // B turned about the x axis through the middle of A's width, so that it crosses A's plane
    // inside A at shift 0, then lifted by `shift`.
    const Eigen::Vector3d pivot(0.0, width / 2, 0.0);
    const Pose pose_b = makePose(tilt, pivot - tilt * pivot + Eigen::Vector3d(0.0, 0.0, shift));
    expectCertified(sliver, Pose::Identity(), sliver, pose_b, describe("slivers", shift, 0.0));
    // Apart in the plane: B slid beyond A's far corner by `shift`.
    const Pose beside =
        makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0 + std::abs(shift), 0.0, 0.0));
    expectCertified(sliver, Pose::Identity(), sliver, beside, describe("side by side", shift, 0.0));
  }
}

TEST(DistanceAtContactScale, ZeroAreaTrianglesOnAndNearAFaceAnEdgeAndACorner) {
  const TriangleMesh cube = unwrap(makeBox(BoxParams{}), "box");
  const double half = 0.5;
  const double out = std::nextafter(half, 1.0);
  const double in = std::nextafter(half, 0.0);
  const Eigen::Vector3d features[] = {
      {half, 0.125, -0.25},  // on a face
      {half, half, 0.1},     // on an edge
      {half, half, half},    // a corner
  };
  for (const Eigen::Vector3d& feature : features) {
    for (const double x : {half, out, in}) {
      for (const double y :
           {feature.y(), std::nextafter(feature.y(), 1.0), std::nextafter(feature.y(), -1.0)}) {
        const Eigen::Vector3d p(x, y, feature.z());
        // A point, and a segment from it along the face's normal, both zero-area triangles.
        const TriangleMesh point = singleTriangle(p, p, p);
        const TriangleMesh segment = singleTriangle(p, p + Eigen::Vector3d(0.25, 0.0, 0.0), p);
        for (const double at : {0.0, 1e3}) {
          const Pose pose = makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(at, at, 0.0));
          const std::string where = describe(" at", p.z(), at);
          expectCertified(cube, pose, point, pose, describe("point", x, y) + where);
          expectCertified(cube, pose, segment, pose, describe("segment", x, y) + where);
        }
      }
    }
  }
}

}  // namespace
}  // namespace collido::obbtree
