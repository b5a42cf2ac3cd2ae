#include "component_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include "format_number.h"
#include "hessian.h"

namespace collido::constraints::detail {
namespace {

/// Pivots of J Jᵀ below this fraction of the largest: J's rows are dependent to about 3e-7, where
/// rounding alone leaves pivots near 1e-16 of the largest.
constexpr double kPivotRatio = 1e-13;
/// Below this residual Newton's full step is taken without a line search.
constexpr double kNewtonRegion = 1e-8;
/// A Newton step that turns a body by more than this (radians) has left the region where the
/// linearisation describes the rotation; the edit is then approached in smaller steps, so that
/// the solve follows the start continuously (a door opened from 0.2 to 3 rad turns 2.8 rad,
/// not −3.2 through an overshoot).
constexpr double kMaxTurnPerStep = 0.5;

}  // namespace

ComponentSolver::ComponentSolver(const Problem& problem, const ParameterLayout& layout,
                                 ConstraintEvaluator& evaluator, const Component& component,
                                 Eigen::VectorXd& x, const SolveOptions& options)
    : problem_(problem),
      layout_(layout),
      evaluator_(evaluator),
      component_(component),
      x_(x),
      x_start_(x),
      options_(options),
      global_to_local_(layout.size, -1) {
  for (int i = 0; i < static_cast<int>(component.columns.size()); ++i) {
    const int column = component.columns[i];
    global_to_local_[column] = i;
    if (column < 6 * layout.body_count && column % 6 >= 3) rotation_columns_.push_back(i);
  }
  int rows = 0;
  for (int c : component.constraints) {
    constraint_row0_.push_back(rows);
    const int count = ConstraintEvaluator::equationCount(problem.constraints()[c].kind);
    for (int k = 0; k < count; ++k)
      row_constraint_.push_back(c);
    rows += count;
  }
  for (int row = 0; row < rows; ++row)
    active_rows_.push_back(row);
  z_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(component.columns.size()));
  // Residuals cannot fall below the rounding of the coordinates they are computed from.
  double largest = 0.0;
  for (int column : component.columns)
    largest = std::max(largest, std::abs(x[column]));
  options_.tolerance = std::max(options_.tolerance, 16.0 * std::numeric_limits<double>::epsilon() *
                                                        largest / problem.lengthScale());
}

std::string ComponentSolver::constraintName(int row) const {
  return "'" + problem_.constraints()[row_constraint_[row]].name + "'";
}

void ComponentSolver::evaluate(const Eigen::VectorXd& z, Eigen::VectorXd& residuals,
                               Eigen::SparseMatrix<double>* jacobian) {
  for (int i = 0; i < static_cast<int>(component_.columns.size()); ++i) {
    const int column = component_.columns[i];
    x_[column] = x_start_[column] + layout_.scale[column] * z[i];
  }
  for (int body : component_.bodies)
    evaluator_.setBody(body, x_);
  for (int column : component_.columns) {
    if (column >= 6 * layout_.body_count) {
      evaluator_.setVariable(column - 6 * layout_.body_count, x_);
    }
  }
  Eigen::VectorXd all(static_cast<Eigen::Index>(row_constraint_.size()));
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t k = 0; k < component_.constraints.size(); ++k) {
    evaluator_.evaluate(problem_.constraints()[component_.constraints[k]], constraint_row0_[k], all,
                        jacobian != nullptr ? &triplets : nullptr);
  }
  residuals.resize(static_cast<Eigen::Index>(active_rows_.size()));
  std::vector<int> active_index(row_constraint_.size(), -1);
  for (int i = 0; i < static_cast<int>(active_rows_.size()); ++i) {
    residuals[i] = all[active_rows_[i]];
    active_index[active_rows_[i]] = i;
  }
  if (jacobian == nullptr) return;
  std::vector<Eigen::Triplet<double>> kept;
  kept.reserve(triplets.size());
  for (const auto& t : triplets) {
    const int row = active_index[t.row()];
    const int column = global_to_local_[t.col()];
    if (row >= 0 && column >= 0) kept.emplace_back(row, column, t.value());
  }
  jacobian->resize(static_cast<Eigen::Index>(active_rows_.size()),
                   static_cast<Eigen::Index>(component_.columns.size()));
  jacobian->setFromTriplets(kept.begin(), kept.end());
}

