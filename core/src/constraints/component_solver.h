#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <collido/constraints/solve.h>

#include "components.h"
#include "equations.h"
#include "rank_analysis.h"

namespace collido::constraints::detail {

/// The least-change problem restricted to one component, in normalised parameters
/// z = (x − x_start) / scale: minimise ½|z|² subject to g(z) = 0.
class ComponentSolver {
 public:
  enum class Outcome { kConverged, kRankDeficient, kStepTooLarge, kNoProgress, kIterationLimit };

  ComponentSolver(const Problem& problem, const ParameterLayout& layout,
                  ConstraintEvaluator& evaluator, const Component& component, Eigen::VectorXd& x,
                  const SolveOptions& options);

  /// Solves from z = 0, approaching the answer in steps when Newton cannot go straight there.
  /// On failure the status names the constraints involved; x then holds the last iterate.
  Status solve(SolveReport& report);

  /// The normalised change z of the component's columns, once solved.
  const Eigen::VectorXd& change() const { return z_; }

 private:
  /// Newton iterations on g(z) − shift·g_start = 0 from z (updated in place).
  Outcome newton(Eigen::VectorXd& z, double shift, int& iterations);
  /// Appends I + Σ λ_j ∇²g_j over the component's columns, at the current x, as triplets
  /// (repeated entries add up).
  void addLagrangianHessian(const Eigen::VectorXd& multipliers,
                            std::vector<Eigen::Triplet<double>>& local);
  void evaluate(const Eigen::VectorXd& z, Eigen::VectorXd& residuals,
                Eigen::SparseMatrix<double>* jacobian);
  /// Names the dependent equations at z: a conflict error, a redundancy error, or (with
  /// allow_redundant) drops the redundant rows and returns ok.
  Status explainRankDeficiency(const Eigen::VectorXd& z, double shift, SolveReport& report);
  /// Names the equations furthest from the full edit at z, the last point reached.
  Status explainFailure(const Eigen::VectorXd& z, double reached);
  std::string constraintName(int row) const;

  const Problem& problem_;
  const ParameterLayout& layout_;
  ConstraintEvaluator& evaluator_;
  const Component& component_;
  Eigen::VectorXd& x_;
  Eigen::VectorXd x_start_;
  SolveOptions options_;
  std::vector<int> global_to_local_;   ///< global column → component column, or −1
  std::vector<int> row_constraint_;    ///< row → constraint index
  std::vector<int> constraint_row0_;   ///< per component constraint, its first row
  std::vector<int> active_rows_;       ///< rows in the solve (redundant ones dropped)
  std::vector<int> rotation_columns_;  ///< component columns that are rotation-vector entries
  Eigen::VectorXd start_residuals_;
  Eigen::VectorXd z_;
};

}  // namespace collido::constraints::detail
