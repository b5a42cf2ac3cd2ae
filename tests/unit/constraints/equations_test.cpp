// Each constraint kind's residuals and derivatives: the Jacobian the solver uses against
// central differences of the residuals, at random poses away from the start (ω ≠ 0).
#include <memory>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "constraints/equations.h"
#include "unit/constraints/constraint_test_support.h"

namespace collido::constraints {
namespace {

using testing::kOrigin;

using detail::ConstraintEvaluator;
using detail::ParameterLayout;

struct KindCase {
  const char* name;
  ConstraintKind kind;
};

class EquationDerivatives : public ::testing::TestWithParam<KindCase> {};

Result<int> addOfKind(Problem& problem, ConstraintKind kind, std::mt19937_64& random,
                      int variable) {
  const PointRef p{0, testing::randomVector(random, 1.0)};
  const PointRef q{1, testing::randomVector(random, 1.0)};
  const DirectionRef d{0, testing::randomVector(random, 1.0)};
  const DirectionRef e{1, testing::randomVector(random, 1.0)};
  switch (kind) {
    case ConstraintKind::kCoincident:
      return problem.addCoincident("c", p, q);
    case ConstraintKind::kPointOnPlane:
      return problem.addPointOnPlane("c", p, Plane{q, e});
    case ConstraintKind::kPointOnLine:
      return problem.addPointOnLine("c", p, Axis{q, e});
    case ConstraintKind::kDistance:
      return problem.addDistance("c", p, q, Target{0.0, variable});
    case ConstraintKind::kAngle:
      return problem.addAngle("c", d, e, Target{0.0, variable});
    case ConstraintKind::kParallel:
      return problem.addParallel("c", d, e);
    case ConstraintKind::kPerpendicular:
      return problem.addPerpendicular("c", d, e);
    case ConstraintKind::kCoaxial:
      return problem.addCoaxial("c", Axis{p, d}, Axis{q, e});
    case ConstraintKind::kClearance:
      // Balls off their bodies' origins, so that turning a body moves its ball.
      problem.setSeparationQuery(std::make_shared<testing::BallSeparation>(
          std::vector<testing::BallSeparation::Ball>{{p.local, 0.3}, {q.local, 0.5}}));
      return problem.addClearance("c", 0, 1, Target{0.0, variable});
  }
  return Status(StatusCode::kInternal, "unknown kind");
}

TEST_P(EquationDerivatives, JacobianMatchesCentralDifferences) {
  std::mt19937_64 random(17);
  for (int trial = 0; trial < 20; ++trial) {
    Problem problem(2.5);
    ASSERT_TRUE(problem.addBody("a", testing::randomPose(random, 3.0), 1.7).ok());
    ASSERT_TRUE(problem.addBody("b", testing::randomPose(random, 3.0), 0.4).ok());
    ASSERT_TRUE(problem.addVariable("v", 1.1, 0.3).ok());
    ASSERT_TRUE(addOfKind(problem, GetParam().kind, random, 0).ok());
    const ParameterLayout layout(problem);
    ConstraintEvaluator evaluator(problem, layout);
    const Constraint& constraint = problem.constraints()[0];
    const int rows = ConstraintEvaluator::equationCount(constraint.kind);

    // Away from the start: rotation vectors up to 1 rad, moved translations and variable.
    const Eigen::VectorXd start = detail::startParameters(problem, layout);
    Eigen::VectorXd z(layout.size);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (int i = 0; i < layout.size; ++i)
      z[i] = uniform(random) * 0.5;
    const auto parameters = [&](const Eigen::VectorXd& normalised) {
      return Eigen::VectorXd(start + layout.scale.cwiseProduct(normalised));
    };
    evaluator.setParameters(parameters(z));
    Eigen::VectorXd residuals(rows);
    std::vector<Eigen::Triplet<double>> triplets;
    evaluator.evaluate(constraint, 0, residuals, &triplets);
    Eigen::MatrixXd analytic = Eigen::MatrixXd::Zero(rows, layout.size);
    for (const auto& t : triplets)
      analytic(t.row(), t.col()) += t.value();

    const double h = 1e-6;
    for (int column = 0; column < layout.size; ++column) {
      Eigen::VectorXd plus = z;
      Eigen::VectorXd minus = z;
      plus[column] += h;
      minus[column] -= h;
      Eigen::VectorXd up(rows);
      Eigen::VectorXd down(rows);
      evaluator.setParameters(parameters(plus));
      evaluator.evaluate(constraint, 0, up, nullptr);
      evaluator.setParameters(parameters(minus));
      evaluator.evaluate(constraint, 0, down, nullptr);
      const Eigen::VectorXd numeric = (up - down) / (2.0 * h);
      for (int row = 0; row < rows; ++row) {
        EXPECT_NEAR(analytic(row, column), numeric[row], 1e-6 * (1.0 + std::abs(numeric[row])))
            << GetParam().name << " trial " << trial << " row " << row << " column " << column;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    EveryKind, EquationDerivatives,
    ::testing::Values(KindCase{"coincident", ConstraintKind::kCoincident},
                      KindCase{"point_on_plane", ConstraintKind::kPointOnPlane},
                      KindCase{"point_on_line", ConstraintKind::kPointOnLine},
                      KindCase{"distance", ConstraintKind::kDistance},
                      KindCase{"angle", ConstraintKind::kAngle},
                      KindCase{"parallel", ConstraintKind::kParallel},
                      KindCase{"perpendicular", ConstraintKind::kPerpendicular},
                      KindCase{"coaxial", ConstraintKind::kCoaxial},
                      KindCase{"clearance", ConstraintKind::kClearance}),
    [](const ::testing::TestParamInfo<KindCase>& param) { return std::string(param.param.name); });

TEST(EquationResiduals, VanishWhereEachConstraintHolds) {
  Problem problem(1.0);
  Pose a = Pose::Identity();
  Pose b = Pose::Identity();
  b.translation() = Eigen::Vector3d(2.0, 0.0, 0.0);
  b.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  ASSERT_TRUE(problem.addBody("a", a, 1.0).ok());
  ASSERT_TRUE(problem.addBody("b", b, 1.0).ok());
  const Eigen::Vector3d b_origin_in_a(2.0, 0.0, 0.0);
  ASSERT_TRUE(
      problem.addCoincident("coincident", PointRef{0, b_origin_in_a}, PointRef{1, kOrigin}).ok());
  ASSERT_TRUE(problem
                  .addPointOnPlane("on_plane", PointRef{1, {0.0, 0.0, 0.0}},
                                   Plane{PointRef{0, {5.0, 7.0, 0.0}}, DirectionRef{0, {0, 0, 1}}})
                  .ok());
  ASSERT_TRUE(
      problem
          .addPointOnLine("on_line", PointRef{1, kOrigin},
                          Axis{PointRef{kWorld, {-3.0, 0.0, 0.0}}, DirectionRef{kWorld, {1, 0, 0}}})
          .ok());
  ASSERT_TRUE(
      problem.addDistance("distance", PointRef{0, kOrigin}, PointRef{1, kOrigin}, Target{2.0})
          .ok());
  ASSERT_TRUE(
      problem.addAngle("angle", DirectionRef{0, {1, 0, 0}}, DirectionRef{1, {1, 0, 0}}, Target{0.5})
          .ok());
  ASSERT_TRUE(
      problem.addParallel("parallel", DirectionRef{0, {0, 0, 1}}, DirectionRef{1, {0, 0, -1}})
          .ok());
  ASSERT_TRUE(
      problem
          .addPerpendicular("perpendicular", DirectionRef{0, {0, 0, 1}}, DirectionRef{1, {0, 1, 0}})
          .ok());
  ASSERT_TRUE(problem
                  .addCoaxial("coaxial",
                              Axis{PointRef{0, {7.0, 0.0, 0.0}}, DirectionRef{0, {1, 0, 0}}},
                              Axis{PointRef{kWorld, kOrigin}, DirectionRef{kWorld, {-2, 0, 0}}})
                  .ok());
  problem.setSeparationQuery(std::make_shared<testing::BallSeparation>(
      std::vector<testing::BallSeparation::Ball>{{kOrigin, 0.8}, {kOrigin, 0.7}}));
  ASSERT_TRUE(problem.addClearance("clearance", 0, 1, Target{0.5}).ok());
  const ParameterLayout layout(problem);
  const ConstraintEvaluator evaluator(problem, layout);
  for (const Constraint& constraint : problem.constraints()) {
    Eigen::VectorXd residuals(ConstraintEvaluator::equationCount(constraint.kind));
    evaluator.evaluate(constraint, 0, residuals, nullptr);
    EXPECT_LT(residuals.cwiseAbs().maxCoeff(), 1e-15) << constraint.name;
  }
}

}  // namespace
}  // namespace collido::constraints
