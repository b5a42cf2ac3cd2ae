// The solver on cases with answers known by hand: each constraint type, fixed parameters,
// independent components, large edits in steps, and the errors for conflicting and redundant
// sets (which must name the constraints and leave the problem as it was).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include <collido/constraints/solve.h>

#include "support/numbers.h"
#include "unit/constraints/constraint_test_support.h"

namespace collido::constraints {
namespace {

using testing::kOrigin;

using test::kPi;

Pose at(double x, double y, double z) {
  Pose pose = Pose::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

TEST(Solve, PointOnPlaneMovesTheBodyStraightAcross) {
  Problem problem(1.0);
  const int body = problem.addBody("part", at(0.3, -0.2, 0.7), 1.0).value();
  ASSERT_TRUE(
      problem
          .addPointOnPlane("on floor", PointRef{body, kOrigin},
                           Plane{PointRef{kWorld, kOrigin}, DirectionRef{kWorld, {0, 0, 1}}})
          .ok());
  const auto report = solve(problem);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_TRUE(
      problem.bodies()[0].pose.translation().isApprox(Eigen::Vector3d(0.3, -0.2, 0.0), 1e-14));
  EXPECT_LT(testing::rotationAngleBetween(problem.bodies()[0].pose, at(0, 0, 0)), 1e-14);
  EXPECT_NEAR(report.value().change, 0.7, 1e-14);
}

TEST(Solve, CoincidentFreeBodiesMeetHalfWay) {
  Problem problem(1.0);
  const int a = problem.addBody("a", at(0, 0, 0), 1.0).value();
  const int b = problem.addBody("b", at(1, 2, 3), 1.0).value();
  ASSERT_TRUE(problem.addCoincident("meet", PointRef{a, kOrigin}, PointRef{b, kOrigin}).ok());
  ASSERT_TRUE(solve(problem).ok());
  EXPECT_TRUE(problem.bodies()[a].pose.translation().isApprox(Eigen::Vector3d(0.5, 1, 1.5), 1e-14));
  EXPECT_TRUE(problem.bodies()[b].pose.translation().isApprox(Eigen::Vector3d(0.5, 1, 1.5), 1e-14));
}

TEST(Solve, FixedBodyStaysAndTheOtherMovesAllTheWay) {
  Problem problem(1.0);
  const int a = problem.addBody("a", at(0, 0, 0), 1.0).value();
  const int b = problem.addBody("b", at(1, 2, 3), 1.0).value();
  ASSERT_TRUE(problem.fixBody(a).ok());
  ASSERT_TRUE(problem.addCoincident("meet", PointRef{a, kOrigin}, PointRef{b, kOrigin}).ok());
  const auto report = solve(problem);
  ASSERT_TRUE(report.ok());
  EXPECT_EQ(report.value().parameters, 6);
  EXPECT_TRUE(problem.bodies()[a].pose.translation().isZero(0.0));
  EXPECT_TRUE(problem.bodies()[b].pose.translation().isZero(1e-14));
}

TEST(Solve, ABodyWithItsRotationFixedOnlySlides) {
  // A point off the body's origin on a plane: turning would be cheaper, but the body may only
  // slide, so it moves straight across and keeps its rotation bit for bit.
  Problem problem(1.0);
  Pose start = at(0.3, -0.2, 0.7);
  start.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const int body = problem.addBody("slider", start, 5.0).value();
  ASSERT_TRUE(problem.fixRotation(body).ok());
  ASSERT_TRUE(
      problem
          .addPointOnPlane("on floor", PointRef{body, Eigen::Vector3d(1.0, 0.0, 0.0)},
                           Plane{PointRef{kWorld, kOrigin}, DirectionRef{kWorld, {0, 0, 1}}})
          .ok());
  const auto report = solve(problem);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.value().parameters, 3);
  EXPECT_EQ(problem.bodies()[body].pose.linear(), start.linear());
  EXPECT_TRUE(
      problem.bodies()[body].pose.translation().isApprox(Eigen::Vector3d(0.3, -0.2, 0.0), 1e-14));
  EXPECT_FALSE(problem.fixRotation(7).ok());
}

TEST(Solve, ADirectionConstraintOnBodiesThatCannotTurnIsCheckedAsFrozen) {
  Problem problem(1.0);
  const int body = problem.addBody("slider", at(0, 0, 0), 1.0).value();
  ASSERT_TRUE(problem.fixRotation(body).ok());
  ASSERT_TRUE(
      problem.addParallel("level", DirectionRef{body, {0, 0, 1}}, DirectionRef{kWorld, {0, 0, 1}})
          .ok());
  ASSERT_TRUE(solve(problem).ok());  // holds already
  ASSERT_TRUE(problem
                  .addPerpendicular("tilted", DirectionRef{body, {0, 0, 1}},
                                    DirectionRef{kWorld, {0, 0, 1}})
                  .ok());
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("'tilted' involves only fixed objects"),
            std::string::npos)
      << report.status().message();
}

TEST(Solve, DistanceSplitsTheChangeByTheParametersWeights) {
  // Body moves a along x, the free variable changes by c: minimise (a/L)² + (c/s)² with
  // 2 + a − (1 + c) = 0 → a = −L²/(L² + s²), c = s²/(L² + s²).
  const double length = 2.0;
  const double scale = 1.0;
  Problem problem(length);
  const int body = problem.addBody("b", at(2, 0, 0), 1.0).value();
  const int gap = problem.addVariable("gap", 1.0, scale).value();
  ASSERT_TRUE(
      problem
          .addDistance("gap", PointRef{kWorld, kOrigin}, PointRef{body, kOrigin}, Target{0.0, gap})
          .ok() == false);  // names must be unique
  ASSERT_TRUE(problem
                  .addDistance("spacing", PointRef{kWorld, kOrigin}, PointRef{body, kOrigin},
                               Target{0.0, gap})
                  .ok());
  ASSERT_TRUE(solve(problem).ok());
  const double weight = length * length + scale * scale;
  EXPECT_NEAR(problem.bodies()[body].pose.translation().x(), 2.0 - length * length / weight, 1e-13);
  EXPECT_NEAR(problem.variables()[gap].value, 1.0 + scale * scale / weight, 1e-13);
}

TEST(Solve, AngleTurnsTheFreeBodyByTheDifferenceAboutTheCommonNormal) {
  // Tilted 0.1 rad about y to start (at 0 the angle has no gradient); tilted to 0.4.
  Problem problem(1.0);
  Pose start = at(1, 1, 1);
  start.linear() = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const int body = problem.addBody("b", start, 1.0).value();
  ASSERT_TRUE(problem
                  .addAngle("tilt", DirectionRef{kWorld, {1, 0, 0}}, DirectionRef{body, {1, 0, 0}},
                            Target{0.4})
                  .ok());
  const auto report = solve(problem);
  ASSERT_TRUE(report.ok()) << report.status().message();
  const Pose& pose = problem.bodies()[body].pose;
  const Eigen::Vector3d x_axis = pose.linear().col(0);
  EXPECT_NEAR(std::acos(x_axis.x()), 0.4, 1e-12);
  // The least turn that tilts x from 0.1 to 0.4 rad is 0.3 rad about y.
  EXPECT_NEAR(testing::rotationAngleBetween(start, pose), 0.3, 1e-12);
  EXPECT_NEAR(testing::rotationAngleBetween(at(0, 0, 0), pose), 0.4, 1e-12);
  EXPECT_NEAR(report.value().change, 0.3, 1e-12);
  EXPECT_TRUE(pose.translation().isApprox(Eigen::Vector3d(1, 1, 1), 1e-14));
}

TEST(Solve, ParallelPerpendicularAndCoaxialHoldAfterTheSolve) {
  std::mt19937_64 random(3);
  Problem problem(1.0);
  const int a = problem.addBody("a", testing::randomPose(random, 1.0), 1.0).value();
  const int b = problem.addBody("b", testing::randomPose(random, 1.0), 1.0).value();
  const int c = problem.addBody("c", testing::randomPose(random, 1.0), 1.0).value();
  ASSERT_TRUE(problem.fixBody(a).ok());
  ASSERT_TRUE(
      problem.addParallel("b along a", DirectionRef{a, {0, 0, 1}}, DirectionRef{b, {0, 1, 0}})
          .ok());
  ASSERT_TRUE(
      problem.addPerpendicular("c across a", DirectionRef{a, {0, 0, 1}}, DirectionRef{c, {0, 0, 1}})
          .ok());
  ASSERT_TRUE(problem
                  .addCoaxial("c on a's axis",
                              Axis{PointRef{a, {0, 0, 0}}, DirectionRef{a, {1, 0, 0}}},
                              Axis{PointRef{c, {0.2, 0, 0}}, DirectionRef{c, {1, 0, 0}}})
                  .ok());
  const auto report = solve(problem);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.value().components, 2);  // b alone, c alone: a is fixed
  const Pose& pa = problem.bodies()[a].pose;
  const Pose& pb = problem.bodies()[b].pose;
  const Pose& pc = problem.bodies()[c].pose;
  EXPECT_NEAR(std::abs(pa.linear().col(2).dot(pb.linear().col(1))), 1.0, 1e-14);
  EXPECT_NEAR(pa.linear().col(2).dot(pc.linear().col(2)), 0.0, 1e-13);
  EXPECT_NEAR(std::abs(pa.linear().col(0).dot(pc.linear().col(0))), 1.0, 1e-14);
  const Eigen::Vector3d offset = pc * Eigen::Vector3d(0.2, 0, 0) - pa.translation();
  EXPECT_LT(offset.cross(pa.linear().col(0)).norm(), 1e-12);
  EXPECT_LT(report.value().max_residual, 1e-12);
}

