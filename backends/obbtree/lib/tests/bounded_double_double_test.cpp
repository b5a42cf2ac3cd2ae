// The bounded double-doubles, the first try of the double-double stage on inexact corners: the
// exact value lies within the running error bound (against CGAL's rationals), the magnitude
// bounds it, a certain sign is the exact one, and the world kernel's orientations of corners
// 1e-18 off a common plane come out as the exact ones, settled by the bound.
#include <array>
#include <cmath>
#include <random>

#include <CGAL/Exact_rational.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "../src/bounded_double_double.h"
#include "../src/tracked_double_double.h"
#include "../src/tracked_world.h"

namespace collido::obbtree {
namespace {

using detail::BoundedDoubleDouble;
using detail::TrackedDoubleDouble;
using Rational = CGAL::Exact_rational;

Rational valueOf(const BoundedDoubleDouble& x) {
  return Rational(x.hi) + Rational(x.lo);
}

// A leaf: the exact product a b as a normalised double-double, stated with a radius of
// `radius_ulps` units of its low part (the exact value is then any value within it: the test
// takes hi + lo + offset, |offset| within the radius).
struct Leaf {
  BoundedDoubleDouble bounded;
  Rational exact;
};

Leaf leafOf(double a, double b, double offset_fraction, bool with_radius) {
  const TrackedDoubleDouble product = TrackedDoubleDouble::product(a, b);
  TrackedDoubleDouble tracked = product;
  Rational exact = Rational(product.hi) + Rational(product.lo);
  if (with_radius) {
    tracked.radius = std::ldexp(std::abs(product.hi), -60);
    exact = exact + Rational(offset_fraction) * Rational(tracked.radius);
  }
  return {detail::boundedOf(tracked), exact};
}

// Sums, differences and products of leaves of widely different scales, nested three deep as a
// determinant's terms are: the exact value within the error, the magnitude above it, and every
// certain sign the exact one.
TEST(BoundedDoubleDouble, TheExactValueLiesWithinTheError) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-70, 10);
  std::uniform_int_distribution<int> pick(0, 2);
  int certain = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    Leaf leaves[4];
    for (int k = 0; k < 4; ++k) {
      const double a = std::ldexp(unit(rng), scale(rng));
      const double b = std::ldexp(unit(rng), scale(rng) / 4);
      leaves[k] = leafOf(a, b, unit(rng), trial % 3 != 0);
    }
    // Pairs that nearly cancel: the second leaf of a pair is the first one nudged.
    if (trial % 2 == 0) {
      const double nudge = std::ldexp(unit(rng), -100 + scale(rng) / 2);
      leaves[1] = leafOf(leaves[0].bounded.hi * (1.0 + nudge), 1.0, unit(rng), trial % 4 == 0);
    }
    const auto apply = [&](int op, const Leaf& p, const Leaf& q) -> Leaf {
      if (op == 0) return {p.bounded + q.bounded, p.exact + q.exact};
      if (op == 1) return {p.bounded - q.bounded, p.exact - q.exact};
      return {p.bounded * q.bounded, p.exact * q.exact};
    };
    const Leaf left = apply(pick(rng), leaves[0], leaves[1]);
    const Leaf right = apply(pick(rng), leaves[2], leaves[3]);
    const Leaf both = apply(pick(rng), left, right);
    const Leaf last = apply(pick(rng), both, leaves[2]);
    for (const Leaf& result : {left, right, both, last}) {
      const BoundedDoubleDouble& x = result.bounded;
      ASSERT_LE(CGAL::abs(valueOf(x) - result.exact), Rational(x.error)) << trial;
      ASSERT_LE(CGAL::abs(result.exact), Rational(x.magnitude)) << trial;
      ASSERT_LE(std::abs(x.hi), x.magnitude) << trial;
      ASSERT_LE(std::abs(x.lo), std::ldexp(std::abs(x.hi), -53)) << trial;
      const int sign = x.certainSign();
      if (sign != TrackedDoubleDouble::kUnsure) {
        ASSERT_EQ(sign, CGAL::sign(result.exact)) << trial;
        ++certain;
      }
    }
  }
  EXPECT_GT(certain, 8000);
}

