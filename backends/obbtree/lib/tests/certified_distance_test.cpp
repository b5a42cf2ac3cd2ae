// The leaf stage's certified bounds on a triangle pair's distance, against the exact distance
// (rational arithmetic): the gap along a given direction never exceeds it, is the distance
// along a face normal where a corner faces the other's face, and is 0 where the projections
// overlap; the certified interval holds the exact distance.
#include <array>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/oracle/distance_oracle.h>

#include "../src/certified_distance.h"
#include "collide_check.h"

namespace collido::obbtree {
namespace {

using Eigen::Vector3d;
using Triangle = std::array<Vector3d, 3>;

// The exact distance's enclosing interval, as the oracle computes it.
ExactInterval exactSquaredDistance(const Triangle& a, const Triangle& b) {
  return exactPosedClosestPoints(a, Pose::Identity(), b, Pose::Identity()).squared_distance;
}

Vector3d normalOf(const Triangle& t) {
  return (t[1] - t[0]).cross(t[2] - t[0]);
}

Triangle randomTriangle(std::mt19937_64& rng, const Vector3d& centre, double size) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Triangle t;
  for (Vector3d& corner : t)
    corner = centre + size * Vector3d(unit(rng), unit(rng), unit(rng));
  return t;
}

TEST(CertifiedDistance, GapAlongAnyDirectionNeverExceedsTheDistance) {
  std::mt19937_64 rng(62);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int positive = 0;
  for (int i = 0; i < 2000; ++i) {
    const double size = std::pow(10.0, 2.0 * unit(rng));
    const Triangle a = randomTriangle(rng, Vector3d::Zero(), size);
    const Triangle b =
        randomTriangle(rng, size * 3.0 * Vector3d(unit(rng), unit(rng), unit(rng)), size);
    const ExactInterval exact = exactSquaredDistance(a, b);
    const double upper = std::sqrt(exact.upper) * (1.0 + 1e-15);
    for (const Vector3d& n : {normalOf(a), normalOf(b), Vector3d(unit(rng), unit(rng), unit(rng)),
                              Vector3d(b[0] - a[0])}) {
      const double gap = detail::separationAlong(n, a, b, 0.0, a[0]);
      EXPECT_GE(gap, 0.0);
      EXPECT_LE(gap, upper) << "pair " << i;
      positive += gap > 0.0;
    }
    // With an error radius on b, the bound drops by that radius (to rounding), or to 0.
    const double error = 0.1 * size;
    const double exact_b = detail::separationAlong(normalOf(a), a, b, 0.0, a[0]);
    EXPECT_LE(detail::separationAlong(normalOf(a), a, b, error, a[0]),
              std::max(0.0, exact_b - error) + 1e-15 * (exact_b + error));
  }
  EXPECT_GT(positive, 2000);  // the check is not vacuous: most directions separate something
}

// A triangle above another's face, tilted, its lowest corner over the face: the gap along the
// lower triangle's normal is their distance, to rounding, far from the origin too.
TEST(CertifiedDistance, GapAlongTheFaceNormalIsTheDistanceWhereACornerFacesTheFace) {
  for (const Vector3d& offset : {Vector3d(0.0, 0.0, 0.0), Vector3d(1e4, -3e3, 250.0)}) {
    const Triangle floor = {offset + Vector3d(0, 0, 0), offset + Vector3d(2, 0, 0),
                            offset + Vector3d(0, 2, 0)};
    const Triangle above = {offset + Vector3d(0.5, 0.5, 0.3), offset + Vector3d(1.5, 0.2, 0.9),
                            offset + Vector3d(0.3, 1.4, 0.7)};
    const double exact = std::sqrt(exactSquaredDistance(floor, above).lower);
    const double gap = detail::separationAlong(normalOf(floor), floor, above, 0.0, floor[0]);
    EXPECT_LE(gap, exact);
    EXPECT_NEAR(gap, exact, 1e-11 * exact) << offset.transpose();
    EXPECT_NEAR(exact, 0.3, 1e-12);
  }
}

TEST(CertifiedDistance, GapIsZeroWhereTheProjectionsOverlap) {
  const Triangle a = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)};
  const Triangle b = {Vector3d(0.2, 0.2, -0.5), Vector3d(0.3, 0.2, 0.5), Vector3d(0.2, 0.3, 0.5)};
  EXPECT_EQ(detail::separationAlong(normalOf(a), a, b, 0.0, a[0]), 0.0);
  EXPECT_EQ(detail::separationAlong(Vector3d::Zero(), a, b, 0.0, a[0]), 0.0);
}

TEST(CertifiedDistance, IntervalHoldsTheExactDistance) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const Triangle a = randomTriangle(rng, Vector3d::Zero(), 1.0);
    const Triangle b = randomTriangle(rng, 2.5 * Vector3d(unit(rng), unit(rng), unit(rng)), 1.0);
    const ExactInterval exact = exactSquaredDistance(a, b);
    const detail::CertifiedDistance computed = detail::certifiedTriangleDistance(a, b, 0.0);
    EXPECT_LE(computed.lower * computed.lower, exact.upper) << "pair " << i;
    EXPECT_GE(computed.upper * computed.upper, exact.lower) << "pair " << i;
    EXPECT_LE(computed.lower, computed.value);
    EXPECT_LE(computed.value, computed.upper);
  }
}

}  // namespace
}  // namespace collido::obbtree
