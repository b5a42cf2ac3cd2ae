// The clearance constraint: the distance between two bodies' shapes through a distance query,
// on balls whose answers are known exactly — the least move, contact, overlaps the query can and
// cannot measure, variables, and a query that fails.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include <collido/constraints/solve.h>

#include "unit/constraints/constraint_test_support.h"

namespace collido::constraints {
namespace {

using testing::BallSeparation;
using testing::kOrigin;

/// Two bodies at the origin and at (x, 0, 0), each carrying a ball of `radius` at its origin.
struct TwoBalls {
  explicit TwoBalls(double x, double radius = 0.5) {
    Pose far = Pose::Identity();
    far.translation() = Eigen::Vector3d(x, 0.0, 0.0);
    a = problem.addBody("a", Pose::Identity(), 1.0).value();
    b = problem.addBody("b", far, 1.0).value();
    query = std::make_shared<BallSeparation>(
        std::vector<BallSeparation::Ball>{{kOrigin, radius}, {kOrigin, radius}});
    problem.setSeparationQuery(query);
  }

  double gap() const {
    return (problem.bodies()[b].pose.translation() - problem.bodies()[a].pose.translation())
               .norm() -
           1.0;
  }

  Problem problem{1.0};
  int a = 0;
  int b = 0;
  std::shared_ptr<BallSeparation> query;
};

TEST(Clearance, AFreeBodyMovesStraightToTheClearance) {
  TwoBalls balls(1.5);  // a gap of 0.5
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  ASSERT_TRUE(balls.problem.addClearance("dock", balls.a, balls.b, Target{1e-4}).ok());
  const auto report = solve(balls.problem);
  ASSERT_TRUE(report.ok()) << report.status().message();
  const Pose& b = balls.problem.bodies()[balls.b].pose;
  EXPECT_NEAR(b.translation().x(), 1.0001, 1e-14);
  EXPECT_NEAR(b.translation().y(), 0.0, 1e-14);
  EXPECT_NEAR(report.value().change, 0.4999, 1e-12);
  EXPECT_LT(testing::rotationAngleBetween(Pose::Identity(), b), 1e-14);
}

TEST(Clearance, TwoFreeBodiesShareTheMove) {
  TwoBalls balls(1.5);
  ASSERT_TRUE(balls.problem.addClearance("dock", balls.a, balls.b, Target{0.1}).ok());
  ASSERT_TRUE(solve(balls.problem).ok());
  EXPECT_NEAR(balls.problem.bodies()[balls.a].pose.translation().x(), 0.2, 1e-13);
  EXPECT_NEAR(balls.problem.bodies()[balls.b].pose.translation().x(), 1.3, 1e-13);
}

TEST(Clearance, ZeroClearanceIsContact) {
  TwoBalls balls(1.5);
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  ASSERT_TRUE(balls.problem.addClearance("touch", balls.a, balls.b, Target{0.0}).ok());
  ASSERT_TRUE(solve(balls.problem).ok());
  EXPECT_NEAR(balls.gap(), 0.0, 1e-14);
}

TEST(Clearance, AnOverlapTheQueryMeasuresIsPushedApart) {
  TwoBalls balls(0.7);  // 0.3 deep
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  ASSERT_TRUE(balls.problem.addClearance("apart", balls.a, balls.b, Target{0.05}).ok());
  ASSERT_TRUE(solve(balls.problem).ok());
  EXPECT_NEAR(balls.gap(), 0.05, 1e-14);
}

TEST(Clearance, AnOverlapTheQueryCannotMeasureIsMeasuredByHowFarItTakesToPart) {
  // A distance-only query: the overlap's depth is the least move of B along the line of the
  // origins that parts them, found by bisection on the distance, so the solve pushes B out.
  TwoBalls balls(0.7);  // 0.3 deep
  balls.query->reports_depth = false;
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  ASSERT_TRUE(balls.problem.addClearance("apart", balls.a, balls.b, Target{0.05}).ok());
  const auto report = solve(balls.problem);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_NEAR(balls.gap(), 0.05, 1e-14);
}

TEST(Clearance, AnOverlapNothingNearbyPartsIsRefusedByName) {
  // Balls of radius 20 overlapping by 39.3: 16 length scales of travel do not part them.
  TwoBalls balls(0.7, 20.0);
  balls.query->reports_depth = false;
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  ASSERT_TRUE(balls.problem.addClearance("apart", balls.a, balls.b, Target{0.05}).ok());
  const auto report = solve(balls.problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("'apart' has no gradient"), std::string::npos)
      << report.status().message();
  EXPECT_EQ(balls.problem.bodies()[balls.b].pose.translation().x(), 0.7);
}

TEST(Clearance, ContactWithoutDepthIsReachedFromApart) {
  // A distance-only query: touching gives no direction, so the last one seen apart is used.
  TwoBalls balls(1.5);
  balls.query->reports_depth = false;
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  ASSERT_TRUE(balls.problem.addClearance("touch", balls.a, balls.b, Target{0.0}).ok());
  ASSERT_TRUE(solve(balls.problem).ok());
  EXPECT_NEAR(balls.gap(), 0.0, 1e-14);
}

TEST(Clearance, ShapesThatOnlyTouchAtTheStartArePartedAlongTheirOrigins) {
  // Distance 0 and no depth, no direction seen yet: a rounding-size step along the line of the
  // origins parts them, so they touch (depth 0) and that line is the way out.
  TwoBalls balls(1.0);
  balls.query->reports_depth = false;
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  ASSERT_TRUE(balls.problem.addClearance("apart", balls.a, balls.b, Target{0.05}).ok());
  ASSERT_TRUE(solve(balls.problem).ok());
  EXPECT_NEAR(balls.gap(), 0.05, 1e-14);
}

TEST(Clearance, ContactThatHoldsAtTheStartIsMetWithoutAChange) {
  TwoBalls balls(1.0);
  balls.query->reports_depth = false;
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  ASSERT_TRUE(balls.problem.addClearance("touch", balls.a, balls.b, Target{0.0}).ok());
  const auto report = solve(balls.problem);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.value().change, 0.0);
  EXPECT_EQ(balls.problem.bodies()[balls.b].pose.translation().x(), 1.0);
}

TEST(Clearance, AFailingQueryOnFixedBodiesIsReported) {
  TwoBalls balls(1.5);
  balls.query->fail_from_call = 1;
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  ASSERT_TRUE(balls.problem.fixBody(balls.b).ok());
  ASSERT_TRUE(balls.problem.addClearance("held", balls.a, balls.b, Target{0.5}).ok());
  const auto report = solve(balls.problem);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.status().message(),
            "constraint 'held': the distance query failed: the engine crashed");
}

