// NURBS evaluation against the exact shapes rational patches stand for, derivatives against
// finite differences, and knot insertion and splitting that keep the shape.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include <collido/nurbs/nurbs_surface.h>

namespace collido::nurbs {
namespace {

// A bicubic patch with 6 x 5 random control points, random weights in [0.5, 2] and interior
// knots (one of them double), on the domain [0, 3] x [1, 2].
NurbsSurface randomPatch(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::uniform_real_distribution<double> weight(0.5, 2.0);
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 5; ++j) {
      points.emplace_back(i + 0.3 * coordinate(rng), j + 0.3 * coordinate(rng), coordinate(rng));
      weights.push_back(weight(rng));
    }
  }
  return NurbsSurface::fromPoints(3, 3, 6, 5, {0, 0, 0, 0, 1, 1.7, 3, 3, 3, 3},
                                  {1, 1, 1, 1, 1.4, 2, 2, 2, 2}, points, weights);
}

// A quarter of the unit cylinder x^2 + y^2 = 1, 0 <= z <= 2: a rational quadratic arc (weights
// 1, sqrt(1/2), 1) swept linearly along z.
NurbsSurface quarterCylinder() {
  const double w = std::sqrt(0.5);
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
  for (const Eigen::Vector3d& arc :
       {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 1, 0)}) {
    for (double z : {0.0, 2.0}) {
      points.push_back(arc + Eigen::Vector3d(0, 0, z));
      weights.push_back(arc.x() == 1 && arc.y() == 1 ? w : 1.0);
    }
  }
  return NurbsSurface::fromPoints(2, 1, 3, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, points, weights);
}

TEST(NurbsSurface, TheRationalQuarterCylinderLiesOnTheCylinder) {
  const NurbsSurface cylinder = quarterCylinder();
  ASSERT_TRUE(validate(cylinder).ok()) << validate(cylinder).message();
  for (int a = 0; a <= 20; ++a) {
    for (int b = 0; b <= 4; ++b) {
      const Eigen::Vector3d p = evaluate(cylinder, a / 20.0, b / 4.0);
      EXPECT_NEAR(std::hypot(p.x(), p.y()), 1.0, 1e-15) << a << ", " << b;
      EXPECT_NEAR(p.z(), 2.0 * b / 4.0, 1e-15);
    }
  }
  EXPECT_TRUE(evaluate(cylinder, 0.5, 0.0)
                  .isApprox(Eigen::Vector3d(std::sqrt(0.5), std::sqrt(0.5), 0), 1e-15));
}

TEST(NurbsSurface, DerivativesMatchFiniteDifferences) {
  const NurbsSurface patch = randomPatch(3);
  ASSERT_TRUE(validate(patch).ok()) << validate(patch).message();
  const double h = 1e-6;
  for (const auto& [u, v] :
       {std::pair{0.3, 1.2}, std::pair{1.0, 1.4}, std::pair{2.9, 1.99}, std::pair{1.7, 1.5}}) {
    const SurfacePoint s = evaluateWithDerivatives(patch, u, v);
    const Eigen::Vector3d du = (evaluate(patch, u + h, v) - evaluate(patch, u - h, v)) / (2 * h);
    const Eigen::Vector3d dv = (evaluate(patch, u, v + h) - evaluate(patch, u, v - h)) / (2 * h);
    EXPECT_LT((s.du - du).norm(), 1e-6 * (1 + du.norm())) << u << ", " << v;
    EXPECT_LT((s.dv - dv).norm(), 1e-6 * (1 + dv.norm())) << u << ", " << v;
  }
}

