#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <collido/constraints/problem.h>
#include <collido/status.h>

namespace collido::constraints::detail {

/// Where each parameter sits in the solver's vector x: a body's 6 parameters (translation, then
/// the rotation vector relative to its starting rotation) at 6·body, the variables after them.
struct ParameterLayout {
  explicit ParameterLayout(const Problem& problem);

  int bodyColumn(int body) const { return 6 * body; }
  int variableColumn(int variable) const { return 6 * body_count + variable; }

  int body_count = 0;
  int size = 0;
  Eigen::VectorXd scale;   ///< the change of each parameter that counts as one unit
  std::vector<bool> free;  ///< false where the parameter is fixed
};

/// The problem's parameters as the vector x (translations absolute, rotation vectors zero).
Eigen::VectorXd startParameters(const Problem& problem, const ParameterLayout& layout);

/// Evaluates constraint residuals and their Jacobian at a parameter vector. Residuals are
/// normalised (lengths over the length scale, angles as they are) and the Jacobian is taken with
/// respect to the normalised parameters z = (x − x_start) / scale.
class ConstraintEvaluator {
 public:
  ConstraintEvaluator(const Problem& problem, const ParameterLayout& layout);

  /// Poses from x (the starting rotations captured at construction).
  void setParameters(const Eigen::VectorXd& x);
  /// Only one body's pose, or one variable, from x: a component's solve touches only its own.
  void setBody(int body, const Eigen::VectorXd& x);
  void setVariable(int variable, const Eigen::VectorXd& x);
  /// The same from the values themselves (no full parameter vector needed).
  void setBodyState(int body, const Eigen::Vector3d& translation, const Eigen::Vector3d& omega);
  void setBodyTranslation(int body, const Eigen::Vector3d& translation);
  void setVariableValue(int variable, double value);

  /// Number of scalar equations of a constraint kind.
  static int equationCount(ConstraintKind kind);

  /// Writes the constraint's residuals at rows [row0, row0 + equationCount) of `residuals` and,
  /// when `jacobian` is given, its non-zero derivatives as (row, global column, value).
  void evaluate(const Constraint& constraint, int row0, Eigen::VectorXd& residuals,
                std::vector<Eigen::Triplet<double>>* jacobian) const;

  /// The pose of a body at the last setParameters.
  Pose pose(int body) const;
  double lengthScale() const { return problem_.lengthScale(); }

  /// The first failure of the separation query (clearance constraints), ok when none: the
  /// residuals it left are NaN, so no step that needed it is taken.
  const Status& queryFailure() const { return query_failure_; }
  /// The constraint's target value: its constant, or its variable's current value.
  double target(const Constraint& c) const {
    return c.target.variable >= 0 ? variables_[c.target.variable] : c.target.value;
  }
  /// Whether the clearance's shapes were apart at its last evaluation.
  bool clearanceWasApart(const Constraint& c) const { return last_apart_[indexOf(c)]; }

 private:
  struct Tracked;
  class RowWriter;
  Tracked point(const PointRef& ref) const;
  Tracked direction(const DirectionRef& ref) const;
  Tracked acrossDirection(const DirectionRef& ref, int which) const;
  /// The constraint's index in its problem (it must be one of the problem's own).
  std::size_t indexOf(const Constraint& c) const;
  void evaluateClearance(const Constraint& c, int row, double target, Eigen::VectorXd& residuals,
                         std::vector<Eigen::Triplet<double>>* jacobian) const;
  /// The separation query's answer, its first failure recorded.
  Result<Separation> measure(const Constraint& c, const Pose& pose_a, const Pose& pose_b) const;
  /// The unit direction from A's origin to B's (+z where they coincide).
  static Eigen::Vector3d originLine(const Pose& pose_a, const Pose& pose_b);
  /// How far B must move along `direction` to part from A (0 when they only touch; `step` is a
  /// rounding-size move); infinity when 16 length scales do not part them, NaN when the query
  /// failed.
  double partingDistance(const Constraint& c, const Pose& pose_a, const Pose& pose_b,
                         const Eigen::Vector3d& direction, double step) const;

  const Problem& problem_;
  const ParameterLayout& layout_;
  std::vector<Eigen::Matrix3d> start_rotations_;
  std::vector<Eigen::Matrix3d> rotations_;
  std::vector<Eigen::Vector3d> translations_;
  std::vector<Eigen::Matrix3d> right_jacobians_;
  Eigen::VectorXd variables_;
  /// Per constraint, the last direction from A to B a clearance saw (zero: none yet): the
  /// gradient where the shapes touch and the query cannot say which way they part.
  mutable std::vector<Eigen::Vector3d> last_direction_;
  mutable std::vector<bool> last_apart_;  ///< per constraint: a clearance's shapes were apart
  mutable Status query_failure_;
};

}  // namespace collido::constraints::detail
