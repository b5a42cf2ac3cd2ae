// Every FRep node's interval range must hold its function at every point of the box: checked
// against dense sampling of random boxes (large, small, straddling the surface), with the
// double-precision value as the sampled truth.
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <collido/frep/solid.h>

namespace collido::frep {
namespace {

struct NamedSolid {
  std::string name;
  SolidPtr solid;
};

Eigen::Affine3d turned(double degrees, const Eigen::Vector3d& axis, const Eigen::Vector3d& shift) {
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(shift);
  t.rotate(Eigen::AngleAxisd(degrees * M_PI / 180, axis.normalized()));
  return t;
}

std::vector<NamedSolid> everyOperation() {
  const SolidPtr ball = sphere({0.1, -0.2, 0.05}, 0.8);
  const SolidPtr egg = ellipsoid({0, 0, 0}, {0.9, 0.5, 0.7});
  const SolidPtr bar = block({0, 0, 0}, {0.2, 0.3, 0.9});
  const SolidPtr ring = torus({0, 0, 0}, 0.6, 0.2);
  Eigen::Matrix3d a;
  a << -1.0, 0.2, 0.1, 0.2, -2.0, 0.3, 0.1, 0.3, -1.5;
  std::vector<NamedSolid> solids = {
      {"sphere", ball},
      {"ellipsoid", egg},
      {"cylinder", cylinder({0, 0, 0}, 0.5, 1.2)},
      {"open_cylinder", cylinder({0, 0, 0}, 0.5, std::numeric_limits<double>::infinity())},
      {"cone", cone({0, 0, -0.5}, 0.4, 1.0)},
      {"torus", ring},
      {"quadric", quadric(a, {0.1, -0.2, 0.3}, 0.5)},
      {"superellipsoid", superellipsoid({0, 0, 0}, {0.8, 0.6, 0.5}, 0.5, 1.5)},
      {"superellipsoid_round", superellipsoid({0, 0, 0}, {0.8, 0.6, 0.5}, 2.5, 0.3)},
      {"block", bar},
      {"half_space", halfSpace({1, 2, -1}, 0.2)},
      {"perturbed", perturbed(ball, {{{0.8, 0, 0}, 0.4, 0.5}, {{0, 0.5, 0.3}, 0.3, -0.4}})},
      {"union", unionOf({ball, bar, ring}, SetBlend::kMinMax)},
      {"union_r", unionOf({ball, bar}, SetBlend::kRFunction)},
      {"intersection", intersectionOf({egg, bar}, SetBlend::kMinMax)},
      {"intersection_r", intersectionOf({egg, bar}, SetBlend::kRFunction)},
      {"difference", differenceOf(ball, bar, SetBlend::kMinMax)},
      {"difference_r", differenceOf(ball, bar, SetBlend::kRFunction)},
      {"offset", offset(ring, 0.05)},
      {"transform", transformed(bar, turned(35, {1, 1, 0}, {0.2, 0.1, -0.3}))},
      {"scaled", transformed(egg, Eigen::Affine3d(Eigen::Scaling(1.5, 0.5, 2.0)))},
      {"twist", twisted(bar, 2.5)},
      {"morph", morphed(ball, bar, 0.3)},
      {"sweep",
       swept(sphere({0, 0, 0}, 0.2), {{-0.5, 0, 0}, {0.3, 0.4, 0.1}, {0.6, -0.2, 0.3}}, 5)},
      {"projection", projected(transformed(bar, turned(30, {1, 0, 0}, {0, 0, 0})), 2, 6)},
  };
  return solids;
}

class Enclosure : public ::testing::TestWithParam<NamedSolid> {};

TEST_P(Enclosure, IntervalRangeHoldsEverySampledValue) {
  const Solid& solid = *GetParam().solid;
  std::mt19937_64 random(20261124);
  // Box centres within the solid's bounds (clipped), so that many boxes meet its surface.
  const Eigen::AlignedBox3d region = solid.bounds().intersection(
      Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-1.2), Eigen::Vector3d::Constant(1.2)));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> exponent(-6.0, 0.0);
  constexpr int kSamples = 9;  // per axis: 729 points per box
  int boxes_straddling = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d centre = region.min() + region.sizes().cwiseProduct(Eigen::Vector3d(
                                                      unit(random), unit(random), unit(random)));
    const Eigen::Vector3d half = Eigen::Vector3d::NullaryExpr(
        [&](Eigen::Index) { return std::pow(10.0, exponent(random)); });
    const Eigen::AlignedBox3d box(centre - half, centre + half);
    const Interval range = solid.range(IntervalBox::of(box));
    ASSERT_LE(range.lower(), range.upper());
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (int i = 0; i < kSamples; ++i) {
      for (int j = 0; j < kSamples; ++j) {
        for (int k = 0; k < kSamples; ++k) {
          const Eigen::Vector3d t(i, j, k);
          const Eigen::Vector3d p =
              box.min() + (box.max() - box.min()).cwiseProduct(t / (kSamples - 1));
          const double f = solid.value(p);
          low = std::min(low, f);
          high = std::max(high, f);
          // The double value carries rounding of a few ulps of the terms' magnitude.
          const double slack = 1e-12 * (1.0 + std::abs(f));
          ASSERT_GE(f, range.lower() - slack) << GetParam().name << " at " << p.transpose();
          ASSERT_LE(f, range.upper() + slack) << GetParam().name << " at " << p.transpose();
        }
      }
    }
    if (low < 0 && high > 0) ++boxes_straddling;
  }
  // The boxes met the surface often enough for the check to mean something.
  EXPECT_GT(boxes_straddling, 20) << GetParam().name;
}