TEST(NurbsSurface, KnotInsertionKeepsTheShape) {
  const NurbsSurface patch = randomPatch(5);
  // At a new knot, at an existing simple knot, and at the double knot (up to the degree).
  for (const auto& [direction, t, times] :
       {std::tuple{Direction::kU, 0.4, 2}, std::tuple{Direction::kU, 1.0, 2},
        std::tuple{Direction::kV, 1.4, 1}, std::tuple{Direction::kV, 1.9, 3}}) {
    const NurbsSurface refined = insertKnot(patch, direction, t, times);
    ASSERT_TRUE(validate(refined).ok()) << validate(refined).message();
    EXPECT_EQ(refined.count_u + refined.count_v, patch.count_u + patch.count_v + times);
    for (double u = 0.0; u <= 3.0; u += 0.25) {
      for (double v = 1.0; v <= 2.0; v += 0.125)
        EXPECT_LT((evaluate(refined, u, v) - evaluate(patch, u, v)).norm(), 1e-14)
            << u << ", " << v;
    }
  }
}

TEST(NurbsSurface, FourSubPatchesCoverTheSurfaceAndInterpolateTheirCorners) {
  const NurbsSurface patch = randomPatch(9);
  const std::array<NurbsSurface, 4> parts = splitInFour(patch);
  const double mu = 1.5;
  const double mv = 1.5;
  const double u_lo[4] = {0, 0, mu, mu};
  const double u_hi[4] = {mu, mu, 3, 3};
  const double v_lo[4] = {1, mv, 1, mv};
  const double v_hi[4] = {mv, 2, mv, 2};
  for (int k = 0; k < 4; ++k) {
    const NurbsSurface& part = parts[static_cast<std::size_t>(k)];
    ASSERT_TRUE(validate(part).ok()) << k << ": " << validate(part).message();
    EXPECT_EQ(part.uMin(), u_lo[k]);
    EXPECT_EQ(part.uMax(), u_hi[k]);
    EXPECT_EQ(part.vMin(), v_lo[k]);
    EXPECT_EQ(part.vMax(), v_hi[k]);
    for (int a = 0; a <= 6; ++a) {
      for (int b = 0; b <= 6; ++b) {
        const double u = u_lo[k] + (u_hi[k] - u_lo[k]) * a / 6.0;
        const double v = v_lo[k] + (v_hi[k] - v_lo[k]) * b / 6.0;
        EXPECT_LT((evaluate(part, u, v) - evaluate(patch, u, v)).norm(), 1e-14) << k;
      }
    }
    // Clamped: the corner control points are the corner points of the patch.
    EXPECT_LT((part.point(0, 0) - evaluate(patch, u_lo[k], v_lo[k])).norm(), 1e-14);
    EXPECT_LT(
        (part.point(part.count_u - 1, part.count_v - 1) - evaluate(patch, u_hi[k], v_hi[k])).norm(),
        1e-14);
  }
}

TEST(NurbsSurface, BadSurfacesAreNamed) {
  const NurbsSurface good = randomPatch(1);
  const auto refused = [](const NurbsSurface& s, const std::string& words) {
    const Status status = validate(s);
    return !status.ok() && status.message().find(words) != std::string::npos;
  };
  NurbsSurface s = good;
  s.at(2, 3).w() = -1.0;
  EXPECT_TRUE(refused(s, "weight of control point (2, 3)"));
  s = good;
  s.at(1, 1).w() = 0.0;
  EXPECT_TRUE(refused(s, "must be > 0"));
  s = good;
  s.knots_u[5] = 0.5;
  EXPECT_TRUE(refused(s, "knots_u: not non-decreasing at index 5"));
  s = good;
  s.knots_v.front() = 0.5;
  EXPECT_TRUE(refused(s, "knots_v: not clamped"));
  s = good;
  s.knots_u.pop_back();
  EXPECT_TRUE(refused(s, "knots_u has 9 values"));
  s = good;
  s.control.pop_back();
  EXPECT_TRUE(refused(s, "control net has 29 points"));
  s = good;
  s.at(0, 0).x() = std::nan("");
  EXPECT_TRUE(refused(s, "control point (0, 0) has a non-finite coordinate"));
  s = good;
  s.degree_v = 0;
  EXPECT_TRUE(refused(s, "degree_v is 0"));
}

}  // namespace
}  // namespace collido::nurbs
