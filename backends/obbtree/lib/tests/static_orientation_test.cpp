// The signs the exact stages settle without the exact predicate: the static filter on exact
// points (static_orientation.h), the prepared triangle's certain sides and zeros and its
// certainly proper corners (prepared_triangle.h: planeSeparates with settleSides, and
// exactPlaneSeparates), and the triangle test told some sides in advance
// (TriangleTest::intersectKnowingSides). Each settled sign must be the exact one, on lattices
// (exact zeros everywhere), near-degenerate doubles and scales where products underflow or
// overflow.
#include <array>
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include <collido/oracle/orientation.h>
#include <collido/oracle/triangle_test.h>

#include "../src/prepared_triangle.h"
#include "../src/static_orientation.h"

namespace collido::obbtree {
namespace {

using Eigen::Vector3d;

// Points of a small lattice, scaled by a power of two and moved: exact zeros are common.
struct LatticeSampler {
  std::mt19937_64 rng;
  double scale = 1.0;
  Vector3d origin = Vector3d::Zero();
  int range = 2;

  Vector3d next() {
    std::uniform_int_distribution<int> c(-range, range);
    return origin + scale * Vector3d(c(rng), c(rng), c(rng));
  }
};

// Scales from subnormal products to near-overflowing ones, with an offset at some.
LatticeSampler samplerForTrial(int trial, std::uint64_t seed) {
  static const double kScales[] = {1.0,    std::ldexp(1.0, -20), 1e-110, 1e-160,
                                   1e-300, std::ldexp(1.0, 30),  1e120,  1e200};
  LatticeSampler sampler{std::mt19937_64(seed + static_cast<std::uint64_t>(trial))};
  sampler.scale = kScales[trial % 8];
  if (trial % 3 == 0) sampler.origin = sampler.scale * Vector3d(1024.0, -512.0, 3.0);
  sampler.range = 1 + trial % 3;
  return sampler;
}

TEST(StaticOrientation, SettledSignsAreTheExactOnes) {
  int zeros = 0;
  int non_zero = 0;
  int undecided = 0;
  for (int trial = 0; trial < 40000; ++trial) {
    LatticeSampler sampler = samplerForTrial(trial, 101);
    std::array<Vector3d, 4> p{sampler.next(), sampler.next(), sampler.next(), sampler.next()};
    if (trial % 4 == 1) p[3] += Vector3d(1.0, -1.0, 1.0) * std::ldexp(sampler.scale, -40);
    if (trial % 4 == 3) {  // random doubles, the fourth on their plane up to rounding
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      const double scale = std::ldexp(1.0, 25 * (trial / 4 % 3) - 25);
      for (int k = 0; k < 3; ++k)
        p[k] = sampler.origin + scale * Vector3d(u(sampler.rng), u(sampler.rng), u(sampler.rng));
      p[3] = p[0] + u(sampler.rng) * (p[1] - p[0]) + u(sampler.rng) * (p[2] - p[0]);
    }
    const int sign = detail::staticOrient3d(p[0], p[1], p[2], p[3]);
    if (sign == detail::kUndecidedSign) {
      ++undecided;
    } else {
      ASSERT_EQ(sign, exact::orient3d(p[0], p[1], p[2], p[3])) << "trial " << trial;
      (sign == 0 ? zeros : non_zero) += 1;
    }
    for (int drop = 0; drop < 3; ++drop) {
      const int sign2 = detail::staticOrient2d(p[0], p[1], p[3], drop);
      if (sign2 != detail::kUndecidedSign) {
        ASSERT_EQ(sign2, exact::orient2d(p[0], p[1], p[3], drop))
            << "trial " << trial << " drop " << drop;
      }
    }
  }
  // Each outcome occurs: zeros by an all-zero expansion, undecided at tiny scales and overflow.
  EXPECT_GT(zeros, 1000);
  EXPECT_GT(non_zero, 10000);
  EXPECT_GT(undecided, 1000);
}

detail::PreparedTriangle preparedExact(const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  detail::PreparedTriangle t;
  const Vector3d corners[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    t.corners[k].p = corners[k];
    t.corners[k].error.setZero();
  }
  detail::prepareTriangle(t);
  return t;
}

TEST(PreparedTriangleSides, SettledSidesAndProperCornersAreExact) {
  int zeros = 0;
  int proper = 0;
  int collinear = 0;
  for (int trial = 0; trial < 40000; ++trial) {
    LatticeSampler sampler = samplerForTrial(trial, 202);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    // Every fourth trial: random doubles, and the other triangle on this one's plane up to
    // rounding, so that the bounds decide.
    const bool near_plane = trial % 4 == 3;
    const double scale = std::ldexp(1.0, 25 * (trial / 4 % 3) - 25);
    const auto corner = [&]() {
      return near_plane ? Vector3d(scale * Vector3d(u(sampler.rng), u(sampler.rng), u(sampler.rng)))
                        : sampler.next();
    };
    const Vector3d a = corner();
    const Vector3d b = corner();
    const Vector3d c = corner();
    const detail::PreparedTriangle t = preparedExact(a, b, c);
    if (detail::certainlyProper(t)) {
      ASSERT_FALSE(exact::collinear(a, b, c)) << "trial " << trial;
      ++proper;
    }
    collinear += exact::collinear(a, b, c) ? 1 : 0;
    Vector3d other_corners[3] = {sampler.next(), sampler.next(), sampler.next()};
    if (near_plane) {
      for (Vector3d& p : other_corners)
        p = a + u(sampler.rng) * (b - a) + u(sampler.rng) * (c - a);
    }
    const detail::PreparedTriangle other =
        preparedExact(other_corners[0], other_corners[1], other_corners[2]);
    int side[3];
    detail::planeSeparates(t, other, side);
    detail::settleSides(t, other, side);
    int exact_side[3];  // the leaves' variant for exact corners
    detail::exactPlaneSeparates(t, other, exact_side);
    for (int k = 0; k < 3; ++k) {
      const int truth = exact::orient3d(a, b, c, other.corners[k].p);
      if (exact_side[k] != detail::kUndecidedSign) {
        ASSERT_EQ(exact_side[k], truth) << "trial " << trial << " corner " << k;
      }
      if (side[k] == detail::kUndecidedSign) continue;
      ASSERT_EQ(side[k], truth) << "trial " << trial << " corner " << k;
      ASSERT_EQ(exact_side[k], side[k]) << "trial " << trial << " corner " << k;
      zeros += side[k] == 0 ? 1 : 0;
    }
  }
  EXPECT_GT(zeros, 1000);
  EXPECT_GT(proper, 20000);
  EXPECT_GT(collinear, 500);
}

// A corner known only to within a radius is on the plane for certain only when the radius lies
// along the plane: a face in z = 1 and a point on it, uncertain in x, then in z.
TEST(PreparedTriangleSides, AZeroIsClaimedOnlyWhereNoErrorCanMoveThePoint) {
  const detail::PreparedTriangle face =
      preparedExact(Vector3d(0, 0, 1), Vector3d(2, 0, 1), Vector3d(0, 2, 1));
  detail::PreparedTriangle on_face =
      preparedExact(Vector3d(0.5, 0.5, 1.0), Vector3d(0.5, 0.5, 1.0), Vector3d(0.5, 0.5, 1.0));
  const auto settled = [&face, &on_face]() {
    int side[3] = {0, 0, 0};
    detail::settleSides(face, on_face, side);
    return side[0];
  };
  on_face.corners[0].error = Vector3d(1e-9, 0.0, 0.0);
  EXPECT_EQ(settled(), 0);
  on_face.corners[0].error = Vector3d(0.0, 0.0, 1e-9);
  EXPECT_EQ(settled(), detail::kUndecidedSign);
}

struct ExactTestKernel {
  using Point = Vector3d;
  static int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    return exact::orient3d(a, b, c, d);
  }
  static int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    return exact::orient2d(a, b, c, drop);
  }
  static bool collinear(const Point& a, const Point& b, const Point& c) {
    return exact::collinear(a, b, c);
  }
  static int compare(const Point& a, const Point& b, int k) {
    return (a[k] > b[k]) - (a[k] < b[k]);
  }
};

