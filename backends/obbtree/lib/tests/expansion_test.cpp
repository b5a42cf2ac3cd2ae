// The exact fallback on floating-point expansions: sums of products come out exact (against
// CGAL's rationals), and posed triangle pairs are decided as the rational kernel and the oracle
// decide them where the certified filter gives up most: parallel and coplanar faces of aligned
// and quarter-turned boxes moved by inexact translations or into exact contact, far from the
// origin too (touching random pairs under random poses: exactness_test.cpp). Inputs outside the
// safe range are left to the rationals.
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <CGAL/Exact_rational.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/obbtree/triangle_intersection.h>

#include "../src/exact_world.h"
#include "../src/expansion.h"
#include "collide_check.h"

namespace collido::obbtree {
namespace {

using Eigen::Vector3d;
using Tri = std::array<Vector3d, 3>;
using Wide = detail::Expansion<64>;

// The exact value of an expansion, as a rational.
CGAL::Exact_rational valueOf(const Wide& e) {
  CGAL::Exact_rational sum = 0;
  for (int i = 0; i < e.size(); ++i)
    sum += CGAL::Exact_rational(e.component(i));
  return sum;
}

TEST(Expansion, SumsAndProductsAreExactAndTheSignIsTheLargestComponents) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-60, 60);
  for (int trial = 0; trial < 2000; ++trial) {
    // (x + y)(x - y) - x x + y y is exactly zero; with w added it is w: the largest and the
    // smallest terms differ by up to 2^240.
    const double x = std::ldexp(u(rng), scale(rng));
    const double y = std::ldexp(u(rng), scale(rng));
    const double w = trial % 3 == 0 ? 0.0 : std::ldexp(u(rng), scale(rng));
    Wide sum(x);
    sum.add(y);
    Wide difference(x);
    difference.add(-y);
    Wide value;
    sum.multiplyInto(difference, value);
    value.add(Wide::product(x, x), /*subtract=*/true);
    value.add(Wide::product(y, y));
    value.add(w);
    ASSERT_FALSE(value.overflowed());
    const CGAL::Exact_rational exact =
        (CGAL::Exact_rational(x) + y) * (CGAL::Exact_rational(x) - y) -
        CGAL::Exact_rational(x) * x + CGAL::Exact_rational(y) * y + w;
    EXPECT_EQ(valueOf(value), exact) << trial;
    EXPECT_EQ(value.sign(), CGAL::sign(exact)) << trial;
    for (int i = 1; i < value.size(); ++i)
      ASSERT_LT(std::abs(value.component(i - 1)), std::abs(value.component(i))) << trial;
  }
}

TEST(Expansion, TheSafeRangeBoundsMagnitudeAndLowestBit) {
  EXPECT_TRUE(detail::inExpansionRange(0.0));
  EXPECT_TRUE(detail::inExpansionRange(-0.2));
  EXPECT_TRUE(detail::inExpansionRange(-std::ldexp(1.0, 149)));
  EXPECT_FALSE(detail::inExpansionRange(std::ldexp(1.0, 150)));
  EXPECT_TRUE(detail::inExpansionRange(std::ldexp(1.0, -170)));
  EXPECT_FALSE(detail::inExpansionRange(std::ldexp(1.0, -171)));
  // 1 + 2^-52 reaches down to 2^-52; scaled by 2^-120 its lowest bit is 2^-172.
  EXPECT_FALSE(detail::inExpansionRange(std::ldexp(1.0 + std::ldexp(1.0, -52), -120)));
  EXPECT_FALSE(detail::inExpansionRange(std::nan("")));
  EXPECT_FALSE(detail::inExpansionRange(INFINITY));
}

// Both deciders on one pair: the expansions answer (inputs in range) and agree with the
// rationals and the oracle. Returns the answer.
bool decideBoth(const Tri& a, const Eigen::Isometry3d& pose_a, const Tri& b,
                const Eigen::Isometry3d& pose_b, int trial) {
  const std::optional<bool> expansions =
      detail::posedTrianglesIntersectByExpansions(a.data(), pose_a, b.data(), pose_b);
  const bool rationals =
      detail::posedTrianglesIntersectByRationals(a.data(), pose_a, b.data(), pose_b);
  EXPECT_TRUE(expansions.has_value()) << trial;
  EXPECT_EQ(expansions.value_or(!rationals), rationals) << trial;
  EXPECT_EQ(rationals, oracleTrianglesIntersect(a, pose_a, b, pose_b)) << trial;
  return rationals;
}

// The 12 triangles of the box [-h, h]^3.
std::vector<Tri> boxTriangles(double h) {
  const auto corner = [h](int i) {
    return Vector3d((i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h);
  };
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  std::vector<Tri> triangles;
  for (const auto& f : faces) {
    triangles.push_back({corner(f[0]), corner(f[1]), corner(f[2])});
    triangles.push_back({corner(f[0]), corner(f[2]), corner(f[3])});
  }
  return triangles;
}

// Aligned unit boxes moved by translations that do not add exactly (0.5 + 0.2), or that bring
// faces, edges and corners into exact contact: every pair of their triangles.
TEST(ExpansionWorldTriangleTest, AlignedBoxesAgreeWithTheRationalsOnEveryPair) {
  const std::vector<Tri> box = boxTriangles(0.5);
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d quarter;
  quarter << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const Vector3d moves[] = {{0.2, 0.2, 0.2}, {1.0, 0.3, 0.1},   {1.0, 1.0, 0.0},
                            {1.0, 1.0, 1.0}, {0.1, 1.0, 1e-17}, {1e8 + 0.2, 0.2, 0.2}};
  int trial = 0;
  int hits = 0;
  for (const Vector3d& move : moves) {
    for (const Eigen::Matrix3d& rotation : {identity, quarter}) {
      const Eigen::Isometry3d pose_a =
          makePose(identity, move.x() > 1e7 ? Vector3d(1e8, 0, 0) : Vector3d::Zero());
      const Eigen::Isometry3d pose_b = makePose(rotation, move);
      for (const Tri& a : box) {
        for (const Tri& b : box)
          hits += decideBoth(a, pose_a, b, pose_b, trial++) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(hits, 0);
}

// Outside the safe range the expansions step aside and the rationals still decide.
TEST(ExpansionWorldTriangleTest, InputsOutsideTheSafeRangeGoToTheRationals) {
  const Tri a = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)};
  const Tri b = {Vector3d(0.25, 0.25, -1), Vector3d(0.25, 0.25, 1), Vector3d(1e-60, 0.3, 0)};
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  EXPECT_FALSE(detail::posedTrianglesIntersectByExpansions(a.data(), identity, b.data(), identity)
                   .has_value());
  EXPECT_TRUE(posedTrianglesIntersect(a.data(), identity, b.data(), identity));
  EXPECT_EQ(posedTrianglesIntersect(a.data(), identity, b.data(), identity),
            oracleTrianglesIntersect(a, identity, b, identity));
}

}  // namespace
}  // namespace collido::obbtree
