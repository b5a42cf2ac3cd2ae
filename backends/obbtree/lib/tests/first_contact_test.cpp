// The tree's first contact over a step against the exact reference's bracket: the same verdict,
// and brackets that meet (each proves its free part and its contact), on analytic cases and on
// tori thrown past each other turning.
#include <random>

#include <gtest/gtest.h>

#include <collido/mesh/procedural.h>
#include <collido/obbtree/first_contact.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/oracle/first_contact_oracle.h>

#include "collide_check.h"

namespace collido::obbtree {
namespace {

using Outcome = ExactFirstContact::Outcome;

Pose at(double x, double y = 0.0, double z = 0.0) {
  Pose pose = Pose::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

StepMotion motion(const Pose& start, const Pose& end) {
  return StepMotion::between(start, end, "test").value();
}

// The tree's answer against the oracle's, with the tree's witness touching at its t_hi; returns
// whether they touch.
bool expectAgrees(const TriangleMesh& a, const StepMotion& ma, const TriangleMesh& b,
                  const StepMotion& mb, double width, const BuildOptions& options = {}) {
  const ObbTree tree_a = ObbTree::build(a.vertices, a.triangles, options);
  const ObbTree tree_b = ObbTree::build(b.vertices, b.triangles, options);
  FirstContactAnswer ours;
  firstContact(MovingTree{tree_a, ma, radiusAboutOrigin(tree_a)},
               MovingTree{tree_b, mb, radiusAboutOrigin(tree_b)}, width, ours);
  const ExactFirstContact truth = exactFirstContact(a, ma, b, mb, width);
  EXPECT_NE(truth.outcome, Outcome::kUndecided);
  EXPECT_EQ(ours.touches, truth.outcome == Outcome::kTouch)
      << "oracle [" << truth.t_lo << ", " << truth.t_hi << "], ours from " << ours.t_lo;
  if (!ours.touches) {
    EXPECT_EQ(ours.t_lo, 1.0);
    return false;
  }
  EXPECT_LE(ours.t_hi - ours.t_lo, width);
  EXPECT_GE(ours.t_hi, truth.t_lo - 1e-12);
  EXPECT_LE(ours.t_lo, truth.t_hi + 1e-12);
  EXPECT_TRUE(exactPairIntersects(a, ma.at(ours.t_hi), b, mb.at(ours.t_hi),
                                  collido::TrianglePair{ours.triangle_a, ours.triangle_b}));
  return true;
}

TEST(FirstContact, HeadOnThinCrossingAndTurningBarAgreeWithTheReference) {
  const TriangleMesh cube = unwrap(makeBox(BoxParams{Eigen::Vector3d(1, 1, 1)}), "cube");
  expectAgrees(cube, motion(at(0), at(0)), cube, motion(at(3), at(0)), 1e-4);
  const TriangleMesh plate = unwrap(makeBox(BoxParams{Eigen::Vector3d(0.02, 2, 2)}), "plate");
  const TriangleMesh rod = unwrap(makeBox(BoxParams{Eigen::Vector3d(0.02, 0.2, 0.2)}), "rod");
  expectAgrees(plate, motion(at(0), at(0)), rod, motion(at(-5), at(5)), 0.01);
  const TriangleMesh bar = unwrap(makeBox(BoxParams{Eigen::Vector3d(2, 0.1, 0.1)}), "bar");
  Pose turned = at(0);
  turned.linear() = Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  expectAgrees(bar, motion(at(0), turned), cube, motion(at(0.8, 0.8), at(0.8, 0.8)), 1e-3);
  expectAgrees(cube, motion(at(0), at(0)), cube, motion(at(-3, 1.5), at(3, 1.5)), 1e-3);
  expectAgrees(cube, motion(at(0), at(0)), cube, motion(at(0.5), at(3)), 1e-3);
}

// Tori thrown past and into each other, turning about random axes.
TEST(FirstContact, TurningToriAgreeWithTheReference) {
  TorusParams params;
  params.major_segments = 16;
  params.minor_segments = 8;
  const TriangleMesh torus = unwrap(makeTorus(params), "torus");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto random_pose = [&](double spread) {
    Pose pose = at(spread * u(rng), spread * u(rng), spread * u(rng));
    pose.linear() = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().matrix();
    return pose;
  };
  int touches = 0;
  const int trials = 16;
  for (int trial = 0; trial < trials; ++trial) {
    SCOPED_TRACE(trial);
    const Pose start_a = random_pose(0.3);
    const Pose end_a = random_pose(0.3);
    const Pose start_b = random_pose(4.0);
    const Pose end_b = random_pose(1.5);
    touches += expectAgrees(torus, motion(start_a, end_a), torus, motion(start_b, end_b),
                            trial % 2 == 0 ? 1e-3 : 1e-2)
                   ? 1
                   : 0;
  }
  // Both verdicts are exercised.
  EXPECT_GT(touches, 0);
  EXPECT_LT(touches, trials);
}

// A peg sliding down a sleeve with little clearance while it drifts and tilts into the wall:
// every advance's pairs face each other across the gap, moving mostly along it, where a motion
// bound per pair along its own direction counts (and must still never step past the contact).
// Both node kinds, and leaves of one and of several triangles.
TEST(FirstContact, PegSlidingIntoASleeveWallAgreesWithTheReference) {
  CylinderParams sleeve_params;
  sleeve_params.radius = 0.3;
  sleeve_params.inner_radius = 0.2;
  sleeve_params.height = 0.4;
  sleeve_params.segments = 24;
  CylinderParams peg_params;
  peg_params.radius = 0.19;
  peg_params.height = 0.6;
  peg_params.segments = 24;
  const TriangleMesh sleeve = unwrap(makeCylinder(sleeve_params), "sleeve");
  const TriangleMesh peg = unwrap(makeCylinder(peg_params), "peg");
  const auto peg_at = [](double x, double z, double tilt_degrees) {
    Pose pose = at(x, 0.0, z);
    pose.linear() =
        Eigen::AngleAxisd(tilt_degrees * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
    return pose;
  };
  BuildOptions compact;
  compact.float_boxes = true;
  compact.max_leaf_triangles = 8;
  int touches = 0;
  for (const BuildOptions& options : {BuildOptions{}, compact}) {
    for (int k = 0; k < 5; ++k) {
      SCOPED_TRACE(k);
      const double drift = 0.003 + 0.001 * k;
      const double tilt = 0.4 * k;
      touches += expectAgrees(sleeve, motion(at(0), at(0)), peg,
                              motion(peg_at(k * drift, 0.45 - 0.1 * k, k * tilt),
                                     peg_at((k + 1) * drift, 0.35 - 0.1 * k, (k + 1) * tilt)),
                              1e-3, options)
                     ? 1
                     : 0;
    }
  }
  EXPECT_GT(touches, 0);
  EXPECT_LT(touches, 10);
}

}  // namespace
}  // namespace collido::obbtree
