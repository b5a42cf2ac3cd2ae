#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "equations.h"

namespace collido::constraints::detail {

/// Adds Σ_k weights[k] ∇²g_k (the constraint's equations, with respect to the normalised
/// free parameters of the bodies and variable it refers to) as triplets over global columns.
/// Exact where those are translations only (most kinds are linear in them; the distance's is
/// known); otherwise by forward differences of the analytic gradient, per constraint over its
/// own ≤ 13 parameters:
/// Newton on the KKT conditions needs it (the identity Hessian alone converges linearly at
/// best, and not at all once the multipliers are large), and it only sets the convergence rate,
/// never the answer. The evaluator is left at `x`.
void addWeightedHessian(ConstraintEvaluator& evaluator, const ParameterLayout& layout,
                        const Constraint& constraint, const double* weights,
                        const Eigen::VectorXd& x, std::vector<Eigen::Triplet<double>>& out);

}  // namespace collido::constraints::detail
