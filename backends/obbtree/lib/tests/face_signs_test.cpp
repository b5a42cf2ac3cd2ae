// Planar faces found at build (ObbTree::faceOf, faceTurn), the per-query table of face signs,
// and flush contact between tessellated flat parts, where every triangle pair of two touching
// faces reads the signs its face decided once: answers checked against the exact oracle.
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/mesh/procedural.h>
#include <collido/obbtree/tree.h>

#include "../src/face_signs.h"
#include "collide_check.h"

namespace collido::obbtree {
namespace {

using Eigen::Vector3d;

TriangleMesh boxForFaces() {
  BoxParams params;
  params.size = Vector3d(2.0, 1.0, 3.0);
  return unwrap(makeBox(params), "box");
}

// A flat sheet in the plane z = 0, cells_x by cells_y cells of two triangles.
TriangleMesh flatSheetForFaces(double width, double depth, int cells_x, int cells_y) {
  GridSheetParams params;
  params.width = width;
  params.depth = depth;
  params.cells_x = cells_x;
  params.cells_y = cells_y;
  return unwrap(makeGridSheet(params), "sheet");
}

// Each triangle with vertices of its own, so that no index is shared.
TriangleMesh unweldedCopy(const TriangleMesh& mesh) {
  TriangleMesh out;
  out.vertices.resize(3, 3 * mesh.triangles.cols());
  out.triangles.resize(3, mesh.triangles.cols());
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    for (int c = 0; c < 3; ++c) {
      out.vertices.col(3 * t + c) = mesh.vertices.col(mesh.triangles(c, t));
      out.triangles(c, t) = static_cast<int>(3 * t + c);
    }
  }
  return out;
}

ObbTree singleTriangleLeafTree(const TriangleMesh& mesh) {
  return ObbTree::build(mesh.vertices, mesh.triangles);
}

// The leaf position of each input triangle.
std::vector<std::int32_t> leafPositionsOf(const ObbTree& tree) {
  std::vector<std::int32_t> position(tree.triangleCount());
  for (std::int32_t k = 0; k < static_cast<std::int32_t>(tree.triangleCount()); ++k)
    position[static_cast<std::size_t>(tree.triangleId(k))] = k;
  return position;
}

std::size_t distinctFaces(const ObbTree& tree) {
  std::set<std::int32_t> faces;
  for (std::int32_t k = 0; k < static_cast<std::int32_t>(tree.triangleCount()); ++k)
    faces.insert(tree.faceOf(k));
  return faces.size();
}

TEST(PlanarFaces, ABoxHasSixFacesOfTwoTrianglesTurningAlike) {
  for (const bool welded : {true, false}) {
    const TriangleMesh mesh = welded ? boxForFaces() : unweldedCopy(boxForFaces());
    const ObbTree tree = singleTriangleLeafTree(mesh);
    EXPECT_EQ(distinctFaces(tree), 6u) << (welded ? "welded" : "a vertex per corner");
    for (std::int32_t k = 0; k < static_cast<std::int32_t>(tree.triangleCount()); ++k) {
      const std::int32_t face = tree.faceOf(k);
      EXPECT_EQ(tree.faceOf(face), face) << "a face is named by one of its triangles";
      EXPECT_EQ(tree.faceTurn(k), 1) << "a closed, consistently wound box";
      // The triangle lies in its face's plane, and no other box face's.
      const Vector3d normal = (mesh.vertices.col(mesh.triangles(1, tree.triangleId(k))) -
                               mesh.vertices.col(mesh.triangles(0, tree.triangleId(k))))
                                  .cross(mesh.vertices.col(mesh.triangles(2, tree.triangleId(k))) -
                                         mesh.vertices.col(mesh.triangles(0, tree.triangleId(k))));
      const Vector3d face_normal =
          (mesh.vertices.col(mesh.triangles(1, tree.triangleId(face))) -
           mesh.vertices.col(mesh.triangles(0, tree.triangleId(face))))
              .cross(mesh.vertices.col(mesh.triangles(2, tree.triangleId(face))) -
                     mesh.vertices.col(mesh.triangles(0, tree.triangleId(face))));
      EXPECT_NEAR(normal.normalized().dot(face_normal.normalized()), 1.0, 1e-12);
    }
  }
}

TEST(PlanarFaces, AFlatSheetIsOneFaceAndAReversedTriangleTurnsAgainstIt) {
  TriangleMesh mesh = flatSheetForFaces(2.0, 1.5, 6, 4);
  std::swap(mesh.triangles(1, 5), mesh.triangles(2, 5));  // input triangle 5 wound the other way
  const ObbTree tree = singleTriangleLeafTree(mesh);
  EXPECT_EQ(distinctFaces(tree), 1u);
  const std::vector<std::int32_t> position = leafPositionsOf(tree);
  const std::int32_t reversed = position[5];
  const int others = tree.faceTurn(position[0] == reversed ? position[1] : position[0]);
  EXPECT_EQ(tree.faceTurn(reversed), -others);
  for (std::int32_t k = 0; k < static_cast<std::int32_t>(tree.triangleCount()); ++k) {
    if (k != reversed) {
      EXPECT_EQ(tree.faceTurn(k), others) << "position " << k;
    }
  }
}

TEST(PlanarFaces, CurvedMeshesKeepATriangleAFaceAndARefitForgetsTheFaces) {
  SphereParams params;
  params.slices = 12;
  params.stacks = 8;
  const ObbTree sphere = singleTriangleLeafTree(unwrap(makeSphere(params), "sphere"));
  for (std::int32_t k = 0; k < static_cast<std::int32_t>(sphere.triangleCount()); ++k) {
    EXPECT_EQ(sphere.faceOf(k), k);
    EXPECT_EQ(sphere.faceTurn(k), 1);
  }
  TriangleMesh mesh = flatSheetForFaces(2.0, 2.0, 4, 4);
  ObbTree tree = singleTriangleLeafTree(mesh);
  ASSERT_EQ(distinctFaces(tree), 1u);
  mesh.vertices(2, 7) = 0.25;  // one vertex lifted off the plane
  tree.refit(mesh.vertices);
  EXPECT_EQ(distinctFaces(tree), tree.triangleCount());
}

TEST(FaceSignCache, KeepsSignsForOneQueryAndGrowsWithoutLosingThem) {
  detail::FaceSignCache cache;
  cache.begin();
  EXPECT_EQ(cache.find(0, 3, 4), detail::FaceSignCache::kNone);
  for (std::int32_t v = 0; v < 5000; ++v)
    cache.store(v % 2, v / 2, v, v % 3 - 1);
  for (std::int32_t v = 0; v < 5000; ++v)
    ASSERT_EQ(cache.find(v % 2, v / 2, v), v % 3 - 1) << v;
  EXPECT_EQ(cache.find(1, 0, 0), detail::FaceSignCache::kNone) << "the object is part of the key";
  cache.begin();
  EXPECT_EQ(cache.find(0, 0, 0), detail::FaceSignCache::kNone) << "a new query forgets";
}

// Two tessellated flat parts face to face in one plane, their grids offset so that edges cross,
// corners fall on edges and whole triangles overlap: every pair decided, each face's signs kept.
TEST(FaceSignCollide, FlushSheetsAgreeWithTheOracle) {
  const TriangleMesh a = flatSheetForFaces(2.0, 1.5, 8, 6);
  TriangleMesh b = flatSheetForFaces(1.25, 1.0, 5, 4);
  for (Eigen::Index t = 0; t < b.triangles.cols(); t += 3)  // some wound the other way
    std::swap(b.triangles(1, t), b.triangles(2, t));
  const ObbTree tree_a = singleTriangleLeafTree(a);
  const ObbTree tree_b = singleTriangleLeafTree(b);
  const ObbTree leaves_a = ObbTree::build(a.vertices, a.triangles, BuildOptions{4, true});
  ASSERT_EQ(distinctFaces(tree_a), 1u);
  ASSERT_EQ(distinctFaces(tree_b), 1u);
  // Rotations about z keep the plane z = 0 exactly (their z rows are exact); the quarter turn
  // maps every coordinate exactly (A's frame), the others only z (the world's double-doubles).
  const Eigen::Matrix3d quarter = (Eigen::Matrix3d() << 0, -1, 0, 1, 0, 0, 0, 0, 1).finished();
  const Eigen::Matrix3d turns[] = {Eigen::Matrix3d::Identity(), quarter,
                                   Eigen::AngleAxisd(0.3, Vector3d::UnitZ()).toRotationMatrix(),
                                   Eigen::AngleAxisd(2.0, Vector3d::UnitZ()).toRotationMatrix()};
  const Vector3d offsets[] = {Vector3d(0.0, 0.0, 0.0), Vector3d(0.125, 0.25, 0.0),
                              Vector3d(-0.3, 0.1, 0.0), Vector3d(0.0, 0.0, 1e-12)};
  int touching = 0;
  for (int r = 0; r < 4; ++r) {
    for (int o = 0; o < 4; ++o) {
      const Pose pose_a = makePose(Eigen::Matrix3d::Identity(), Vector3d(0.5, -0.25, 2.0));
      const Pose pose_b = makePose(turns[r], Vector3d(0.5, -0.25, 2.0) + offsets[o]);
      const std::string label = "turn " + std::to_string(r) + ", offset " + std::to_string(o);
      const Outcome outcome = checkQuery(a, tree_a, pose_a, b, tree_b, pose_b, label);
      checkQuery(a, leaves_a, pose_a, b, tree_b, pose_b, label + ", leaves of 4, float boxes");
      touching += outcome.truth.empty() ? 0 : 1;
      if (HasFailure()) return;
    }
  }
  EXPECT_EQ(touching, 12) << "every pose in the plane touches; the lifted ones do not";
}

// A box through or standing on a sheet whose triangles are wound both ways: the sides of the
// box's corners against the sheet's one face are kept once and read by every sheet triangle,
// each turned by that triangle's own winding.
TEST(FaceSignCollide, ABoxThroughOrOnASheetWoundBothWaysAgreesWithTheOracle) {
  TriangleMesh sheet = flatSheetForFaces(2.0, 1.5, 8, 6);
  for (Eigen::Index t = 0; t < sheet.triangles.cols(); t += 3)
    std::swap(sheet.triangles(1, t), sheet.triangles(2, t));
  BoxParams params;
  params.size = Vector3d(0.7, 0.5, 0.6);
  const TriangleMesh block = unwrap(makeBox(params), "box");
  const ObbTree tree_a = singleTriangleLeafTree(sheet);
  const ObbTree tree_b = singleTriangleLeafTree(block);
  const Eigen::Matrix3d quarter = (Eigen::Matrix3d() << 0, -1, 0, 1, 0, 0, 0, 0, 1).finished();
  const Eigen::Matrix3d turns[] = {Eigen::Matrix3d::Identity(), quarter,
                                   Eigen::AngleAxisd(0.3, Vector3d::UnitZ()).toRotationMatrix()};
  int touching = 0;
  for (int r = 0; r < 3; ++r) {
    for (const double lift : {0.0, 0.3, 0.125}) {  // through, standing on, half through
      for (const Vector3d& at :
           {Vector3d(0.0, 0.0, 0.0), Vector3d(0.25, -0.125, 0.0), Vector3d(-0.6, 0.4, 0.0)}) {
        const Pose pose_a = makePose(Eigen::Matrix3d::Identity(), Vector3d(1.0, 2.0, -0.5));
        const Pose pose_b =
            makePose(turns[r], Vector3d(1.0, 2.0, -0.5) + at + Vector3d(0.0, 0.0, lift));
        const std::string label = "turn " + std::to_string(r) + ", lift " + std::to_string(lift);
        touching +=
            checkQuery(sheet, tree_a, pose_a, block, tree_b, pose_b, label).truth.empty() ? 0 : 1;
        if (HasFailure()) return;
      }
    }
  }
  EXPECT_EQ(touching, 27);
}

}  // namespace
}  // namespace collido::obbtree