// Told any subset of the sides (zeros included) and which triangles are proper, the test gives
// intersect()'s answer.
TEST(TriangleTestKnowingSides, AnswersAsTheFullTestWhateverItIsTold) {
  using ExactTest = exact::TriangleTest<ExactTestKernel>;
  std::mt19937_64 rng(303);
  std::uniform_int_distribution<int> c(0, 2);
  std::uniform_int_distribution<int> mask(0, 63);
  ExactTestKernel kernel;
  int hits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Vector3d t1[3];
    Vector3d t2[3];
    for (Vector3d& p : t1)
      p = Vector3d(c(rng), c(rng), c(rng));
    for (Vector3d& p : t2)
      p = Vector3d(c(rng), c(rng), c(rng));
    const bool truth = ExactTest(kernel).intersect(t1[0], t1[1], t1[2], t2[0], t2[1], t2[2]);
    const int told = mask(rng);
    int side1[3];
    int side2[3];
    for (int i = 0; i < 3; ++i) {
      side1[i] =
          told >> i & 1 ? exact::orient3d(t2[0], t2[1], t2[2], t1[i]) : ExactTest::kUnknownSide;
      side2[i] = told >> (3 + i) & 1 ? exact::orient3d(t1[0], t1[1], t1[2], t2[i])
                                     : ExactTest::kUnknownSide;
    }
    const bool proper1 = trial % 2 == 0 && !exact::collinear(t1[0], t1[1], t1[2]);
    const bool proper2 = trial % 3 == 0 && !exact::collinear(t2[0], t2[1], t2[2]);
    ASSERT_EQ(ExactTest(kernel).intersectKnowingSides(t1, side1, proper1, t2, side2, proper2),
              truth)
        << "trial " << trial << " told " << told;
    hits += truth ? 1 : 0;
  }
  EXPECT_GT(hits, 4000);
  EXPECT_GT(20000 - hits, 2000);
}

}  // namespace
}  // namespace collido::obbtree
