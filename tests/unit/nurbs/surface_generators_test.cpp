// The generated surfaces are what they claim: exact sphere zones and saddles, valid sheets and
// blades.
#include <cmath>

#include <gtest/gtest.h>

#include <collido/nurbs/surface_generators.h>
#include <collido/nurbs/tessellate.h>

namespace collido::nurbs {
namespace {

TEST(SurfaceGenerators, SphereZoneLiesOnItsSphere) {
  const Eigen::Vector3d centre(1, -2, 0.5);
  const NurbsSurface zone = sphereZone(centre, 0.75, 30.0);
  ASSERT_TRUE(validate(zone).ok()) << validate(zone).message();
  for (int a = 0; a <= 10; ++a) {
    for (int b = 0; b <= 10; ++b) {
      const Eigen::Vector3d p = evaluate(zone, a / 10.0, b / 10.0);
      EXPECT_NEAR((p - centre).norm(), 0.75, 1e-15);
      const double latitude = std::asin((p.z() - centre.z()) / 0.75) * 180.0 / M_PI;
      EXPECT_LE(std::abs(latitude), 45.0 + 1e-9);
    }
  }
  // Longitudes 30..120 degrees: the corner (u, v) = (0.5, 0) is on the equator at 30 degrees.
  const Eigen::Vector3d start = evaluate(zone, 0.5, 0.0) - centre;
  EXPECT_NEAR(std::atan2(start.y(), start.x()) * 180.0 / M_PI, 30.0, 1e-12);
}

TEST(SurfaceGenerators, SaddleIsTheQuadric) {
  const NurbsSurface s = saddle(Eigen::Vector3d(0, 0, 1), 2.0, 0.25);
  ASSERT_TRUE(validate(s).ok());
  for (int a = 0; a <= 8; ++a) {
    for (int b = 0; b <= 8; ++b) {
      const Eigen::Vector3d p = evaluate(s, a / 8.0, b / 8.0);
      EXPECT_NEAR(p.z(), 1.0 + 0.25 * (p.x() * p.x() - p.y() * p.y()), 1e-14);
    }
  }
}

TEST(SurfaceGenerators, SheetsAndBladesAreValid) {
  const NurbsSurface sheet = wavySheet(Eigen::Vector3d::Zero(), 4.0, 12, 2.0, 0.2, 0.0);
  ASSERT_TRUE(validate(sheet).ok()) << validate(sheet).message();
  EXPECT_EQ(sheet.count_u, 12);
  const NurbsSurface blade = sweptBlade(Eigen::Vector3d::Zero(), 1.0, 0.1, 3.0, 40.0);
  ASSERT_TRUE(validate(blade).ok()) << validate(blade).message();
  // The tip section is turned by the twist: its chord direction at 40 degrees.
  const Eigen::Vector3d chord = evaluate(blade, 1.0, 1.0) - evaluate(blade, 1.0, 0.0);
  EXPECT_NEAR(std::atan2(chord.y(), chord.x()) * 180.0 / M_PI, 40.0, 1e-9);
  EXPECT_NEAR(evaluate(blade, 1.0, 0.5).z(), 3.0, 1e-12);
}

}  // namespace
}  // namespace collido::nurbs

namespace collido::nurbs {
namespace {

TEST(Tessellate, VerticesLieOnTheSurfaceAndTheGridIsComplete) {
  const NurbsSurface zone = sphereZone(Eigen::Vector3d(1, 2, 3), 2.0, 0.0);
  const TriangleMesh mesh = tessellate(zone, 6, 4);
  EXPECT_EQ(mesh.vertexCount(), 7u * 5u);
  EXPECT_EQ(mesh.triangleCount(), 2u * 6u * 4u);
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v)
    EXPECT_NEAR((mesh.vertices.col(v) - Eigen::Vector3d(1, 2, 3)).norm(), 2.0, 1e-14);
  // Every triangle is non-degenerate and faces the same side (outward for the zone).
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    const Eigen::Vector3d a = mesh.vertices.col(mesh.triangles(0, t));
    const Eigen::Vector3d b = mesh.vertices.col(mesh.triangles(1, t));
    const Eigen::Vector3d c = mesh.vertices.col(mesh.triangles(2, t));
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    EXPECT_GT(normal.norm(), 1e-6);
    EXPECT_GT(std::abs(normal.normalized().dot((a - Eigen::Vector3d(1, 2, 3)).normalized())), 0.9);
  }
}

}  // namespace
}  // namespace collido::nurbs
