#include "hessian.h"

#include <algorithm>

#include "components.h"

namespace collido::constraints::detail {
namespace {

/// Step of the forward differences, in normalised parameters (truncation ~h, rounding
/// ~1e-16/h: both near 1e-8 of the Hessian, which only steers the iteration; central
/// differences cost twice the evaluations and saved no iteration on the bench's chains).
constexpr double kStep = 1e-8;

}  // namespace

void addWeightedHessian(ConstraintEvaluator& evaluator, const ParameterLayout& layout,
                        const Constraint& constraint, const double* weights,
                        const Eigen::VectorXd& x, std::vector<Eigen::Triplet<double>>& out) {
  const ConstraintSupport support = supportOf(constraint);
  std::vector<int> columns;
  for (int body : support.bodies) {
    for (int k = 0; k < 6; ++k)
      columns.push_back(layout.bodyColumn(body) + k);
  }
  for (int variable : support.variables)
    columns.push_back(layout.variableColumn(variable));
  const int size = static_cast<int>(columns.size());
  const int rows = ConstraintEvaluator::equationCount(constraint.kind);
  Eigen::VectorXd residuals(rows);
  std::vector<Eigen::Triplet<double>> triplets;
  // The weighted gradient Σ_k w_k ∇g_k over `columns`, at the evaluator's current state.
  const auto gradient = [&] {
    triplets.clear();
    evaluator.evaluate(constraint, 0, residuals, &triplets);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(size);
    for (const auto& t : triplets) {
      const auto found = std::find(columns.begin(), columns.end(), t.col());
      if (found != columns.end()) g[found - columns.begin()] += weights[t.row()] * t.value();
    }
    return g;
  };
  // Moves one parameter by `delta` from x (delta 0 puts it back). Only the moved body's state
  // is recomputed, and a translation leaves its rotation as it is.
  const auto move = [&](int column, double delta) {
    if (column >= 6 * layout.body_count) {
      evaluator.setVariableValue(column - 6 * layout.body_count, x[column] + delta);
      return;
    }
    const int first = column - column % 6;
    Eigen::Vector3d translation = x.segment<3>(first);
    Eigen::Vector3d omega = x.segment<3>(first + 3);
    if (column % 6 < 3) {
      translation[column % 6] += delta;
      evaluator.setBodyTranslation(column / 6, translation);
    } else {
      omega[column % 6 - 3] += delta;
      evaluator.setBodyState(column / 6, translation, omega);
    }
  };
  Eigen::MatrixXd hessian(size, size);
  const Eigen::VectorXd here = gradient();
  for (int i = 0; i < size; ++i) {
    const int column = columns[i];
    move(column, kStep * layout.scale[column]);
    const Eigen::VectorXd up = gradient();
    move(column, 0.0);
    hessian.col(i) = (up - here) / kStep;
  }
  for (int i = 0; i < size; ++i) {
    for (int j = 0; j < size; ++j) {
      const double value = 0.5 * (hessian(i, j) + hessian(j, i));
      if (value != 0.0) out.emplace_back(columns[i], columns[j], value);
    }
  }
}

}  // namespace collido::constraints::detail