TEST(Solve, PointOnLineKeepsTheFootOfThePerpendicular) {
  Problem problem(1.0);
  const int body = problem.addBody("b", at(3, 0.4, -0.3), 1.0).value();
  ASSERT_TRUE(problem
                  .addPointOnLine("rail", PointRef{body, kOrigin},
                                  Axis{PointRef{kWorld, kOrigin}, DirectionRef{kWorld, {1, 0, 0}}})
                  .ok());
  ASSERT_TRUE(solve(problem).ok());
  EXPECT_TRUE(problem.bodies()[body].pose.translation().isApprox(Eigen::Vector3d(3, 0, 0), 1e-14));
}

TEST(Solve, AlreadySatisfiedProblemsDoNotMove) {
  Problem problem(1.0);
  const Pose start = at(1, 2, 3);
  const int body = problem.addBody("b", start, 1.0).value();
  ASSERT_TRUE(problem
                  .addDistance("held", PointRef{kWorld, kOrigin}, PointRef{body, kOrigin},
                               Target{start.translation().norm()})
                  .ok());
  const auto report = solve(problem);
  ASSERT_TRUE(report.ok());
  EXPECT_EQ(report.value().change, 0.0);
  EXPECT_TRUE(problem.bodies()[body].pose.isApprox(start, 0.0));
}