void ComponentSolver::addLagrangianHessian(const Eigen::VectorXd& multipliers,
                                           std::vector<Eigen::Triplet<double>>& local) {
  const int rows = static_cast<int>(row_constraint_.size());
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(rows);
  for (int i = 0; i < static_cast<int>(active_rows_.size()); ++i) {
    weights[active_rows_[i]] = multipliers[i];
  }
  std::vector<Eigen::Triplet<double>> global;
  for (std::size_t k = 0; k < component_.constraints.size(); ++k) {
    const double* w = weights.data() + constraint_row0_[k];
    const int count =
        ConstraintEvaluator::equationCount(problem_.constraints()[component_.constraints[k]].kind);
    if (Eigen::Map<const Eigen::VectorXd>(w, count).isZero(0.0)) continue;
    addWeightedHessian(evaluator_, layout_, problem_.constraints()[component_.constraints[k]], w,
                       x_, global);
  }
  const int n = static_cast<int>(component_.columns.size());
  local.reserve(local.size() + global.size() + static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    local.emplace_back(i, i, 1.0);  // ½|z|²
  for (const auto& t : global) {
    const int row = global_to_local_[t.row()];
    const int column = global_to_local_[t.col()];
    if (row >= 0 && column >= 0) local.emplace_back(row, column, t.value());
  }
}

ComponentSolver::Outcome ComponentSolver::newton(Eigen::VectorXd& z, double shift,
                                                 int& iterations) {
  Eigen::VectorXd residuals;
  Eigen::SparseMatrix<double> jacobian;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> normal_factorization;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>>
      symmetric_factorization;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> kkt_factorization;
  std::vector<int> kkt_outer;  // the pattern the factorisations were analysed for
  std::vector<int> kkt_inner;
  bool lu_analyzed = false;
  Eigen::VectorXd multipliers;  // λ of the last accepted step; empty until there is one
  double penalty = 1.0;
  const int n = static_cast<int>(z.size());
  for (int iteration = 0; iteration < options_.max_iterations; ++iteration) {
    ++iterations;
    evaluate(z, residuals, &jacobian);
    const int m = static_cast<int>(residuals.size());
    const Eigen::VectorXd target_residuals = residuals - shift * start_residuals_;
    Eigen::VectorXd step;
    Eigen::VectorXd next_multipliers;
    // Newton on the KKT conditions once multipliers are known: [H Jᵀ; J 0][Δz; λ] = −[z; g]
    // with H = I + Σ λ_j ∇²g_j. Kept only where it is a descent direction of the merit below.
    if (multipliers.size() == m && !multipliers.isZero(0.0)) {
      std::vector<Eigen::Triplet<double>> entries;
      addLagrangianHessian(multipliers, entries);
      for (int k = 0; k < jacobian.outerSize(); ++k) {
        for (Eigen::SparseMatrix<double>::InnerIterator it(jacobian, k); it; ++it) {
          entries.emplace_back(n + static_cast<int>(it.row()), static_cast<int>(it.col()),
                               it.value());
          entries.emplace_back(static_cast<int>(it.col()), n + static_cast<int>(it.row()),
                               it.value());
        }
      }
      // The constraint block gets −δ on its diagonal: the matrix is then quasi-definite where
      // H is positive definite on the constraints' null space, and a symmetric LDLᵀ (about a
      // third of the LU's work) factors it stably. Its inertia (n positive pivots, m negative)
      // confirms that case; refinement against the unshifted matrix removes δ's bias. Else LU.
      constexpr double kShift = 1e-10;
      for (int i = n; i < n + m; ++i)
        entries.emplace_back(i, i, -kShift);
      Eigen::SparseMatrix<double> shifted(n + m, n + m);
      shifted.setFromTriplets(entries.begin(), entries.end());
      Eigen::VectorXd right(n + m);
      right << -z, -target_residuals;
      const auto kktTimes = [&](const Eigen::VectorXd& x) {
        Eigen::VectorXd product = shifted * x;
        product.tail(m) += kShift * x.tail(m);
        return product;
      };
      // The orderings depend only on where the entries are, which rarely changes between
      // iterations: each is computed again only when the pattern did.
      const bool same_pattern =
          static_cast<std::size_t>(shifted.outerSize()) + 1 == kkt_outer.size() &&
          shifted.nonZeros() == static_cast<Eigen::Index>(kkt_inner.size()) &&
          std::equal(kkt_outer.begin(), kkt_outer.end(), shifted.outerIndexPtr()) &&
          std::equal(kkt_inner.begin(), kkt_inner.end(), shifted.innerIndexPtr());
      if (!same_pattern) {
        kkt_outer.assign(shifted.outerIndexPtr(),
                         shifted.outerIndexPtr() + shifted.outerSize() + 1);
        kkt_inner.assign(shifted.innerIndexPtr(), shifted.innerIndexPtr() + shifted.nonZeros());
        symmetric_factorization.analyzePattern(shifted);
        lu_analyzed = false;
      }
      Eigen::VectorXd solution;
      symmetric_factorization.factorize(shifted);
      if (symmetric_factorization.info() == Eigen::Success) {
        const Eigen::VectorXd pivots = symmetric_factorization.vectorD();
        if ((pivots.array() > 0.0).count() == n && (pivots.array() < 0.0).count() == m) {
          solution = symmetric_factorization.solve(right);
          for (int refinement = 0; refinement < 3; ++refinement)
            solution += symmetric_factorization.solve(right - kktTimes(solution));
          const double scale = std::max(1.0, right.cwiseAbs().maxCoeff());
          if (!((right - kktTimes(solution)).cwiseAbs().maxCoeff() <= 1e-13 * scale)) {
            solution.resize(0);
          }
        }
      }
      if (solution.size() == 0) {
        Eigen::SparseMatrix<double> kkt = shifted;
        for (int i = n; i < n + m; ++i)
          kkt.coeffRef(i, i) = 0.0;
        if (!lu_analyzed) {
          kkt_factorization.analyzePattern(kkt);
          lu_analyzed = true;
        }
        kkt_factorization.factorize(kkt);
        if (kkt_factorization.info() == Eigen::Success) solution = kkt_factorization.solve(right);
      }
      if (solution.size() == n + m) {
        const Eigen::VectorXd newton_step = solution.head(n);
        const Eigen::VectorXd newton_multipliers = solution.tail(m);
        const double newton_penalty =
            std::max(penalty, 2.0 * newton_multipliers.cwiseAbs().maxCoeff());
        const double slope = z.dot(newton_step) - newton_penalty * target_residuals.lpNorm<1>();
        if (solution.allFinite() && (slope < 0.0 || newton_step.isZero(0.0))) {
          step = newton_step;
          next_multipliers = newton_multipliers;
        }
      }
    }
    if (step.size() == 0) {
      // J Jᵀ: its pivots tell whether the equations are independent here (always checked on
      // an attempt's first iteration, which has no multipliers yet), and it gives the step with
      // the identity Hessian of ½|z|²: (J Jᵀ) λ = g − J z, new point −Jᵀ λ.
      const Eigen::SparseMatrix<double> normal = jacobian * jacobian.transpose();
      normal_factorization.compute(normal);
      const Eigen::VectorXd pivots = normal_factorization.info() == Eigen::Success
                                         ? Eigen::VectorXd(normal_factorization.vectorD())
                                         : Eigen::VectorXd::Zero(std::max(m, 1));
      if (pivots.size() > 0 && !(pivots.minCoeff() > kPivotRatio * pivots.cwiseAbs().maxCoeff())) {
        // Dependent at the attempt's start: the equations themselves. Later: the iteration ran
        // into a singular configuration, and a shorter step of the edit may avoid it.
        return iteration == 0 ? Outcome::kRankDeficient : Outcome::kNoProgress;
      }
      next_multipliers = normal_factorization.solve(target_residuals - jacobian * z);
      step = -(jacobian.transpose() * next_multipliers) - z;
    }
    const double residual_norm = target_residuals.cwiseAbs().maxCoeff();
    const double step_norm = step.cwiseAbs().maxCoeff();
    const double step_tolerance = std::max(options_.tolerance, 1e-11 * z.cwiseAbs().maxCoeff());
    if (residual_norm <= options_.tolerance && step_norm <= step_tolerance) {
      return Outcome::kConverged;
    }
    for (int column : rotation_columns_) {
      if (std::abs(step[column]) * layout_.scale[component_.columns[column]] > kMaxTurnPerStep) {
        return Outcome::kStepTooLarge;
      }
    }
    if (residual_norm < kNewtonRegion) {
      z += step;
      multipliers = next_multipliers;
      continue;
    }
    // Line search on the ℓ1 merit ½|z|² + μ‖g‖₁, with μ above the multipliers so that the
    // step is a descent direction.
    penalty = std::max(penalty, 2.0 * next_multipliers.cwiseAbs().maxCoeff());
    const auto merit = [&](const Eigen::VectorXd& point, const Eigen::VectorXd& g) {
      return 0.5 * point.squaredNorm() + penalty * g.lpNorm<1>();
    };
    const double merit_here = merit(z, target_residuals);
    const double slope = z.dot(step) - penalty * target_residuals.lpNorm<1>();
    double fraction = 1.0;
    bool accepted = false;
    Eigen::VectorXd trial_residuals;
    while (fraction > 1e-6) {
      const Eigen::VectorXd trial = z + fraction * step;
      evaluate(trial, trial_residuals, nullptr);
      trial_residuals -= shift * start_residuals_;
      if (merit(trial, trial_residuals) <= merit_here + 1e-4 * fraction * slope) {
        z = trial;
        accepted = true;
        break;
      }
      fraction *= 0.5;
    }
    if (!accepted) return Outcome::kNoProgress;
    multipliers = next_multipliers;
  }
  return Outcome::kIterationLimit;
}

Status ComponentSolver::solve(SolveReport& report) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(z_.size());
  evaluate(z, start_residuals_, nullptr);
  // The edit is the residual at the start; steps scale it down to zero: at fraction t the
  // equations are g(z) = (1 − t) g_start, which z = 0 meets at t = 0.
  double reached = 0.0;
  double step = 1.0;
  const double smallest_step = std::ldexp(1.0, -options_.max_step_halvings);
  int steps = 0;
  // Every attempt either advances by at least smallest_step or halves the step, so this bounds
  // the work even where successes and failures alternate.
  const int max_attempts = 4 * (options_.max_step_halvings + 1) * (1 << 10);
  for (int attempt = 0; reached < 1.0; ++attempt) {
    if (attempt == max_attempts) return explainFailure(z, reached);
    const double next = std::min(1.0, reached + step);
    Eigen::VectorXd trial = z;
    const Outcome outcome = newton(trial, 1.0 - next, report.iterations);
    if (outcome == Outcome::kConverged) {
      z = trial;
      reached = next;
      ++steps;
      step = std::min(1.0, 2.0 * step);
      continue;
    }
    if (outcome == Outcome::kRankDeficient) {
      if (Status status = explainRankDeficiency(trial, 1.0 - next, report); !status.ok()) {
        return status;
      }
      // Redundant rows dropped: start the residuals again without them.
      evaluate(Eigen::VectorXd::Zero(z.size()), start_residuals_, nullptr);
      continue;
    }
    step *= 0.5;
    if (step < smallest_step) return explainFailure(z, reached);
  }
  // Dropped redundant rows were judged at one configuration: they must hold at the answer too.
  if (active_rows_.size() != row_constraint_.size()) {
    const std::vector<int> kept = active_rows_;
    active_rows_.resize(row_constraint_.size());
    for (int row = 0; row < static_cast<int>(row_constraint_.size()); ++row)
      active_rows_[row] = row;
    Eigen::VectorXd all;
    evaluate(z, all, nullptr);
    for (int row = 0; row < all.size(); ++row) {
      if (std::abs(all[row]) > 1e3 * options_.tolerance) {
        return Status(StatusCode::kInvalidArgument,
                      "the redundant constraint " + constraintName(row) +
                          ", dropped where it repeated others, does not hold at the answer "
                          "(off by " +
                          formatNumber(std::abs(all[row])) + ")");
      }
    }
    active_rows_ = kept;
  }
  report.edit_steps = std::max(report.edit_steps, steps);
  z_ = z;
  evaluate(z, start_residuals_, nullptr);  // leaves x_ at the solution
  report.max_residual =
      std::max(report.max_residual,
               start_residuals_.size() > 0 ? start_residuals_.cwiseAbs().maxCoeff() : 0.0);
  report.equations += static_cast<int>(active_rows_.size());
  report.parameters += static_cast<int>(component_.columns.size());
  return {};
}

