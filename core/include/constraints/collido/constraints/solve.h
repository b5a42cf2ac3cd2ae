#pragma once

#include <string>
#include <vector>

#include <collido/constraints/problem.h>
#include <collido/status.h>

namespace collido::constraints {

/// Options of solve().
struct SolveOptions {
  /// Converged when every equation's residual is below tolerance × length_scale (angles: below
  /// tolerance) and the last Newton step changed no normalised parameter by more than tolerance.
  double tolerance = 1e-12;
  int max_iterations = 50;  ///< Newton iterations per step of an edit
  /// An edit too large for Newton from the start is approached in steps (the residuals at the
  /// start scaled down to zero); a failed step is halved, at most this many times in a row.
  int max_step_halvings = 12;
  /// Redundant but consistent equations (e.g. a constraint stated twice) are an error unless
  /// allowed, in which case the dependent ones are dropped.
  bool allow_redundant = false;
};

/// What solve() did.
struct SolveReport {
  int components = 0;   ///< independent groups of constraints and parameters solved apart
  int equations = 0;    ///< scalar equations over all components
  int parameters = 0;   ///< free parameters over all components (fixed ones eliminated)
  int iterations = 0;   ///< Newton iterations, all components and steps
  int edit_steps = 0;   ///< steps an edit took (1 when Newton went straight there)
  double change = 0.0;  ///< the normalised change √Σ(Δx_i / scale_i)², the quantity minimised
  double max_residual = 0.0;
  std::vector<std::string> dropped_redundant;  ///< with allow_redundant: equations dropped
};

/// Solves the problem for the parameters that change least: minimum Σ (Δx_i / scale_i)² over
/// the free parameters, subject to every constraint (Lagrange multipliers; Newton iterations on
/// the KKT conditions with a sparse factorisation). On failure the problem keeps the state it
/// started with and the status names the constraints that conflict or are redundant.
Result<SolveReport> solve(Problem& problem, const SolveOptions& options = {});

}  // namespace collido::constraints