TEST(Solve, ALargeEditIsApproachedInStepsAndStillChangesLeast) {
  // A door on a hinge (the z axis) opened from 0.2 to 3.0 rad: Newton on the angle's cosine
  // straight from the start would overshoot by far; the answer is the 2.8 rad turn about the
  // hinge, not the shorter-looking −3.2 rad one.
  Problem problem(1.0);
  Pose start = Pose::Identity();
  start.linear() = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const int door = problem.addBody("door", start, 1.0).value();
  const int opening = problem.addVariable("opening", 0.2, 1.0).value();
  ASSERT_TRUE(problem
                  .addCoaxial("hinge", Axis{PointRef{door, kOrigin}, DirectionRef{door, {0, 0, 1}}},
                              Axis{PointRef{kWorld, kOrigin}, DirectionRef{kWorld, {0, 0, 1}}})
                  .ok());
  ASSERT_TRUE(
      problem
          .addPointOnPlane("sill", PointRef{door, kOrigin},
                           Plane{PointRef{kWorld, kOrigin}, DirectionRef{kWorld, {0, 0, 1}}})
          .ok());
  ASSERT_TRUE(problem
                  .addAngle("open", DirectionRef{kWorld, {1, 0, 0}}, DirectionRef{door, {1, 0, 0}},
                            Target{0.0, opening})
                  .ok());
  ASSERT_TRUE(solve(problem).ok());  // already holds
  ASSERT_TRUE(problem.setVariable(opening, 3.0).ok());
  const auto report = solve(problem);
  ASSERT_TRUE(report.ok()) << report.status().message();
  const Eigen::AngleAxisd turn(start.linear().transpose() * problem.bodies()[door].pose.linear());
  EXPECT_NEAR(turn.angle(), 2.8, 1e-12);
  EXPECT_NEAR(std::abs(turn.axis().z()), 1.0, 1e-12);
  EXPECT_NEAR(report.value().change, 2.8, 1e-12);
  EXPECT_LT(problem.bodies()[door].pose.translation().norm(), 1e-14);
  EXPECT_GE(report.value().edit_steps, 1);
}

