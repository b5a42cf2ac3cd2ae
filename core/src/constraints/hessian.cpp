#include "hessian.h"

#include <algorithm>

#include "components.h"

namespace collido::constraints::detail {
namespace {

/// Step of the forward differences, in normalised parameters (truncation ~h, rounding
/// ~1e-16/h: both near 1e-8 of the Hessian, which only steers the iteration; central
/// differences cost twice the evaluations and saved no iteration on the bench's chains).
constexpr double kStep = 1e-8;

/// Where every free parameter of the constraint is a translation (its bodies' rotations fixed
/// or not involved), most kinds are linear in them and the distance's Hessian is known: these
/// are written exactly, without differencing. Returns false for the other cases.
bool addTranslationHessian(const ConstraintEvaluator& evaluator, const ParameterLayout& layout,
                           const Constraint& constraint, double weight,
                           const std::vector<int>& columns,
                           std::vector<Eigen::Triplet<double>>& out) {
  for (int column : columns) {
    if (column >= 6 * layout.body_count || column % 6 >= 3) return false;
  }
  switch (constraint.kind) {
    case ConstraintKind::kCoincident:
    case ConstraintKind::kPointOnPlane:
    case ConstraintKind::kPointOnLine:
    case ConstraintKind::kCoaxial:
    case ConstraintKind::kParallel:
    case ConstraintKind::kPerpendicular:
    case ConstraintKind::kAngle:
      return true;  // linear in translations, or independent of them
    case ConstraintKind::kDistance:
      break;
    case ConstraintKind::kClearance:
      return false;
  }
  const int a = constraint.p.body;
  const int b = constraint.q.body;
  if (a == b) return true;  // both points on one body: the distance does not change
  const auto world = [&](const PointRef& ref) {
    return ref.body == kWorld ? ref.local : Eigen::Vector3d(evaluator.pose(ref.body) * ref.local);
  };
  const Eigen::Vector3d offset = world(constraint.p) - world(constraint.q);
  const double distance = offset.norm();
  if (!(distance > 0.0)) return false;
  const Eigen::Vector3d u = offset / distance;
  // ∇²|p − q| over p's translation is (I − u uᵀ) / |p − q|, over q's the same, across −that.
  const Eigen::Matrix3d block = weight * (Eigen::Matrix3d::Identity() - u * u.transpose()) /
                                (distance * evaluator.lengthScale());
  const auto write = [&](int body_i, int body_j, double sign) {
    if (body_i == kWorld || body_j == kWorld) return;
    const int ci = layout.bodyColumn(body_i);
    const int cj = layout.bodyColumn(body_j);
    if (!layout.free[ci] || !layout.free[cj]) return;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        out.emplace_back(ci + i, cj + j,
                         sign * block(i, j) * layout.scale[ci + i] * layout.scale[cj + j]);
      }
    }
  };
  write(a, a, 1.0);
  write(b, b, 1.0);
  write(a, b, -1.0);
  write(b, a, -1.0);
  return true;
}

}  // namespace

void addWeightedHessian(ConstraintEvaluator& evaluator, const ParameterLayout& layout,
                        const Constraint& constraint, const double* weights,
                        const Eigen::VectorXd& x, std::vector<Eigen::Triplet<double>>& out) {
  const ConstraintSupport support = supportOf(constraint);
  std::vector<int> columns;
  // Only free parameters: the solve drops every other column of the Hessian.
  for (int body : support.bodies) {
    for (int k = 0; k < 6; ++k) {
      if (layout.free[layout.bodyColumn(body) + k]) columns.push_back(layout.bodyColumn(body) + k);
    }
  }
  for (int variable : support.variables) {
    if (layout.free[layout.variableColumn(variable)])
      columns.push_back(layout.variableColumn(variable));
  }
  if (addTranslationHessian(evaluator, layout, constraint, weights[0], columns, out)) return;
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
  // A contact, or a clearance whose shapes touch or overlap, changes closest features with
  // every step (a rim on a face, a corner on a face): differences across them are noise that
  // misleads Newton, and in overlap each costs a search for the parting distance. There its
  // Hessian is left out (Gauss–Newton for that equation).
  if (constraint.kind == ConstraintKind::kClearance &&
      (!evaluator.clearanceWasApart(constraint) || evaluator.target(constraint) == 0.0)) {
    return;
  }
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
