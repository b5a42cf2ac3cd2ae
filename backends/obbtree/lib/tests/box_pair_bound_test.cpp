// The distance search's lower bound on the distance of two boxes, against the distance of two
// boxes the separating-axis test calls apart, found by brute force over their features (every
// corner against the other solid box, every pair of edges); its exactness on thin facing boxes
// offset sideways, where the axes of the separating-axis test alone fall short; and its
// tightness for boxes far apart for their size.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/obbtree/separating_axis.h>
#include <collido/oracle/triangle_distance.h>

#include "../src/box_pair_bound.h"
#include "collide_check.h"

namespace collido::obbtree {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Box A axis-aligned at the origin, box B in A's frame (as the search gives them).
struct Boxes {
  Matrix3d r = Matrix3d::Identity();
  Vector3d t = Vector3d::Zero();
  Vector3d a = Vector3d::Ones();
  Vector3d b = Vector3d::Ones();
};

// The slack the search passes for exactly orthonormal inputs (no mapping error).
double slackOf(const Boxes& p) {
  return 5.0 * 16.0 * kEps * (p.t.cwiseAbs().sum() + p.a.sum() + p.b.sum());
}

double lowerBound(const Boxes& p) {
  return detail::boxPairLowerBound({p.r, p.t, p.a, p.b}, slackOf(p));
}

std::array<Vector3d, 8> corners(const Matrix3d& axes, const Vector3d& centre,
                                const Vector3d& half) {
  std::array<Vector3d, 8> out;
  for (int i = 0; i < 8; ++i) {
    const Vector3d sign((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    out[static_cast<std::size_t>(i)] = centre + axes * sign.cwiseProduct(half);
  }
  return out;
}

double pointToBox(const Vector3d& point, const Matrix3d& axes, const Vector3d& centre,
                  const Vector3d& half) {
  const Vector3d local = axes.transpose() * (point - centre);
  return (local - local.cwiseMax(-half).cwiseMin(half)).norm();
}

// The distance of two boxes that do not meet: two convex polytopes apart are closest at a
// corner of one and a face of the other, or at two edges (the other feature pairs include
// one of these).
double separatedDistance(const Boxes& p) {
  const std::array<Vector3d, 8> of_a = corners(Matrix3d::Identity(), Vector3d::Zero(), p.a);
  const std::array<Vector3d, 8> of_b = corners(p.r, p.t, p.b);
  double best = std::numeric_limits<double>::infinity();
  for (const Vector3d& c : of_a)
    best = std::min(best, pointToBox(c, p.r, p.t, p.b));
  for (const Vector3d& c : of_b)
    best = std::min(best, pointToBox(c, Matrix3d::Identity(), Vector3d::Zero(), p.a));
  for (std::size_t i = 0; i < 8; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t i_end = i | (std::size_t{1} << k);
      if (i_end == i) continue;  // each edge once, from its corner with bit k clear
      for (std::size_t j = 0; j < 8; ++j) {
        for (std::size_t m = 0; m < 3; ++m) {
          const std::size_t j_end = j | (std::size_t{1} << m);
          if (j_end == j) continue;
          Vector3d on_a;
          Vector3d on_b;
          best = std::min(best, std::sqrt(closestPointsOfSegments(of_a[i], of_a[i_end], of_b[j],
                                                                  of_b[j_end], on_a, on_b)));
        }
      }
    }
  }
  return best;
}

// Random separated pairs: thin, long and cubic boxes at every orientation and distance.
std::vector<Boxes> separatedPairs(int count) {
  std::mt19937_64 rng(62);
  std::uniform_real_distribution<double> extent(0.005, 2.0);
  std::uniform_real_distribution<double> reach(0.0, 6.0);
  std::vector<Boxes> pairs;
  while (static_cast<int>(pairs.size()) < count) {
    Boxes p;
    p.a = Vector3d(extent(rng), extent(rng), extent(rng));
    p.b = Vector3d(extent(rng), extent(rng), extent(rng));
    p.r = randomRotation(rng);
    p.t = randomRotation(rng).col(0) * reach(rng);
    if (!boxesOverlap(p.r, p.t, p.a, p.b)) pairs.push_back(p);
  }
  return pairs;
}

TEST(BoxPairBound, NeverExceedsTheDistanceOfSeparatedBoxes) {
  for (const Boxes& p : separatedPairs(3000)) {
    const double exact = separatedDistance(p);
    const double bound = lowerBound(p);
    EXPECT_GE(bound, 0.0);
    // The brute force rounds too: a few ulps of the boxes' reach.
    EXPECT_LE(bound, exact + 1e-14 * (p.t.norm() + p.a.sum() + p.b.sum()))
        << "t " << p.t.transpose() << " a " << p.a.transpose() << " b " << p.b.transpose();
  }
}

TEST(BoxPairBound, IsZeroForBoxesThatMeet) {
  Boxes same;
  EXPECT_EQ(lowerBound(same), 0.0);
  std::mt19937_64 rng(7);
  for (int i = 0; i < 500; ++i) {
    Boxes p;
    p.r = randomRotation(rng);
    p.t = randomRotation(rng).col(1) * 1.5;  // centres 1.5 apart, boxes of half size 1: meet
    EXPECT_EQ(lowerBound(p), 0.0);
  }
}

// Thin plates facing each other, B tilted a little and offset sideways beyond A's edge, as
// patches of two facing curved surfaces are: their closest points are an edge of B and an
// edge of A, along no axis of the separating-axis test.
TEST(BoxPairBound, IsTheDistanceOfFacingPlatesOffsetSideways) {
  for (const double tilt : {0.0, 0.02, 0.1}) {
    Boxes p;
    p.a = Vector3d(1.0, 1.0, 0.01);
    p.b = p.a;
    p.r = Eigen::AngleAxisd(tilt, Vector3d(1.0, -1.0, 0.0).normalized()).toRotationMatrix();
    p.t = Vector3d(2.3, 2.2, 0.3);
    ASSERT_FALSE(boxesOverlap(p.r, p.t, p.a, p.b));
    const double exact = separatedDistance(p);
    EXPECT_NEAR(lowerBound(p), exact, 1e-9 * exact) << "tilt " << tilt;
    // The separating-axis test's own axes fall well short here.
    double faces = 0.0;
    const Matrix3d abs_r = p.r.cwiseAbs();
    for (int i = 0; i < 3; ++i) {
      faces = std::max(faces, std::abs(p.t[i]) - p.a[i] - abs_r.row(i).dot(p.b));
      faces = std::max(faces, std::abs(p.t.dot(p.r.col(i))) - abs_r.col(i).dot(p.a) - p.b[i]);
    }
    EXPECT_LT(faces, 0.8 * exact) << "tilt " << tilt;
  }
}

// Far apart for their size (the pairs a search sets aside high in the trees), the one direction
// the bound takes is close to that of the closest points, and so is the bound to the distance.
TEST(BoxPairBound, IsNearTheDistanceOfBoxesFarApart) {
  for (Boxes p : separatedPairs(500)) {
    const double size = p.a.norm() + p.b.norm();
    p.t = p.t.normalized() * (10.0 * size + p.t.norm());
    const double exact = separatedDistance(p);
    EXPECT_LE(lowerBound(p), exact * (1.0 + 1e-12));
    EXPECT_GE(lowerBound(p), 0.98 * exact)
        << "t " << p.t.transpose() << " a " << p.a.transpose() << " b " << p.b.transpose();
  }
}

}  // namespace
}  // namespace collido::obbtree