TEST(Solve, ConflictingDistancesAreNamedAndNothingMoves) {
  Problem problem(1.0);
  const int a = problem.addBody("a", at(0, 0, 0), 1.0).value();
  const int b = problem.addBody("b", at(1.5, 0, 0), 1.0).value();
  ASSERT_TRUE(
      problem.addDistance("one", PointRef{a, kOrigin}, PointRef{b, kOrigin}, Target{1.0}).ok());
  ASSERT_TRUE(
      problem.addDistance("two", PointRef{b, kOrigin}, PointRef{a, kOrigin}, Target{2.0}).ok());
  const Problem start = problem;
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("conflicting"), std::string::npos)
      << report.status().message();
  EXPECT_NE(report.status().message().find("'one'"), std::string::npos);
  EXPECT_NE(report.status().message().find("'two'"), std::string::npos);
  EXPECT_TRUE(problem.bodies()[b].pose.isApprox(start.bodies()[b].pose, 0.0));
}

TEST(Solve, RedundantConstraintsAreNamedOrDroppedWhenAllowed) {
  Problem problem(1.0);
  const int a = problem.addBody("a", at(0, 0, 0), 1.0).value();
  const int b = problem.addBody("b", at(0.2, 0.1, 0), 1.0).value();
  ASSERT_TRUE(problem.fixBody(a).ok());
  ASSERT_TRUE(problem.addCoincident("pin", PointRef{a, {1, 0, 0}}, PointRef{b, kOrigin}).ok());
  ASSERT_TRUE(problem
                  .addPointOnPlane("pin on plane", PointRef{b, kOrigin},
                                   Plane{PointRef{a, {1, 0, 0}}, DirectionRef{a, {0, 1, 0}}})
                  .ok());
  Problem strict = problem;
  const auto refused = solve(strict);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.status().message().find("redundant"), std::string::npos);
  EXPECT_NE(refused.status().message().find("'pin on plane' with 'pin'"), std::string::npos)
      << refused.status().message();
  EXPECT_TRUE(strict.bodies()[b].pose.isApprox(problem.bodies()[b].pose, 0.0));

  SolveOptions options;
  options.allow_redundant = true;
  const auto allowed = solve(problem, options);
  ASSERT_TRUE(allowed.ok()) << allowed.status().message();
  EXPECT_EQ(allowed.value().dropped_redundant, std::vector<std::string>{"pin on plane"});
  EXPECT_TRUE(problem.bodies()[b].pose.translation().isApprox(Eigen::Vector3d(1, 0, 0), 1e-14));
}