TEST(Clearance, FollowsAVariable) {
  TwoBalls balls(1.5);
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  const int backlash = balls.problem.addVariable("backlash", 0.5, 0.01).value();
  ASSERT_TRUE(balls.problem.addClearance("mesh", balls.a, balls.b, Target{0.0, backlash}).ok());
  ASSERT_TRUE(balls.problem.setVariable(backlash, 0.02).ok());
  ASSERT_TRUE(solve(balls.problem).ok());
  EXPECT_NEAR(balls.gap(), 0.02, 1e-14);
}

TEST(Clearance, AFreeVariableTakesTheChangeWhenItWeighsLess) {
  TwoBalls balls(1.5);
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  const int gap = balls.problem.addVariable("gap", 0.1, 1.0).value();
  ASSERT_TRUE(balls.problem.addClearance("mesh", balls.a, balls.b, Target{0.0, gap}).ok());
  ASSERT_TRUE(solve(balls.problem).ok());
  // Equal weights: the body and the variable each take half of the 0.4 difference.
  EXPECT_NEAR(balls.gap(), 0.3, 1e-13);
  EXPECT_NEAR(balls.problem.variables()[gap].value, 0.3, 1e-13);
}

TEST(Clearance, AFailingQueryEndsTheSolveWithItsMessageAndChangesNothing) {
  TwoBalls balls(1.5);
  balls.query->fail_from_call = 3;
  ASSERT_TRUE(balls.problem.fixBody(balls.a).ok());
  ASSERT_TRUE(balls.problem.addClearance("dock", balls.a, balls.b, Target{0.1}).ok());
  const auto report = solve(balls.problem);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.status().message(),
            "constraint 'dock': the distance query failed: the engine crashed");
  EXPECT_EQ(balls.problem.bodies()[balls.b].pose.translation().x(), 1.5);
}

TEST(Clearance, NeedsADistanceQuery) {
  Problem problem;
  ASSERT_TRUE(problem.addBody("a", Pose::Identity(), 1.0).ok());
  ASSERT_TRUE(problem.addBody("b", Pose::Identity(), 1.0).ok());
  ASSERT_TRUE(problem.addClearance("dock", 0, 1, Target{0.1}).ok());
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("'dock': a clearance needs a distance query"),
            std::string::npos);
}

TEST(Clearance, BuilderRefusesBadBodiesAndNegativeClearances) {
  TwoBalls balls(1.5);
  Problem& problem = balls.problem;
  EXPECT_NE(problem.addClearance("w", kWorld, 1, Target{0.1})
                .status()
                .message()
                .find("'w': the first body names no body"),
            std::string::npos);
  EXPECT_NE(
      problem.addClearance("s", 1, 1, Target{0.1}).status().message().find("two different bodies"),
      std::string::npos);
  EXPECT_NE(problem.addClearance("n", 0, 1, Target{-0.1}).status().message().find(">= 0"),
            std::string::npos);
  const int v = problem.addVariable("v", -1.0, 1.0).value();
  ASSERT_TRUE(problem.addClearance("c", 0, 1, Target{0.0, v}).ok());
  const auto report = solve(problem);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("the clearances >= 0"), std::string::npos)
      << report.status().message();
}

}  // namespace
}  // namespace collido::constraints
