#pragma once

#include <vector>

#include <Eigen/Core>

namespace collido::constraints::detail {

/// An equation whose gradient is a combination of earlier equations' gradients.
struct DependentRow {
  int row = 0;
  std::vector<int> combined_rows;  ///< the earlier independent rows it combines
  /// Its residual minus the same combination of theirs: zero for a redundant equation, not
  /// zero for one that conflicts with them (no step satisfies all of them to first order).
  double inconsistency = 0.0;
};

/// Walks the rows of a (normalised) Jacobian in order and returns those in the span of the
/// earlier independent ones (modified Gram–Schmidt, twice, so that ordering decides which
/// equation is blamed: the later one). Cost rows × rank × columns: it runs on failure only.
std::vector<DependentRow> findDependentRows(const Eigen::MatrixXd& jacobian,
                                            const Eigen::VectorXd& residuals,
                                            double relative_threshold = 1e-9);

}  // namespace collido::constraints::detail