TEST(Solve, ACycleOfCoincidencesInRotatedFramesIsRedundant) {
  // a = b, b = c, c = a on points of three turned bodies: the third repeats the first two up to
  // rounding, which the rank analysis must still see.
  std::mt19937_64 random(11);
  Problem problem(1.0);
  int bodies[3];
  for (int i = 0; i < 3; ++i) {
    bodies[i] =
        problem.addBody("body " + std::to_string(i), testing::randomPose(random, 1.0), 1.0).value();
  }
  const Eigen::Vector3d p(0.3, -0.2, 0.1);
  ASSERT_TRUE(problem.addCoincident("ab", PointRef{bodies[0], p}, PointRef{bodies[1], p}).ok());
  ASSERT_TRUE(problem.addCoincident("bc", PointRef{bodies[1], p}, PointRef{bodies[2], p}).ok());
  ASSERT_TRUE(problem.addCoincident("ca", PointRef{bodies[2], p}, PointRef{bodies[0], p}).ok());
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("redundant constraints: 'ca' with 'ab', 'bc'"),
            std::string::npos)
      << report.status().message();
}

TEST(Solve, UnreachableDistancesConflictNonlinearly) {
  // A point 1 from each of two fixed points 5 apart: no solution exists.
  Problem problem(1.0);
  const int body = problem.addBody("b", at(2.5, 0.3, 0), 1.0).value();
  ASSERT_TRUE(
      problem.addDistance("left", PointRef{kWorld, {0, 0, 0}}, PointRef{body, kOrigin}, Target{1.0})
          .ok());
  ASSERT_TRUE(
      problem
          .addDistance("right", PointRef{kWorld, {5, 0, 0}}, PointRef{body, kOrigin}, Target{1.0})
          .ok());
  const Problem start = problem;
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("'left'"), std::string::npos)
      << report.status().message();
  EXPECT_NE(report.status().message().find("'right'"), std::string::npos)
      << report.status().message();
  EXPECT_TRUE(problem.bodies()[body].pose.isApprox(start.bodies()[body].pose, 0.0));
}

TEST(Solve, AConstraintWithoutGradientAtTheStartIsNamedAsSingular) {
  // Parallel directions: the angle's cosine is flat there, no first-order step can open it.
  Problem problem(1.0);
  const int body = problem.addBody("b", at(0, 0, 0), 1.0).value();
  ASSERT_TRUE(problem
                  .addAngle("tilt", DirectionRef{kWorld, {1, 0, 0}}, DirectionRef{body, {1, 0, 0}},
                            Target{0.4})
                  .ok());
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("'tilt' has no gradient"), std::string::npos)
      << report.status().message();
}

TEST(Solve, AConstraintOnFixedObjectsOnlyMustAlreadyHold) {
  Problem problem(1.0);
  const int a = problem.addBody("a", at(0, 0, 0), 1.0).value();
  ASSERT_TRUE(problem.fixBody(a).ok());
  ASSERT_TRUE(
      problem.addDistance("frozen", PointRef{a, kOrigin}, PointRef{kWorld, {1, 0, 0}}, Target{2.0})
          .ok());
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("'frozen' involves only fixed"), std::string::npos)
      << report.status().message();
}

TEST(Solve, AFrozenConstraintOffByLittleShowsHowLittle) {
  // Off by 1e-9: fixed six decimals would print "residual 0.000000".
  Problem problem(1.0);
  const int a = problem.addBody("a", at(0, 0, 0), 1.0).value();
  ASSERT_TRUE(problem.fixBody(a).ok());
  ASSERT_TRUE(problem
                  .addDistance("frozen", PointRef{a, kOrigin}, PointRef{kWorld, {1, 0, 0}},
                               Target{1.0 + 1e-9})
                  .ok());
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("(residual 1e-09)"), std::string::npos)
      << report.status().message();
}

