// The least-change property: the solver's answer against an independent dense reference solve
// (full Newton on the KKT conditions, the Lagrangian's Hessian by central differences, dense
// LU), and the second-order condition that makes it a minimum and not a saddle.
#include <memory>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <collido/constraints/solve.h>

#include "constraints/equations.h"
#include "unit/constraints/constraint_test_support.h"

namespace collido::constraints {
namespace {

using detail::ConstraintEvaluator;
using detail::ParameterLayout;

/// The problem's equations over its free parameters in normalised coordinates z.
class DenseSystem {
 public:
  explicit DenseSystem(const Problem& problem)
      : problem_(problem),
        layout_(problem),
        evaluator_(problem, layout_),
        start_(detail::startParameters(problem, layout_)) {
    for (int column = 0; column < layout_.size; ++column) {
      if (layout_.free[column]) free_.push_back(column);
    }
    for (const Constraint& c : problem.constraints()) {
      rows_ += ConstraintEvaluator::equationCount(c.kind);
    }
  }

  int parameters() const { return static_cast<int>(free_.size()); }
  int equations() const { return rows_; }

  void evaluate(const Eigen::VectorXd& z, Eigen::VectorXd& g, Eigen::MatrixXd& jacobian) {
    Eigen::VectorXd x = start_;
    for (int i = 0; i < parameters(); ++i)
      x[free_[i]] += layout_.scale[free_[i]] * z[i];
    evaluator_.setParameters(x);
    g.resize(rows_);
    std::vector<Eigen::Triplet<double>> triplets;
    int row = 0;
    for (const Constraint& c : problem_.constraints()) {
      evaluator_.evaluate(c, row, g, &triplets);
      row += ConstraintEvaluator::equationCount(c.kind);
    }
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(rows_, layout_.size);
    for (const auto& t : triplets)
      full(t.row(), t.col()) += t.value();
    jacobian.resize(rows_, parameters());
    for (int i = 0; i < parameters(); ++i)
      jacobian.col(i) = full.col(free_[i]);
  }

  /// The KKT residual F(z, λ) = [z + Jᵀλ; g].
  Eigen::VectorXd kkt(const Eigen::VectorXd& unknowns) {
    const Eigen::VectorXd z = unknowns.head(parameters());
    const Eigen::VectorXd lambda = unknowns.tail(rows_);
    Eigen::VectorXd g;
    Eigen::MatrixXd jacobian;
    evaluate(z, g, jacobian);
    Eigen::VectorXd f(parameters() + rows_);
    f << z + jacobian.transpose() * lambda, g;
    return f;
  }

  /// Full Newton on F from (z = start, λ = 0), with F's Jacobian by central differences.
  Eigen::VectorXd referenceSolve(const Eigen::VectorXd& start) {
    const int size = parameters() + rows_;
    Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(size);
    unknowns.head(parameters()) = start;
    for (int iteration = 0; iteration < 30; ++iteration) {
      const Eigen::VectorXd f = kkt(unknowns);
      if (f.cwiseAbs().maxCoeff() < 1e-14 || !(f.cwiseAbs().maxCoeff() < 1e3)) break;
      Eigen::MatrixXd jacobian(size, size);
      for (int k = 0; k < size; ++k) {
        Eigen::VectorXd plus = unknowns;
        Eigen::VectorXd minus = unknowns;
        plus[k] += 1e-6;
        minus[k] -= 1e-6;
        jacobian.col(k) = (kkt(plus) - kkt(minus)) / 2e-6;
      }
      unknowns -= jacobian.fullPivLu().solve(f);
    }
    return unknowns;
  }

  /// The smallest eigenvalue of the Lagrangian's Hessian projected onto the constraints'
  /// tangent space (positive at a strict minimum of the change).
  double reducedHessianMinimum(const Eigen::VectorXd& unknowns) {
    const int n = parameters();
    const auto gradient = [&](const Eigen::VectorXd& z) {
      Eigen::VectorXd full(n + rows_);
      full << z, unknowns.tail(rows_);
      return Eigen::VectorXd(kkt(full).head(n));
    };
    Eigen::MatrixXd hessian(n, n);
    for (int k = 0; k < n; ++k) {
      Eigen::VectorXd plus = unknowns.head(n);
      Eigen::VectorXd minus = unknowns.head(n);
      plus[k] += 1e-6;
      minus[k] -= 1e-6;
      hessian.col(k) = (gradient(plus) - gradient(minus)) / 2e-6;
    }
    Eigen::VectorXd g;
    Eigen::MatrixXd jacobian;
    evaluate(unknowns.head(n), g, jacobian);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(jacobian);
    const Eigen::MatrixXd tangent = lu.kernel();
    const Eigen::MatrixXd reduced =
        tangent.transpose() * 0.5 * (hessian + hessian.transpose()) * tangent;
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(reduced).eigenvalues().minCoeff();
  }

