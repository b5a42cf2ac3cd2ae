#include <collido/constraints/solve.h>

#include <cmath>
#include <vector>

#include "angle_range.h"
#include "component_solver.h"
#include "components.h"
#include "equations.h"
#include "format_number.h"
#include "rotation.h"

namespace collido::constraints {
namespace {

Status checkOptions(const SolveOptions& options) {
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance)) {
    return Status(StatusCode::kInvalidArgument, "solve: the tolerance must be positive");
  }
  if (options.max_iterations < 1 || options.max_step_halvings < 0) {
    return Status(StatusCode::kInvalidArgument,
                  "solve: max_iterations must be at least 1 and max_step_halvings not negative");
  }
  return {};
}

/// Constraints on fixed objects only: nothing can move, so they hold already or they conflict.
Status checkFrozen(const Problem& problem, const std::vector<int>& frozen,
                   const detail::ConstraintEvaluator& evaluator, double tolerance) {
  for (int c : frozen) {
    const Constraint& constraint = problem.constraints()[c];
    Eigen::VectorXd residuals(detail::ConstraintEvaluator::equationCount(constraint.kind));
    evaluator.evaluate(constraint, 0, residuals, nullptr);
    if (!(residuals.cwiseAbs().maxCoeff() <= tolerance)) {  // NaN: a failed distance query
      return Status(StatusCode::kInvalidArgument,
                    "constraint '" + constraint.name +
                        "' involves only fixed objects and values (or one body alone), and "
                        "does not hold (residual " +
                        detail::formatNumber(residuals.cwiseAbs().maxCoeff()) + ")");
    }
  }
  return {};
}

/// A variable that sets an angle must stay inside (0, π), one that sets a distance above 0: at
/// the edges the equations lose their meaning (cos is even; a zero distance has no direction).
/// `values` holds each variable's value, before the solve or at its answer.
Status checkVariableTargets(const Problem& problem, const std::vector<double>& values,
                            const char* when) {
  for (const Constraint& c : problem.constraints()) {
    if (c.target.variable < 0) continue;
    const double value = values[c.target.variable];
    const bool angle = c.kind == ConstraintKind::kAngle;
    const bool clearance = c.kind == ConstraintKind::kClearance;
    const bool in_range = angle       ? detail::angleTargetInRange(value)
                          : clearance ? value >= 0.0
                                      : value > 0.0;
    if (!in_range) {
      return Status(StatusCode::kInvalidArgument, "constraint '" + c.name + "': its variable '" +
                                                      problem.variables()[c.target.variable].name +
                                                      "' is " + detail::formatNumber(value) + " " +
                                                      when + ", outside " +
                                                      (angle       ? "(0, pi) radians"
                                                       : clearance ? "the clearances >= 0"
                                                                   : "the positive distances"));
    }
  }
  return {};
}

/// Clearance constraints measure through the problem's separation query.
Status checkSeparationQuery(const Problem& problem) {
  if (problem.separationQuery() != nullptr) return {};
  for (const Constraint& c : problem.constraints()) {
    if (c.kind == ConstraintKind::kClearance) {
      return Status(StatusCode::kInvalidArgument,
                    "constraint '" + c.name +
                        "': a clearance needs a distance query (Problem::setSeparationQuery)");
    }
  }
  return {};
}

}  // namespace

Result<SolveReport> solve(Problem& problem, const SolveOptions& options) {
  if (Status status = checkOptions(options); !status.ok()) return status;
  if (Status status = checkSeparationQuery(problem); !status.ok()) return status;
  std::vector<double> values;
  for (const Variable& variable : problem.variables())
    values.push_back(variable.value);
  if (Status status = checkVariableTargets(problem, values, "before the solve"); !status.ok()) {
    return status;
  }
  const detail::ParameterLayout layout(problem);
  detail::ConstraintEvaluator evaluator(problem, layout);
  Eigen::VectorXd x = detail::startParameters(problem, layout);
  std::vector<int> frozen;
  const std::vector<detail::Component> components = detail::findComponents(problem, layout, frozen);
  const Status frozen_status = checkFrozen(problem, frozen, evaluator, options.tolerance);
  if (!evaluator.queryFailure().ok()) return evaluator.queryFailure();
  if (!frozen_status.ok()) return frozen_status;
  SolveReport report;
  report.components = static_cast<int>(components.size());
  double change_squared = 0.0;
  std::vector<bool> moved_body(problem.bodies().size(), false);
  for (const detail::Component& component : components) {
    for (int body : component.bodies)
      moved_body[body] = true;
    detail::ComponentSolver solver(problem, layout, evaluator, component, x, options);
    // The problem is written only when every component solved: a failure leaves it untouched.
    Status status = solver.solve(report);
    // A failed distance query is the cause of whatever the iteration concluded after it.
    if (!evaluator.queryFailure().ok()) return evaluator.queryFailure();
    if (!status.ok()) return status;
    change_squared += solver.change().squaredNorm();
  }
  report.change = std::sqrt(change_squared);
  // The answer must keep every variable target meaningful; else the problem stays as it was.
  for (int v = 0; v < static_cast<int>(values.size()); ++v)
    values[v] = x[layout.variableColumn(v)];
  if (Status status = checkVariableTargets(problem, values, "at the answer"); !status.ok()) {
    return status;
  }
  // Only what a component solved is written: fixed and unconstrained poses stay bit for bit.
  for (int b = 0; b < layout.body_count; ++b) {
    if (!moved_body[b]) continue;
    Body& body = problem.mutableBodies()[b];
    const Eigen::Matrix3d rotation =
        body.pose.linear() * detail::expMap(x.segment<3>(layout.bodyColumn(b) + 3));
    // Re-orthonormalise: products of rotations drift by an ulp per solve.
    body.pose.linear() = Eigen::Quaterniond(rotation).normalized().toRotationMatrix();
    body.pose.translation() = x.segment<3>(layout.bodyColumn(b));
  }
  for (int v = 0; v < static_cast<int>(problem.variables().size()); ++v) {
    if (problem.variables()[v].fixed) continue;
    problem.mutableVariables()[v].value = x[layout.variableColumn(v)];
  }
  return report;
}

}  // namespace collido::constraints
