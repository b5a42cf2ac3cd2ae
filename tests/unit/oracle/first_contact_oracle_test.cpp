// The motion over a step (collido/motion.h) and the exact first-contact reference: head-on,
// turning and thin-part crossings against their analytic or densely sampled first contact.
#include <cmath>

#include <gtest/gtest.h>

#include <collido/mesh/procedural.h>
#include <collido/motion.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/oracle/first_contact_oracle.h>

#include "support/mesh_checks.h"

namespace collido {
namespace {

using Outcome = ExactFirstContact::Outcome;

TriangleMesh box(double x, double y, double z) {
  return test::build(makeBox(BoxParams{Eigen::Vector3d(x, y, z)}));
}

Pose at(double x, double y = 0.0, double z = 0.0) {
  Pose pose = Pose::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

StepMotion motion(const Pose& start, const Pose& end) {
  Result<StepMotion> m = StepMotion::between(start, end, "test");
  EXPECT_TRUE(m.ok()) << m.status().toString();
  return m.value();
}

TEST(StepMotion, TurnsAtAConstantRateAboutOneAxisAndMovesItsOriginOnALine) {
  Pose end = at(2.0, 0.0, 0.0);
  end.linear() = Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const StepMotion m = motion(at(0.0), end);
  EXPECT_NEAR(m.angle(), M_PI / 2.0, 1e-15);
  EXPECT_TRUE(m.at(0.0).isApprox(at(0.0), 1e-15));
  EXPECT_TRUE(m.at(1.0).isApprox(end, 1e-15));
  const Pose half = m.at(0.5);
  EXPECT_TRUE(half.translation().isApprox(Eigen::Vector3d(1.0, 0.0, 0.0), 1e-15));
  EXPECT_NEAR(Eigen::AngleAxisd(half.linear()).angle(), M_PI / 4.0, 1e-15);
  // No point within radius 3 moves faster than the bound, sampled over the step.
  const double bound = m.speedBound(3.0);
  const Eigen::Vector3d point(3.0, 0.0, 0.0);
  for (int i = 0; i < 100; ++i) {
    const double t0 = i / 100.0;
    const double t1 = (i + 1) / 100.0;
    EXPECT_LE((m.at(t1) * point - m.at(t0) * point).norm(), bound * (t1 - t0) * (1 + 1e-12));
  }
}

TEST(StepMotion, RefusesAPoseThatIsNotRigidNamingIt) {
  Pose scaled = at(0.0);
  scaled.linear() *= 2.0;
  Result<StepMotion> m = StepMotion::between(at(0.0), scaled, "objects 'peg' in frame 3");
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("objects 'peg' in frame 3: end of the step: not a rotation"),
            std::string::npos)
      << m.status().message();
  const Pose not_finite = at(std::nan(""));
  m = StepMotion::between(not_finite, at(0.0), "peg");
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("peg: start of the step: pose has a non-finite entry"),
            std::string::npos)
      << m.status().message();
}

// A unit cube closing on another along x: faces meet at t = 2/3.
TEST(ExactFirstContact, HeadOnApproachIsBracketedWithinTheWidth) {
  const TriangleMesh cube = box(1, 1, 1);
  const double width = 1e-4;
  const ExactFirstContact c =
      exactFirstContact(cube, motion(at(0), at(0)), cube, motion(at(3), at(0)), width);
  ASSERT_EQ(c.outcome, Outcome::kTouch);
  EXPECT_LE(c.t_lo, 2.0 / 3.0);
  EXPECT_GE(c.t_hi, 2.0 / 3.0 - 1e-12);
  EXPECT_LE(c.t_hi - c.t_lo, width);
  EXPECT_TRUE(exactPairIntersects(cube, at(0), cube, at(3.0 - 3.0 * c.t_hi), c.witness));
}

// A rod 0.02 thick crossing a plate 0.02 thick in one step: they overlap for t in
// [0.498, 0.502] only, so neither end of the step sees it.
TEST(ExactFirstContact, AThinPartCrossingWithinTheStepIsFound) {
  const TriangleMesh plate = box(0.02, 2, 2);
  const TriangleMesh rod = box(0.02, 0.2, 0.2);
  const StepMotion still = motion(at(0), at(0));
  const StepMotion crossing = motion(at(-5), at(5));
  EXPECT_FALSE(exactIntersectingPairs(plate, at(0), rod, at(-5)).intersecting);
  EXPECT_FALSE(exactIntersectingPairs(plate, at(0), rod, at(5)).intersecting);
  const double width = 0.01;
  const ExactFirstContact c = exactFirstContact(plate, still, rod, crossing, width);
  ASSERT_EQ(c.outcome, Outcome::kTouch);
  EXPECT_LE(c.t_lo, 0.498);
  EXPECT_GE(c.t_hi, 0.498 - 1e-12);
  EXPECT_LE(c.t_hi, 0.502 + 1e-12);
  EXPECT_LE(c.t_hi - c.t_lo, width);
}

// A bar turning a quarter turn about its centre sweeps into a post: the bracket holds the first
// of 2,000 evenly spaced exact samples that intersect, and no earlier one does.
TEST(ExactFirstContact, ATurningBarMeetsThePostWhereDenseSamplesSay) {
  const TriangleMesh bar = box(2.0, 0.1, 0.1);
  const TriangleMesh post = box(0.1, 0.1, 0.1);
  Pose turned = at(0);
  turned.linear() = Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const StepMotion turning = motion(at(0), turned);
  const StepMotion still = motion(at(0.3, 0.8), at(0.3, 0.8));
  const int samples = 2000;
  int first = -1;
  for (int i = 0; i <= samples && first < 0; ++i) {
    const double t = static_cast<double>(i) / samples;
    if (exactIntersectingPairs(bar, turning.at(t), post, still.at(t), OracleMode::kFirstPair)
            .intersecting)
      first = i;
  }
  ASSERT_GT(first, 0);
  const double width = 1e-3;
  const ExactFirstContact c = exactFirstContact(bar, turning, post, still, width);
  ASSERT_EQ(c.outcome, Outcome::kTouch);
  EXPECT_LE(c.t_lo, static_cast<double>(first) / samples);
  EXPECT_GE(c.t_hi, static_cast<double>(first - 1) / samples);
  EXPECT_LE(c.t_hi - c.t_lo, width);
}

TEST(ExactFirstContact, APassingCubeIsApartAndATouchingStartIsAtZero) {
  const TriangleMesh cube = box(1, 1, 1);
  const ExactFirstContact apart =
      exactFirstContact(cube, motion(at(0), at(0)), cube, motion(at(-3, 1.5), at(3, 1.5)), 1e-3);
  EXPECT_EQ(apart.outcome, Outcome::kApart);
  EXPECT_EQ(apart.t_lo, 1.0);
  const ExactFirstContact touching =
      exactFirstContact(cube, motion(at(0), at(0)), cube, motion(at(1), at(3)), 1e-3);
  ASSERT_EQ(touching.outcome, Outcome::kTouch);
  EXPECT_EQ(touching.t_lo, 0.0);
  EXPECT_EQ(touching.t_hi, 0.0);
}

// Two cubes sliding past each other face to face, never apart by more than rounding: no
// bracket can be proven past the start, and the oracle says so rather than guessing.
TEST(ExactFirstContact, AGrazingPassWithinRoundingIsUndecided) {
  const TriangleMesh cube = box(1, 1, 1);
  const ExactFirstContact c = exactFirstContact(
      cube, motion(at(0), at(0)), cube, motion(at(-3, 1.0 + 1e-15), at(3, 1.0 + 1e-15)), 1e-3, 64);
  EXPECT_EQ(c.outcome, Outcome::kUndecided);
  EXPECT_LT(c.t_lo, 1.0);
}

}  // namespace
}  // namespace collido
