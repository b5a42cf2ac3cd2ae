#include "hessian.h"

#include <algorithm>

#include "components.h"

namespace collido::constraints::detail {
namespace {

/// Step of the central differences, in normalised parameters (gradient error ~h², rounding
/// ~1e-16/h: both near 1e-10 of the Hessian, which only steers the iteration).
constexpr double kStep = 1e-5;

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
  const auto apply = [&](int column, const Eigen::VectorXd& at) {
    if (column < 6 * layout.body_count) {
      evaluator.setBody(column / 6, at);
    } else {
      evaluator.setVariable(column - 6 * layout.body_count, at);
    }
  };
  Eigen::MatrixXd hessian(size, size);
  Eigen::VectorXd moved = x;
  for (int i = 0; i < size; ++i) {
    const int column = columns[i];
    const double delta = kStep * layout.scale[column];
    moved[column] = x[column] + delta;
    apply(column, moved);
    const Eigen::VectorXd up = gradient();
    moved[column] = x[column] - delta;
    apply(column, moved);
    const Eigen::VectorXd down = gradient();
    moved[column] = x[column];
    apply(column, moved);
    hessian.col(i) = (up - down) / (2.0 * kStep);
  }
  for (int i = 0; i < size; ++i) {
    for (int j = 0; j < size; ++j) {
      const double value = 0.5 * (hessian(i, j) + hessian(j, i));
      if (value != 0.0) out.emplace_back(columns[i], columns[j], value);
    }
  }
}

}  // namespace collido::constraints::detail
