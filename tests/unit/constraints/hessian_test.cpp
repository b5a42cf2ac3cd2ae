// The constraint Hessians the KKT steps use: exact over translations, differenced otherwise,
// each against central differences of the analytic Jacobian.
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "constraints/hessian.h"
#include "unit/constraints/constraint_test_support.h"

namespace collido::constraints {
namespace {

using detail::ConstraintEvaluator;
using detail::ParameterLayout;

/// Σ w_k ∇²g_k by central differences of the evaluator's Jacobian over the free columns.
Eigen::MatrixXd differencedHessian(ConstraintEvaluator& evaluator, const ParameterLayout& layout,
                                   const Constraint& constraint, const Eigen::VectorXd& weights,
                                   const Eigen::VectorXd& x) {
  const int rows = ConstraintEvaluator::equationCount(constraint.kind);
  const auto gradient = [&](const Eigen::VectorXd& at) {
    evaluator.setParameters(at);
    Eigen::VectorXd residuals(rows);
    std::vector<Eigen::Triplet<double>> triplets;
    evaluator.evaluate(constraint, 0, residuals, &triplets);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(layout.size);
    for (const auto& t : triplets)
      g[t.col()] += weights[t.row()] * t.value();
    return g;
  };
  Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero(layout.size, layout.size);
  const double h = 1e-6;
  for (int column = 0; column < layout.size; ++column) {
    if (!layout.free[column]) continue;
    Eigen::VectorXd plus = x;
    Eigen::VectorXd minus = x;
    plus[column] += h * layout.scale[column];
    minus[column] -= h * layout.scale[column];
    hessian.col(column) = (gradient(plus) - gradient(minus)) / (2.0 * h);
  }
  for (int row = 0; row < layout.size; ++row) {
    if (!layout.free[row]) hessian.row(row).setZero();
  }
  evaluator.setParameters(x);
  return hessian;
}

void expectHessianMatches(Problem& problem) {
  const ParameterLayout layout(problem);
  ConstraintEvaluator evaluator(problem, layout);
  const Eigen::VectorXd x = detail::startParameters(problem, layout);
  for (const Constraint& constraint : problem.constraints()) {
    const int rows = ConstraintEvaluator::equationCount(constraint.kind);
    const Eigen::VectorXd weights = Eigen::VectorXd::LinSpaced(rows, 0.7, -1.3);
    std::vector<Eigen::Triplet<double>> triplets;
    evaluator.setParameters(x);
    detail::addWeightedHessian(evaluator, layout, constraint, weights.data(), x, triplets);
    Eigen::MatrixXd computed = Eigen::MatrixXd::Zero(layout.size, layout.size);
    for (const auto& t : triplets)
      computed(t.row(), t.col()) += t.value();
    const Eigen::MatrixXd expected = differencedHessian(evaluator, layout, constraint, weights, x);
    EXPECT_LT((computed - expected).cwiseAbs().maxCoeff(), 1e-5 * (1.0 + expected.norm()))
        << constraint.name << "\ncomputed\n"
        << computed << "\nexpected\n"
        << expected;
  }
}

/// Bodies a and b at random poses, with a distance, a point on a plane, a coincidence and an
/// angle between them.
Problem mixedProblem(std::mt19937_64& random, bool rotations_fixed) {
  Problem problem(1.3);
  const int a = problem.addBody("a", testing::randomPose(random, 2.0), 0.8).value();
  const int b = problem.addBody("b", testing::randomPose(random, 2.0), 1.6).value();
  if (rotations_fixed) {
    EXPECT_TRUE(problem.fixRotation(a).ok());
    EXPECT_TRUE(problem.fixRotation(b).ok());
  }
  const PointRef p{a, testing::randomVector(random, 1.0)};
  const PointRef q{b, testing::randomVector(random, 1.0)};
  EXPECT_TRUE(problem.addDistance("distance", p, q, Target{1.0}).ok());
  EXPECT_TRUE(
      problem.addDistance("to world", p, PointRef{kWorld, testing::kOrigin}, Target{1.0}).ok());
  EXPECT_TRUE(
      problem.addPointOnPlane("plane", p, Plane{q, DirectionRef{b, Eigen::Vector3d(1, 2, 3)}})
          .ok());
  EXPECT_TRUE(problem.addCoincident("coincident", p, q).ok());
  EXPECT_TRUE(problem
                  .addAngle("angle", DirectionRef{a, Eigen::Vector3d::UnitX()},
                            DirectionRef{b, Eigen::Vector3d::UnitY()}, Target{1.0})
                  .ok());
  return problem;
}

TEST(ConstraintHessians, ExactOverTranslationsMatchDifferences) {
  std::mt19937_64 random(31);
  for (int trial = 0; trial < 10; ++trial) {
    Problem problem = mixedProblem(random, true);
    expectHessianMatches(problem);
  }
}

TEST(ConstraintHessians, DifferencedWithRotationsMatchCentralDifferences) {
  std::mt19937_64 random(37);
  for (int trial = 0; trial < 10; ++trial) {
    Problem problem = mixedProblem(random, false);
    expectHessianMatches(problem);
  }
}

}  // namespace
}  // namespace collido::constraints
