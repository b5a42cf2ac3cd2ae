#include "rank_analysis.h"

#include <cmath>

namespace collido::constraints::detail {

std::vector<DependentRow> findDependentRows(const Eigen::MatrixXd& jacobian,
                                            const Eigen::VectorXd& residuals,
                                            double relative_threshold) {
  const int rows = static_cast<int>(jacobian.rows());
  const int columns = static_cast<int>(jacobian.cols());
  // basis.col(j) is orthonormal; basis_in_rows(:, j) writes it as a combination of the
  // independent rows (their order in `independent`).
  Eigen::MatrixXd basis(columns, 0);
  Eigen::MatrixXd basis_in_rows(0, 0);
  std::vector<int> independent;
  std::vector<DependentRow> dependent;
  const double largest = jacobian.rowwise().norm().maxCoeff();
  for (int row = 0; row < rows; ++row) {
    Eigen::VectorXd remainder = jacobian.row(row).transpose();
    const int rank = static_cast<int>(independent.size());
    Eigen::VectorXd projection = Eigen::VectorXd::Zero(rank);
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXd coefficients = basis.transpose() * remainder;
      remainder -= basis * coefficients;
      projection += coefficients;
    }
    const double norm = remainder.norm();
    // A zero row (e.g. a distance between coincident points) depends on nothing.
    if (norm <= relative_threshold * std::max(largest, 1e-300)) {
      DependentRow found;
      found.row = row;
      const Eigen::VectorXd combination = basis_in_rows.topRows(rank) * projection;
      double combined_residual = 0.0;
      for (int i = 0; i < rank; ++i) {
        if (std::abs(combination[i]) > 1e-9 * std::max(1.0, combination.cwiseAbs().maxCoeff())) {
          found.combined_rows.push_back(independent[i]);
          combined_residual += combination[i] * residuals[independent[i]];
        }
      }
      found.inconsistency = residuals[row] - combined_residual;
      dependent.push_back(std::move(found));
      continue;
    }
    // New basis vector q = (row − basis·projection) / norm, i.e. in rows:
    // q = (e_row − basis_in_rows·projection) / norm.
    basis.conservativeResize(Eigen::NoChange, rank + 1);
    basis.col(rank) = remainder / norm;
    Eigen::MatrixXd grown = Eigen::MatrixXd::Zero(rank + 1, rank + 1);
    grown.topLeftCorner(rank, rank) = basis_in_rows;
    grown.col(rank).head(rank) = -(basis_in_rows * projection) / norm;
    grown(rank, rank) = 1.0 / norm;
    basis_in_rows = std::move(grown);
    independent.push_back(row);
  }
  return dependent;
}

}  // namespace collido::constraints::detail
