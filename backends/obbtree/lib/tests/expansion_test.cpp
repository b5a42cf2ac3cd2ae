// The exact fallback's stages, double-doubles with certified radii and floating-point
// expansions: their sums and products come out exact or within their radii (against CGAL's
// rationals), and posed triangle pairs are decided as the rational kernel and the oracle
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
#include "../src/tracked_double_double.h"
#include "../src/tracked_world.h"
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

// The three deciders on one pair: the expansions answer (inputs in range), the double-doubles
// answer or step aside, and both agree with the rationals and the oracle. Returns the answer;
// counts the pairs the double-doubles settle in `tracked_answers`.
bool decideAll(const Tri& a, const Eigen::Isometry3d& pose_a, const Tri& b,
               const Eigen::Isometry3d& pose_b, int trial, int& tracked_answers) {
  const std::optional<bool> tracked =
      detail::posedTrianglesIntersectByTrackedDoubles(a.data(), pose_a, b.data(), pose_b);
  const std::optional<bool> expansions =
      detail::posedTrianglesIntersectByExpansions(a.data(), pose_a, b.data(), pose_b);
  const bool rationals =
      detail::posedTrianglesIntersectByRationals(a.data(), pose_a, b.data(), pose_b);
  EXPECT_TRUE(expansions.has_value()) << trial;
  EXPECT_EQ(expansions.value_or(!rationals), rationals) << trial;
  EXPECT_EQ(tracked.value_or(rationals), rationals) << trial;
  EXPECT_EQ(rationals, oracleTrianglesIntersect(a, pose_a, b, pose_b)) << trial;
  tracked_answers += tracked.has_value() ? 1 : 0;
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
// faces, edges and corners into exact contact, and boxes turned by a solver's nearly upright
// rotation (1e-18 where exact arithmetic has 0): every pair of their triangles. The
// double-doubles settle most pairs, exact zeros of exactly placed faces included.
TEST(ExpansionWorldTriangleTest, AlignedBoxesAgreeWithTheRationalsOnEveryPair) {
  const std::vector<Tri> box = boxTriangles(0.5);
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d quarter;
  quarter << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  Eigen::Matrix3d upright = Eigen::AngleAxisd(0.35, Vector3d::UnitY()).toRotationMatrix();
  upright(0, 1) = 2.6e-18;
  upright(1, 0) = -2.3e-18;
  upright(2, 1) = 4.4e-19;
  const Vector3d moves[] = {{0.2, 0.2, 0.2}, {1.0, 0.3, 0.1},   {1.0, 1.0, 0.0},
                            {1.0, 1.0, 1.0}, {0.1, 1.0, 1e-17}, {1e8 + 0.2, 0.2, 0.2}};
  int trial = 0;
  int hits = 0;
  int tracked_answers = 0;
  for (const Vector3d& move : moves) {
    for (const Eigen::Matrix3d& rotation : {identity, quarter, upright}) {
      const Eigen::Isometry3d pose_a =
          makePose(identity, move.x() > 1e7 ? Vector3d(1e8, 0, 0) : Vector3d::Zero());
      const Eigen::Isometry3d pose_b = makePose(rotation, move);
      for (const Tri& a : box) {
        for (const Tri& b : box)
          hits += decideAll(a, pose_a, b, pose_b, trial++, tracked_answers) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(hits, 0);
  EXPECT_GT(tracked_answers, trial * 3 / 4);
}

// The double-double arithmetic: on sums and products of products of doubles of widely
// different scales (as world coordinates and their determinants are), the exact value lies
// within the radius, and a zero radius means hi + lo is exact.
TEST(TrackedDoubleDouble, TheExactValueLiesWithinTheRadius) {
  using detail::TrackedDoubleDouble;
  using Q = CGAL::Exact_rational;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-70, 10);
  std::uniform_int_distribution<int> pick(0, 3);
  const auto value = [](const TrackedDoubleDouble& x) -> Q { return Q(x.hi) + Q(x.lo); };
  int exact_results = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // Leaves: products of two doubles, one of them sometimes an exact small integer (exact
    // doubles give exact sums), in pairs so that differences cancel.
    TrackedDoubleDouble x[4];
    Q truth[4];
    for (int k = 0; k < 4; ++k) {
      const double a = trial % 5 == 0 ? std::round(8.0 * u(rng)) : std::ldexp(u(rng), scale(rng));
      const double b = std::ldexp(u(rng), scale(rng) / 4);
      x[k] = TrackedDoubleDouble::product(a, b);
      truth[k] = Q(a) * Q(b);
    }
    // ((x0 op x1) op (x2 op x3)) op x0, the ops drawn at random.
    const auto apply = [&](int op, const TrackedDoubleDouble& p, const Q& tp,
                           const TrackedDoubleDouble& q, const Q& tq, TrackedDoubleDouble& out,
                           Q& tout) {
      out = op == 0 ? p + q : (op == 1 ? p - q : p * q);
      tout = op == 0 ? Q(tp + tq) : (op == 1 ? Q(tp - tq) : Q(tp * tq));
    };
    TrackedDoubleDouble left, right, both, last;
    Q t_left, t_right, t_both, t_last;
    apply(pick(rng) % 3, x[0], truth[0], x[1], truth[1], left, t_left);
    apply(pick(rng) % 3, x[2], truth[2], x[3], truth[3], right, t_right);
    apply(pick(rng) % 3, left, t_left, right, t_right, both, t_both);
    apply(pick(rng) % 3, both, t_both, x[0], truth[0], last, t_last);
    for (const auto& [computed, exact] : {std::pair{left, t_left}, std::pair{right, t_right},
                                          std::pair{both, t_both}, std::pair{last, t_last}}) {
      const Q error = CGAL::abs(value(computed) - exact);
      ASSERT_LE(error, Q(computed.radius)) << trial;
      if (computed.radius == 0.0) {
        ASSERT_EQ(error, Q(0)) << trial;
        ++exact_results;
      }
      const int sign = computed.certainSign();
      if (sign != TrackedDoubleDouble::kUnsure) {
        ASSERT_EQ(sign, CGAL::sign(exact)) << trial;
      }
    }
  }
  EXPECT_GT(exact_results, 100);
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