  /// The normalised change between the start and the problem's current (solved) state.
  Eigen::VectorXd changeOf(const Problem& solved) const {
    Eigen::VectorXd z(parameters());
    for (int i = 0; i < parameters(); ++i) {
      const int column = free_[i];
      if (column < 6 * layout_.body_count) {
        const int body = column / 6;
        const int k = column % 6;
        const Pose& before = problem_.bodies()[body].pose;
        const Pose& after = solved.bodies()[body].pose;
        if (k < 3) {
          z[i] = (after.translation()[k] - before.translation()[k]) / layout_.scale[column];
        } else {
          const Eigen::AngleAxisd turn(before.linear().transpose() * after.linear());
          z[i] = (turn.angle() * turn.axis())[k - 3] / layout_.scale[column];
        }
      } else {
        const int variable = column - 6 * layout_.body_count;
        z[i] = (solved.variables()[variable].value - problem_.variables()[variable].value) /
               layout_.scale[column];
      }
    }
    return z;
  }

 private:
  const Problem& problem_;
  ParameterLayout layout_;
  ConstraintEvaluator evaluator_;
  Eigen::VectorXd start_;
  std::vector<int> free_;
  int rows_ = 0;
};

/// A docking-like problem: three free bodies and a fixed base, each body's start pose nudged off
/// a configuration where every constraint holds.
Problem nudgedAssembly(std::mt19937_64& random, double nudge) {
  Problem problem(2.0);
  const auto nudged = [&](Pose pose) {
    const Eigen::Vector3d axis = testing::randomVector(random, 1.0).normalized();
    pose.linear() = pose.linear() * Eigen::AngleAxisd(nudge, axis).toRotationMatrix();
    pose.translation() += testing::randomVector(random, nudge);
    return pose;
  };
  Pose base = Pose::Identity();
  Pose module = Pose::Identity();
  module.translation() = Eigen::Vector3d(0.0, 0.0, 3.0);
  // The panel folded 0.3 rad about its hinge (along x); the arm, its origin held in a plane
  // across x, grips the panel's point (-0.5, 0.5, 0). (With the arm's height fixed as well the
  // grip would repeat the fold: the rank analysis names that set redundant.)
  Pose panel = Pose::Identity();
  panel.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  panel.translation() = Eigen::Vector3d(-1.0, 2.0, 0.0);
  const Eigen::Vector3d grip = panel * Eigen::Vector3d(-0.5, 0.5, 0.0);
  Pose arm = Pose::Identity();
  arm.translation() = Eigen::Vector3d(grip.x() - 0.5, grip.y(), 1.0);
  const Eigen::Vector3d arm_grip(0.5, 0.0, grip.z() - 1.0);
  const int b = problem.addBody("base", base, 2.0).value();
  const int m = problem.addBody("module", nudged(module), 1.5).value();
  const int a = problem.addBody("arm", nudged(arm), 0.8).value();
  const int p = problem.addBody("panel", nudged(panel), 1.2).value();
  const int gap = problem.addVariable("gap", 1.0, 0.5).value();
  EXPECT_TRUE(problem.fixBody(b).ok());
  const Eigen::Vector3d z_axis = Eigen::Vector3d::UnitZ();
  EXPECT_TRUE(problem
                  .addCoaxial("docking axis", Axis{PointRef{b, {0, 0, 1}}, DirectionRef{b, z_axis}},
                              Axis{PointRef{m, {0, 0, -1}}, DirectionRef{m, z_axis}})
                  .ok());
  EXPECT_TRUE(problem
                  .addDistance("docking gap", PointRef{b, {0, 0, 1}}, PointRef{m, {0, 0, -1}},
                               Target{0.0, gap})
                  .ok());
  EXPECT_TRUE(
      problem
          .addPointOnPlane("arm on rail plane", PointRef{a, {0, 0, 0}},
                           Plane{PointRef{b, arm.translation()}, DirectionRef{b, {1, 0, 0}}})
          .ok());
  EXPECT_TRUE(
      problem.addPerpendicular("arm upright", DirectionRef{a, {1, 0, 0}}, DirectionRef{b, z_axis})
          .ok());
  EXPECT_TRUE(problem
                  .addPointOnLine("panel hinge", PointRef{p, {1, 0, 0}},
                                  Axis{PointRef{b, {0, 2, 0}}, DirectionRef{b, {1, 0, 0}}})
                  .ok());
  EXPECT_TRUE(problem
                  .addAngle("panel fold", DirectionRef{p, {0, 1, 0}}, DirectionRef{b, {0, 1, 0}},
                            Target{0.3})
                  .ok());
  EXPECT_TRUE(problem
                  .addParallel("panel beside module", DirectionRef{p, {1, 0, 0}},
                               DirectionRef{m, {1, 0, 0}})
                  .ok());
  EXPECT_TRUE(
      problem.addCoincident("arm grips panel", PointRef{a, arm_grip}, PointRef{p, {-0.5, 0.5, 0}})
          .ok());
  return problem;
}

TEST(LeastChange, EqualsTheDenseReferenceSolveOnNudgedAssemblies) {
  std::mt19937_64 random(20261124);
  int solved = 0;
  for (int trial = 0; trial < 10; ++trial) {
    Problem problem = nudgedAssembly(random, 0.01 + 0.01 * trial);
    const Problem start = problem;
    DenseSystem reference(start);
    // The constraints are not convex (parallel or opposite, angles both ways): several local
    // minima exist. The reference is the least change among the local minima that full Newton
    // reaches from the start and from 8 random points around it.
    std::normal_distribution<double> normal(0.0, 0.3);
    Eigen::VectorXd expected;
    for (int attempt = 0; attempt <= 8; ++attempt) {
      Eigen::VectorXd from = Eigen::VectorXd::Zero(reference.parameters());
      if (attempt > 0) {
        for (int i = 0; i < from.size(); ++i)
          from[i] = normal(random);
      }
      const Eigen::VectorXd found = reference.referenceSolve(from);
      if (reference.kkt(found).cwiseAbs().maxCoeff() > 1e-12 ||
          reference.reducedHessianMinimum(found) <= 0.0) {
        continue;
      }
      const int n = reference.parameters();
      if (expected.size() == 0 || found.head(n).norm() < expected.head(n).norm()) expected = found;
    }
    if (expected.size() == 0) continue;
    const auto report = solve(problem);
    ASSERT_TRUE(report.ok()) << "trial " << trial << ": " << report.status().message();
    const Eigen::VectorXd z = reference.changeOf(problem);
    const Eigen::VectorXd expected_z = expected.head(reference.parameters());
    EXPECT_LE((z - expected_z).norm(), 1e-9 * expected_z.norm()) << "trial " << trial;
    EXPECT_NEAR(report.value().change, expected_z.norm(), 1e-9 * expected_z.norm());
    ++solved;
  }
  EXPECT_GE(solved, 8);
}

TEST(LeastChange, FartherEditsEndAtTheStrictLocalMinimumNewtonReachesFromTheStart) {
  // Farther from the manifold other local minima come close (the constraints are curved). The
  // answer is a strict local minimum (KKT conditions to 1e-12, reduced Hessian positive
  // definite), the one full Newton from the start reaches too, unless Newton's undamped first
  // steps jump to a farther basin.
  std::mt19937_64 random(99);
  int compared = 0;
  int same = 0;
  for (int trial = 0; trial < 10; ++trial) {
    Problem problem = nudgedAssembly(random, 0.1 + 0.03 * trial);
    const Problem start = problem;
    DenseSystem reference(start);
    const auto report = solve(problem);
    ASSERT_TRUE(report.ok()) << "trial " << trial << ": " << report.status().message();
    const Eigen::VectorXd z = reference.changeOf(problem);
    Eigen::VectorXd g;
    Eigen::MatrixXd jacobian;
    reference.evaluate(z, g, jacobian);
    const Eigen::VectorXd lambda = jacobian.transpose().completeOrthogonalDecomposition().solve(-z);
    Eigen::VectorXd ours(z.size() + lambda.size());
    ours << z, lambda;
    EXPECT_LT(reference.kkt(ours).cwiseAbs().maxCoeff(), 1e-12) << "trial " << trial;
    EXPECT_GT(reference.reducedHessianMinimum(ours), 0.0) << "trial " << trial;
    const Eigen::VectorXd newton = reference.referenceSolve(Eigen::VectorXd::Zero(z.size()));
    if (reference.kkt(newton).cwiseAbs().maxCoeff() > 1e-12) continue;
    const Eigen::VectorXd newton_z = newton.head(z.size());
    if ((z - newton_z).norm() <= 1e-9 * z.norm()) {
      ++same;
    } else {
      // Undamped Newton jumped to another basin; ours must then be the smaller change.
      EXPECT_LT(z.norm(), newton_z.norm()) << "trial " << trial;
    }
    ++compared;
  }
  EXPECT_GE(compared, 8);
  EXPECT_GE(same, 8);
}

TEST(LeastChange, NoOtherFeasiblePointNearbyChangesLess) {
  std::mt19937_64 random(7);
  Problem problem = nudgedAssembly(random, 0.02);
  const Problem start = problem;
  ASSERT_TRUE(solve(problem).ok());
  DenseSystem system(start);
  const Eigen::VectorXd z = system.changeOf(problem);
  // Walk along the constraint manifold from the answer (tangent step, then Newton back onto
  // it) in random directions: the change never gets smaller.
  Eigen::VectorXd g;
  Eigen::MatrixXd jacobian;
  system.evaluate(z, g, jacobian);
  const Eigen::MatrixXd tangent = Eigen::FullPivLU<Eigen::MatrixXd>(jacobian).kernel();
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::VectorXd coefficients = Eigen::VectorXd::Random(tangent.cols());
    Eigen::VectorXd moved = z + 1e-3 * tangent * coefficients.normalized();
    for (int k = 0; k < 20; ++k) {
      system.evaluate(moved, g, jacobian);
      moved -= jacobian.completeOrthogonalDecomposition().solve(g);
    }
    system.evaluate(moved, g, jacobian);
    ASSERT_LT(g.cwiseAbs().maxCoeff(), 1e-13);
    EXPECT_GT(moved.norm(), z.norm());
  }
}

TEST(LeastChange, ClearanceThroughADistanceQueryEqualsTheDenseReferenceSolve) {
  // Balls off their bodies' origins, so the least change turns as well as moves them; a plane
  // holds one body's point, the clearance is set against a fixed base and between the two.
  // (Not contact: at a clearance of 0 the direction between the closest points is rounding,
  // and the least change is defined only to that precision.)
  std::mt19937_64 random(20261125);
  for (int trial = 0; trial < 6; ++trial) {
    Problem problem(1.0);
    const int base = problem.addBody("base", Pose::Identity(), 1.0).value();
    Pose first = testing::randomPose(random, 0.2);
    first.translation() += Eigen::Vector3d(1.6, 0.0, 0.0);
    Pose second = testing::randomPose(random, 0.2);
    second.translation() += Eigen::Vector3d(0.0, 1.7, 0.0);
    const int a = problem.addBody("a", first, 0.6).value();
    const int b = problem.addBody("b", second, 0.8).value();
    ASSERT_TRUE(problem.fixBody(base).ok());
    problem.setSeparationQuery(std::make_shared<testing::BallSeparation>(
        std::vector<testing::BallSeparation::Ball>{{testing::kOrigin, 0.5},
                                                   {Eigen::Vector3d(0.4, 0.1, 0.0), 0.3},
                                                   {Eigen::Vector3d(0.0, 0.3, 0.5), 0.4}}));
    ASSERT_TRUE(problem.addClearance("a to base", base, a, Target{0.05 + 0.02 * trial}).ok());
    ASSERT_TRUE(problem.addClearance("b to base", base, b, Target{0.01}).ok());
    ASSERT_TRUE(problem.addClearance("a to b", a, b, Target{0.3}).ok());
    ASSERT_TRUE(problem
                    .addPointOnPlane("a level", PointRef{a, Eigen::Vector3d(0.0, 0.0, 0.2)},
                                     Plane{PointRef{kWorld, testing::kOrigin},
                                           DirectionRef{kWorld, Eigen::Vector3d::UnitZ()}})
                    .ok());
    const Problem start = problem;
    DenseSystem reference(start);
    const Eigen::VectorXd expected =
        reference.referenceSolve(Eigen::VectorXd::Zero(reference.parameters()));
    ASSERT_LT(reference.kkt(expected).cwiseAbs().maxCoeff(), 1e-12) << "trial " << trial;
    ASSERT_GT(reference.reducedHessianMinimum(expected), 0.0) << "trial " << trial;
    const auto report = solve(problem);
    ASSERT_TRUE(report.ok()) << "trial " << trial << ": " << report.status().message();
    const Eigen::VectorXd z = reference.changeOf(problem);
    const Eigen::VectorXd expected_z = expected.head(reference.parameters());
    EXPECT_LE((z - expected_z).norm(), 1e-9 * expected_z.norm()) << "trial " << trial;
  }
}

}  // namespace
}  // namespace collido::constraints
