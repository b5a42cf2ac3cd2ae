// The seed method's certified distance on surfaces whose distance is known in closed form, both
// bounds (hulls and boxes) agreeing, and the hulls searching fewer pairs.
#include <cmath>

#include <gtest/gtest.h>

#include <collido/nurbs/surface_distance.h>
#include <collido/nurbs/surface_generators.h>

namespace collido::nurbs {
namespace {

// A bicubic plane patch z = height over [x0, x0 + size] x [y0, y0 + size], its control points
// unevenly spaced in the plane (so the parametrisation is not trivial).
NurbsSurface planePatch(double x0, double y0, double size, double height) {
  std::vector<Eigen::Vector3d> points;
  const double t[4] = {0.0, 0.2, 0.7, 1.0};
  for (double s : t) {
    for (double r : t)
      points.emplace_back(x0 + size * s, y0 + size * r, height);
  }
  return NurbsSurface::fromPoints(3, 3, 4, 4, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1},
                                  points, std::vector<double>(16, 1.0));
}

void expectCertified(const SurfaceDistance& d, double exact, double tolerance) {
  EXPECT_TRUE(d.converged);
  EXPECT_LE(d.lower, exact + 1e-12);
  EXPECT_GE(d.upper, exact - 1e-12);
  EXPECT_LE(d.upper - d.lower, tolerance + 1e-15);
  EXPECT_NEAR((d.point_a - d.point_b).norm(), d.upper, 1e-9);
}

TEST(SurfaceDistance, TwoSphereZonesFacingEachOther) {
  // Zones centred on +x and -x: closest points on the x axis, 3 - 1 - 0.5 = 1.5 apart.
  const NurbsSurface a = sphereZone(Eigen::Vector3d::Zero(), 1.0, -45.0);
  const NurbsSurface b = sphereZone(Eigen::Vector3d(3, 0, 0), 0.5, 135.0);
  for (const PatchBound bound : {PatchBound::kConvexHull, PatchBound::kBox}) {
    SurfaceDistanceOptions options;
    options.bound = bound;
    options.tolerance = 1e-6;
    const SurfaceDistance d = minimumDistance(a, b, options);
    expectCertified(d, 1.5, options.tolerance);
    EXPECT_NEAR(d.point_a.x(), 1.0, 1e-5);
    EXPECT_NEAR(d.point_b.x(), 2.5, 1e-5);
  }
}

TEST(SurfaceDistance, SphereZoneAboveAPlaneIsClosestAtItsCorners) {
  // The zone about (0, 0, 2), radius 1, longitudes -45..45: its lowest points are its lower ring
  // at z = 2 - sqrt(1/2); the plane patch (z = 0) ends at x = 0.5, where the ring's two corner
  // points (longitudes +-45 degrees, x = 0.5) lie right above its edge. Every other ring point
  // is beyond the edge (x > 0.5), so the distance, 2 - sqrt(1/2), is attained at the corners.
  const NurbsSurface zone = sphereZone(Eigen::Vector3d(0, 0, 2), 1.0, -45.0);
  const NurbsSurface plane = planePatch(-1.5, -1.0, 2.0, 0.0);
  const double exact = 2.0 - std::sqrt(0.5);
  SurfaceDistanceOptions options;
  options.tolerance = 1e-7;
  const SurfaceDistance d = minimumDistance(zone, plane, options);
  expectCertified(d, exact, options.tolerance);
  EXPECT_NEAR(std::abs(d.point_a.y()), 0.5, 1e-6);
}

TEST(SurfaceDistance, IntersectingSurfacesAreCertifiedAtZero) {
  const NurbsSurface zone = sphereZone(Eigen::Vector3d(0, 0, 0.2), 1.0, -45.0);
  const NurbsSurface plane = planePatch(-0.5, -1.0, 3.0, 0.0);
  SurfaceDistanceOptions options;
  options.tolerance = 1e-6;
  const SurfaceDistance d = minimumDistance(zone, plane, options);
  EXPECT_TRUE(d.converged);
  EXPECT_EQ(d.lower, 0.0);
  EXPECT_LE(d.upper, 1e-6);
}

TEST(SurfaceDistance, HullsSearchFarFewerPairsThanBoxes) {
  // Two zones at an angle to the axes: a small patch's box stays loose by its size, its hull by
  // its size squared, so boxes need many more pairs (about 4x per level) for the same interval.
  const NurbsSurface a = sphereZone(Eigen::Vector3d::Zero(), 1.0, 10.0);
  const NurbsSurface b = sphereZone(Eigen::Vector3d(2.2, 1.9, 0.3), 0.7, 200.0);
  for (const bool refine : {false, true}) {
    SurfaceDistanceOptions hull;
    hull.tolerance = 3e-2;
    hull.refine = refine;
    SurfaceDistanceOptions box = hull;
    box.bound = PatchBound::kBox;
    const SurfaceDistance dh = minimumDistance(a, b, hull);
    const SurfaceDistance db = minimumDistance(a, b, box);
    ASSERT_TRUE(dh.converged && db.converged);
    EXPECT_LE(std::max(dh.lower, db.lower), std::min(dh.upper, db.upper))
        << "the two certified intervals must overlap";
    EXPECT_LT(20 * dh.pairs_bounded, db.pairs_bounded) << "refine " << refine;
  }
}

TEST(SurfaceDistance, TheLowerBoundCountsDroppedPairs) {
  // With the descent the upper bound is found at once and every child pair is dropped; the
  // interval must still be the tolerance wide at most, and hold the exact 1.5.
  const NurbsSurface a = sphereZone(Eigen::Vector3d::Zero(), 1.0, -45.0);
  const NurbsSurface b = sphereZone(Eigen::Vector3d(3, 0, 0), 0.5, 135.0);
  SurfaceDistanceOptions options;
  options.tolerance = 1e-2;
  const SurfaceDistance d = minimumDistance(a, b, options);
  EXPECT_LE(d.lower, 1.5);
  EXPECT_LT(d.lower, d.upper) << "a dropped pair's bound is below the upper bound";
  EXPECT_NEAR(d.upper, 1.5, 1e-9);
}

}  // namespace
}  // namespace collido::nurbs
