// Polygonization through OpenVDB: the mesh lies on the surface within a cell, closes, and bad
// regions are refused.
#include <cmath>

#include <gtest/gtest.h>

#include <collido/frep_mesh/polygonize.h>

namespace collido::frep {
namespace {

TEST(Polygonize, SphereMeshLiesOnTheSurfaceWithinACell) {
  const SolidPtr ball = sphere({0.3, -0.2, 0.1}, 0.7);
  for (int resolution : {8, 32}) {
    const Result<TriangleMesh> mesh = polygonize(*ball, ball->bounds(), resolution);
    ASSERT_TRUE(mesh.ok()) << mesh.status().message();
    const double cell = 1.4 / resolution;
    EXPECT_GT(mesh.value().triangleCount(), 20U);
    for (Eigen::Index v = 0; v < mesh.value().vertices.cols(); ++v) {
      const double radius = (mesh.value().vertices.col(v) - Eigen::Vector3d(0.3, -0.2, 0.1)).norm();
      EXPECT_NEAR(radius, 0.7, cell) << resolution;
    }
    // Closed: every edge is shared by two triangles, so the signed volume is the ball's (to the
    // grid's error), positive with the outward winding.
    double volume = 0;
    for (std::size_t t = 0; t < mesh.value().triangleCount(); ++t) {
      const auto a = mesh.value().corner(t, 0);
      const auto b = mesh.value().corner(t, 1);
      const auto c = mesh.value().corner(t, 2);
      volume += a.dot(b.cross(c)) / 6;
    }
    EXPECT_NEAR(volume, 4.0 / 3.0 * M_PI * 0.343, 0.1 * 1.437) << resolution;
  }
}

TEST(Polygonize, RefusesUnboundedEmptyAndCoarseRegions) {
  const SolidPtr ball = sphere({0, 0, 0}, 1);
  EXPECT_FALSE(polygonize(*ball, Eigen::AlignedBox3d(), 16).ok());
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(
      polygonize(
          *ball,
          Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-inf), Eigen::Vector3d::Constant(inf)), 16)
          .ok());
  EXPECT_FALSE(polygonize(*ball, ball->bounds(), 1).ok());
  // A solid smaller than a cell, away from the grid points: nothing to mesh, said so.
  const SolidPtr speck = sphere({0.013, 0.017, 0.011}, 1e-4);
  const Result<TriangleMesh> none = polygonize(
      *speck, Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-1), Eigen::Vector3d::Constant(1)), 4);
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.status().message().find("resolution 4"), std::string::npos);
}

}  // namespace
}  // namespace collido::frep