// A bound is never zero: an exact zero stays undecided (the tracked radii certify those).
TEST(BoundedDoubleDouble, AnExactZeroIsNeverCertain) {
  const BoundedDoubleDouble x = detail::boundedOf(TrackedDoubleDouble::product(0.1, 3.0));
  EXPECT_EQ((x - x).certainSign(), TrackedDoubleDouble::kUnsure);
  const BoundedDoubleDouble zero{};
  EXPECT_EQ((zero * x).certainSign(), TrackedDoubleDouble::kUnsure);
}

// The world kernel on corners placed by a solver's "upright" rotation (1e-18 off the axis) and
// on exact corners: every orientation against a plane of the other's corners is the exact one
// (CGAL on the double-doubles' exact values), settled by the bounds where a corner is inexact.
TEST(BoundedDoubleDouble, WorldOrientationsOfNearlyCoplanarCornersAreExact) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  using Point3 = std::array<Rational, 3>;
  // The exact world position R v + t, as the oracle places a vertex.
  const auto exactOf = [](const Eigen::Vector3d& v, const Eigen::Isometry3d& pose) {
    Point3 p;
    for (int row = 0; row < 3; ++row) {
      p[row] = Rational(pose.translation()[row]);
      for (int k = 0; k < 3; ++k)
        p[row] = p[row] + Rational(pose.linear()(row, k)) * Rational(v[k]);
    }
    return p;
  };
  const auto orient = [](const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    Rational u[3];
    Rational v[3];
    Rational w[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = b[k] - a[k];
      v[k] = c[k] - a[k];
      w[k] = d[k] - a[k];
    }
    const Rational det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                         u[2] * (v[0] * w[1] - v[1] * w[0]);
    return CGAL::sign(det);
  };
  int settled = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // A flat part's corners at y = 0.25 exactly, the other's placed by a rotation about y with
    // 1e-18 terms off the axis and a translation that puts its face at y = 0.25 too.
    const double angle = 3.0 * unit(rng);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() << std::cos(angle), std::ldexp(unit(rng), -59), std::sin(angle),
        std::ldexp(unit(rng), -59), 1.0, std::ldexp(unit(rng), -60), -std::sin(angle),
        std::ldexp(unit(rng), -61), std::cos(angle);
    pose.translation() << unit(rng), 1.0, unit(rng);
    const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
    Eigen::Vector3d fixed_model[3];
    Eigen::Vector3d moved_model[3];
    detail::TrackedPoint fixed[3];
    detail::TrackedPoint moved[3];
    Point3 fixed_exact[3];
    Point3 moved_exact[3];
    for (int k = 0; k < 3; ++k) {
      fixed_model[k] = Eigen::Vector3d(4.0 * unit(rng), 0.25, 4.0 * unit(rng));
      moved_model[k] = Eigen::Vector3d(2.0 * unit(rng), -0.75, 2.0 * unit(rng));
      detail::LazyWorldPoint flat(fixed_model[k], identity, true);
      detail::LazyWorldPoint placed(moved_model[k], pose, true);
      fixed[k] = flat.world();
      moved[k] = placed.world();
      fixed_exact[k] = exactOf(fixed_model[k], identity);
      moved_exact[k] = exactOf(moved_model[k], pose);
    }
    for (int k = 0; k < 3; ++k) {
      const int next = (k + 1) % 3;
      detail::TrackedWorldKernel kernel;
      const int sign = kernel.orient3d(fixed[0], fixed[1], fixed[2], moved[k]);
      const int mixed = kernel.orient3d(fixed[0], fixed[1], moved[k], moved[next]);
      ASSERT_FALSE(kernel.unsure()) << trial;
      ASSERT_EQ(sign, orient(fixed_exact[0], fixed_exact[1], fixed_exact[2], moved_exact[k]))
          << trial;
      ASSERT_EQ(mixed, orient(fixed_exact[0], fixed_exact[1], moved_exact[k], moved_exact[next]))
          << trial;
      if (sign != 0) ++settled;
    }
  }
  EXPECT_GT(settled, 1000);
}

}  // namespace
}  // namespace collido::obbtree