TEST(Solve, AConstraintWithinOneBodyIsCheckedNotSolved) {
  // Two points of one body: no rigid motion changes their distance.
  Problem problem(1.0);
  const int body = problem.addBody("b", at(0, 0, 0), 1.0).value();
  ASSERT_TRUE(
      problem.addDistance("inside", PointRef{body, kOrigin}, PointRef{body, {1, 0, 0}}, Target{2.0})
          .ok());
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find(
                "'inside' involves only fixed objects and values (or one body alone)"),
            std::string::npos)
      << report.status().message();
}

TEST(Solve, AVariableAngleOutsideItsRangeIsRefusedNamingBoth) {
  Problem problem(1.0);
  Pose start = Pose::Identity();
  start.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const int body = problem.addBody("b", start, 1.0).value();
  const int opening = problem.addVariable("opening", 0.5, 1.0).value();
  ASSERT_TRUE(problem
                  .addAngle("open", DirectionRef{kWorld, {1, 0, 0}}, DirectionRef{body, {1, 0, 0}},
                            Target{0.0, opening})
                  .ok());
  ASSERT_TRUE(problem.setVariable(opening, -0.5).ok());
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find(
                "constraint 'open': its variable 'opening' is -0.5 before the solve"),
            std::string::npos)
      << report.status().message();
}

TEST(ProblemBuilding, RefusesBadReferencesAndValuesNamingTheConstraint) {
  Problem problem(1.0);
  const int a = problem.addBody("a", at(0, 0, 0), 1.0).value();
  const auto message = [](const Result<int>& result) {
    return result.ok() ? std::string("accepted") : result.status().message();
  };
  EXPECT_NE(message(problem.addCoincident("x", PointRef{7, kOrigin}, PointRef{a, kOrigin}))
                .find("'x': the point names no body"),
            std::string::npos);
  EXPECT_NE(message(problem.addParallel("y", DirectionRef{a, {0, 0, 0}}, DirectionRef{}))
                .find("'y': the direction is a zero vector"),
            std::string::npos);
  EXPECT_NE(message(problem.addAngle("z", DirectionRef{a, {1, 0, 0}}, DirectionRef{}, Target{0.0}))
                .find("strictly between 0 and pi"),
            std::string::npos);
  EXPECT_NE(message(problem.addAngle("z", DirectionRef{a, {1, 0, 0}}, DirectionRef{}, Target{kPi}))
                .find("strictly between"),
            std::string::npos);
  EXPECT_NE(message(problem.addDistance("w", PointRef{a, kOrigin}, PointRef{}, Target{-1.0}))
                .find("'w': a distance must be positive"),
            std::string::npos);
  EXPECT_NE(message(problem.addDistance("v", PointRef{a, kOrigin}, PointRef{}, Target{1.0, 3}))
                .find("'v': the target names no variable"),
            std::string::npos);
  EXPECT_NE(
      message(problem.addCoincident("", PointRef{}, PointRef{a, kOrigin})).find("needs a name"),
      std::string::npos);
  EXPECT_NE(message(problem.addBody("a", at(0, 0, 0), 1.0)).find("'a': the name is already used"),
            std::string::npos);
  EXPECT_NE(message(problem.addBody("nan", at(std::nan(""), 0, 0), 1.0))
                .find("'nan': the pose is not finite"),
            std::string::npos);
  Pose sheared = Pose::Identity();
  sheared.linear()(0, 1) = 0.5;
  EXPECT_NE(message(problem.addBody("s", sheared, 1.0)).find("not a rotation"), std::string::npos);
  EXPECT_NE(message(problem.addBody("r", at(0, 0, 0), 0.0)).find("radius"), std::string::npos);
  EXPECT_NE(message(problem.addVariable("q", 1.0, -1.0)).find("scale"), std::string::npos);
  EXPECT_FALSE(problem.fixBody(3).ok());
  const int v = problem.addVariable("v", 1.0, 1.0).value();
  EXPECT_FALSE(problem.setVariable(v, std::nan("")).ok());
  EXPECT_FALSE(problem.variables()[v].fixed);  // a refused edit changes nothing
  EXPECT_TRUE(problem.constraints().empty());
}

}  // namespace
}  // namespace collido::constraints