Status ComponentSolver::explainRankDeficiency(const Eigen::VectorXd& z, double shift,
                                              SolveReport& report) {
  Eigen::VectorXd residuals;
  Eigen::SparseMatrix<double> jacobian;
  evaluate(z, residuals, &jacobian);
  residuals -= shift * start_residuals_;
  const std::vector<DependentRow> dependent =
      findDependentRows(Eigen::MatrixXd(jacobian), residuals);
  if (dependent.empty()) {
    return Status(
        StatusCode::kInvalidArgument,
        "the constraints are nearly dependent here (a singular configuration); "
        "largest residuals: " +
            [&] {
              std::string names;
              for (int i = 0; i < residuals.size() && names.size() < 200; ++i) {
                if (std::abs(residuals[i]) > options_.tolerance) {
                  names += (names.empty() ? "" : ", ") + constraintName(active_rows_[i]);
                }
              }
              return names.empty() ? std::string("none") : names;
            }());
  }
  const auto describe = [&](const DependentRow& row) {
    std::vector<std::string> names;
    const std::string own = constraintName(active_rows_[row.row]);
    for (int combined : row.combined_rows) {
      const std::string name = constraintName(active_rows_[combined]);
      if (name != own && std::find(names.begin(), names.end(), name) == names.end()) {
        names.push_back(name);
      }
    }
    if (names.empty()) return own + " (its equation has no gradient here)";
    std::string text = own + " with ";
    // A long chain of dependencies is named by its first few links and a count.
    constexpr std::size_t kNamed = 8;
    for (std::size_t i = 0; i < std::min(names.size(), kNamed); ++i) {
      text += (i > 0 ? ", " : "") + names[i];
    }
    if (names.size() > kNamed) text += " and " + std::to_string(names.size() - kNamed) + " more";
    return text;
  };
  // A row with no gradient at all: the configuration is singular for it (an angle between
  // parallel directions, a distance between coincident points), whatever the others say.
  std::string singular;
  for (const DependentRow& row : dependent) {
    if (row.combined_rows.empty() && std::abs(row.inconsistency) > 1e3 * options_.tolerance) {
      const std::string name = constraintName(active_rows_[row.row]);
      if (singular.find(name) == std::string::npos) {
        singular += (singular.empty() ? "" : ", ") + name;
      }
    }
  }
  if (!singular.empty()) {
    return Status(
        StatusCode::kInvalidArgument,
        singular + (singular.find(',') == std::string::npos ? " has" : " have") +
            " no gradient in this configuration, so no small change can satisfy it "
            "(e.g. an angle between parallel directions, a distance between "
            "coincident points, a clearance between shapes that already share a point): start "
            "from a configuration off the singularity");
  }
  std::string conflicts;
  std::string redundancies;
  std::vector<int> redundant_rows;
  for (const DependentRow& row : dependent) {
    const bool conflicting = std::abs(row.inconsistency) > 1e3 * options_.tolerance;
    std::string& list = conflicting ? conflicts : redundancies;
    list += (list.empty() ? "" : "; ") + describe(row);
    if (!conflicting) redundant_rows.push_back(active_rows_[row.row]);
  }
  if (!conflicts.empty()) {
    return Status(StatusCode::kInvalidArgument,
                  "conflicting constraints: " + conflicts + " (no change satisfies them together)");
  }
  if (!options_.allow_redundant) {
    return Status(StatusCode::kInvalidArgument,
                  "redundant constraints: " + redundancies +
                      " (they repeat what the others already fix; remove them or allow "
                      "redundant constraints)");
  }
  for (int row : redundant_rows) {
    active_rows_.erase(std::find(active_rows_.begin(), active_rows_.end(), row));
    const std::string name = problem_.constraints()[row_constraint_[row]].name;
    if (std::find(report.dropped_redundant.begin(), report.dropped_redundant.end(), name) ==
        report.dropped_redundant.end()) {
      report.dropped_redundant.push_back(name);
    }
  }
  return {};
}