TEST_P(Enclosure, RangeAtAPointHoldsTheValue) {
  const Solid& solid = *GetParam().solid;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> position(-1.5, 1.5);
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector3d p(position(random), position(random), position(random));
    const Interval range = solid.range(IntervalBox::ofPoint(p));
    const double f = solid.value(p);
    const double slack = 1e-12 * (1.0 + std::abs(f));
    ASSERT_GE(f, range.lower() - slack) << GetParam().name;
    ASSERT_LE(f, range.upper() + slack) << GetParam().name;
    // At a point the enclosure is tight (no box to overestimate over), except where a sweep or
    // projection bounds the path by pieces.
    if (GetParam().name != "sweep" && GetParam().name != "projection") {
      ASSERT_LE(range.upper() - range.lower(), 1e-9 * (1.0 + std::abs(f))) << GetParam().name;
    }
  }
}

TEST_P(Enclosure, BoundsHoldEverySampledInsidePoint) {
  const Solid& solid = *GetParam().solid;
  for (double level : {-0.3, 0.0, 0.2}) {
    const Eigen::AlignedBox3d bounds = solid.superlevelBounds(level);
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> position(-3, 3);
    for (int trial = 0; trial < 20000; ++trial) {
      const Eigen::Vector3d p(position(random), position(random), position(random));
      if (solid.value(p) >= level) {
        ASSERT_TRUE(bounds.contains(p))
            << GetParam().name << " level " << level << " point " << p.transpose();
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryOperation, Enclosure, ::testing::ValuesIn(everyOperation()),
                         [](const ::testing::TestParamInfo<NamedSolid>& param_info) {
                           return param_info.param.name;
                         });

TEST(Interval, OutwardRoundingHoldsTheExactSum) {
  // 0.1 + 0.2 is not representable: the interval must straddle the exact decimal sum.
  const Interval sum = point(0.1) + point(0.2);
  EXPECT_LT(sum.lower(), sum.upper());
  EXPECT_LE(sum.lower(), 0.1 + 0.2);
  EXPECT_GE(sum.upper(), 0.1 + 0.2);
  const Interval zero = point(0.0) * Interval(-3, 5);
  EXPECT_EQ(zero.lower(), 0.0);
  EXPECT_EQ(zero.upper(), 0.0);
}

TEST(Interval, CosineAndSineEncloseSampledValues) {
  for (double from = -7; from < 7; from += 0.37) {
    for (double width : {1e-9, 0.01, 0.5, 2.0, 7.0}) {
      const Interval x(from, from + width);
      const Interval c = cos(x);
      const Interval s = sin(x);
      for (int i = 0; i <= 200; ++i) {
        const double t = from + width * i / 200;
        ASSERT_LE(c.lower(), std::cos(t));
        ASSERT_GE(c.upper(), std::cos(t));
        ASSERT_LE(s.lower(), std::sin(t));
        ASSERT_GE(s.upper(), std::sin(t));
      }
    }
  }
}

TEST(Interval, PowerOfNonNegativeEnclosesSamples) {
  for (double p : {0.3, 1.0, 1.7, 4.0}) {
    const Interval x(0.2, 1.9);
    const Interval y = powNonNegative(x, p);
    for (int i = 0; i <= 100; ++i) {
      const double t = 0.2 + 1.7 * i / 100;
      ASSERT_LE(y.lower(), std::pow(t, p));
      ASSERT_GE(y.upper(), std::pow(t, p));
    }
  }
}

TEST(SolidBuilders, RefuseBadParameters) {
  EXPECT_THROW(sphere({0, 0, 0}, -1), std::invalid_argument);
  EXPECT_THROW(sphere({NAN, 0, 0}, 1), std::invalid_argument);
  EXPECT_THROW(torus({0, 0, 0}, 1, 0), std::invalid_argument);
  EXPECT_THROW(superellipsoid({0, 0, 0}, {1, 1, 1}, 0, 1), std::invalid_argument);
  EXPECT_THROW(morphed(sphere({0, 0, 0}, 1), sphere({0, 0, 0}, 1), 1.5), std::invalid_argument);
  EXPECT_THROW(swept(sphere({0, 0, 0}, 1), {{0, 0, 0}}, 4), std::invalid_argument);
  EXPECT_THROW(transformed(sphere({0, 0, 0}, 1), Eigen::Affine3d(Eigen::Scaling(1.0, 0.0, 1.0))),
               std::invalid_argument);
  EXPECT_THROW(projected(halfSpace({0, 0, 1}, 0), 2, 4), std::invalid_argument);
  EXPECT_THROW(unionOf({}, SetBlend::kMinMax), std::invalid_argument);
}

}  // namespace
}  // namespace collido::frep

namespace collido::frep {
namespace {

// Edge cases where a bound computed in plain double precision was too small (found in review).
TEST(SuperlevelBounds, NearlyAxisNormalKeepsTheHalfSpaceUnbounded) {
  const SolidPtr tilted = halfSpace({1e-9, 0, 1}, 0);
  const Eigen::Vector3d inside(-1e6, 0, 5e-4);  // z <= -1e-9 x
  ASSERT_GE(tilted->value(inside), 0.0);
  EXPECT_TRUE(tilted->bounds().contains(inside));
  // An exact axis normal bounds its side, outward-rounded.
  const SolidPtr floor = halfSpace({0, 0, 1}, 0.1);
  EXPECT_GE(floor->bounds().max().z(), 0.1);
  EXPECT_TRUE(std::isinf(floor->bounds().min().z()));
}

TEST(SuperlevelBounds, TransformOfAFarChildBackToTheOrigin) {
  // A thin block far from its frame's origin, moved back next to the world origin and turned.
  const SolidPtr far = block({1e3, -2e3, 5e2}, {1e-6, 2e-6, 3e-6});
  Eigen::Affine3d back = Eigen::Affine3d::Identity();
  back.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  back.translate(-Eigen::Vector3d(1e3, -2e3, 5e2));
  const SolidPtr near = transformed(far, back);
  const Eigen::AlignedBox3d bounds = near->bounds();
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int inside = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const Eigen::Vector3d p = 5e-6 * Eigen::Vector3d(unit(random), unit(random), unit(random));
    if (near->value(p) >= 0.0) {
      ++inside;
      ASSERT_TRUE(bounds.contains(p)) << p.transpose();
    }
  }
  EXPECT_GT(inside, 100);
}

TEST(SuperlevelBounds, NearlySingularQuadricIsUnbounded) {
  const Eigen::Matrix3d a = Eigen::Vector3d(-1.0, -1.0, -1e-17).asDiagonal();
  const SolidPtr slab = quadric(a, Eigen::Vector3d::Zero(), 1.0);
  EXPECT_FALSE(slab->bounds().max().allFinite());
}

TEST(SuperlevelBounds, OffsetByTheRoundedSquareKeepsTheCentre) {
  // 0.1 * 0.1 rounds to 0.010000000000000002: the solid is a tiny ball about the centre.
  const SolidPtr speck = offset(sphere({0.3, 0.2, 0.1}, 0.1), -0.01);
  ASSERT_GE(speck->value({0.3, 0.2, 0.1}), 0.0);
  EXPECT_TRUE(speck->bounds().contains(Eigen::Vector3d(0.3, 0.2, 0.1)));
}

}  // namespace
}  // namespace collido::frep