Status ComponentSolver::explainFailure(const Eigen::VectorXd& z, double reached) {
  // Named by how far each equation still is from the full edit.
  Eigen::VectorXd residuals;
  evaluate(z, residuals, nullptr);
  std::vector<int> order(static_cast<std::size_t>(residuals.size()));
  for (int i = 0; i < residuals.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return std::abs(residuals[a]) > std::abs(residuals[b]); });
  std::string worst;
  std::vector<std::string> named;
  for (int i : order) {
    if (named.size() == 3 || std::abs(residuals[i]) <= options_.tolerance) break;
    const std::string name = constraintName(active_rows_[i]);
    if (std::find(named.begin(), named.end(), name) != named.end()) continue;
    named.push_back(name);
    worst += (worst.empty() ? "" : ", ") + name + " off by " + formatNumber(std::abs(residuals[i]));
  }
  if (worst.empty()) {
    worst =
        "no equation is off by more than the tolerance, but Newton's steps did not settle "
        "(the answer is not isolated here, or the tolerance is below the rounding of the "
        "coordinates)";
  }
  return Status(StatusCode::kInvalidArgument,
                "the constraints could not all be met (the solve got " + formatNumber(reached) +
                    " of the way through the edit): " + worst);
}

}  // namespace collido::constraints::detail
