#include "equations.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include <collido/assert.h>

#include "rotation.h"

namespace collido::constraints::detail {
namespace {

using Gradient = Eigen::Matrix<double, 1, 6>;

/// Two unit vectors across a unit direction, fixed in the direction's frame: the residuals of
/// "on this line" and "parallel to this" are components along them.
Eigen::Vector3d across(const Eigen::Vector3d& direction, int which) {
  const Eigen::Vector3d helper =
      std::abs(direction.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d first = direction.cross(helper).normalized();
  return which == 0 ? first : direction.cross(first);
}

}  // namespace

ParameterLayout::ParameterLayout(const Problem& problem)
    : body_count(static_cast<int>(problem.bodies().size())),
      size(6 * body_count + static_cast<int>(problem.variables().size())),
      scale(size),
      free(size, true) {
  const double length = problem.lengthScale();
  for (int b = 0; b < body_count; ++b) {
    const Body& body = problem.bodies()[b];
    for (int k = 0; k < 6; ++k) {
      scale[6 * b + k] = k < 3 ? length : length / body.radius;
      free[6 * b + k] = !body.fixed && (k < 3 || !body.rotation_fixed);
    }
  }
  for (int v = 0; v < static_cast<int>(problem.variables().size()); ++v) {
    scale[variableColumn(v)] = problem.variables()[v].scale;
    free[variableColumn(v)] = !problem.variables()[v].fixed;
  }
}

Eigen::VectorXd startParameters(const Problem& problem, const ParameterLayout& layout) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(layout.size);
  for (int b = 0; b < layout.body_count; ++b) {
    x.segment<3>(layout.bodyColumn(b)) = problem.bodies()[b].pose.translation();
  }
  for (int v = 0; v < static_cast<int>(problem.variables().size()); ++v) {
    x[layout.variableColumn(v)] = problem.variables()[v].value;
  }
  return x;
}

/// A world vector and its derivative with respect to one body's raw parameters [t, ω].
struct ConstraintEvaluator::Tracked {
  Eigen::Vector3d value;
  int body = kWorld;
  Eigen::Matrix<double, 3, 6> jacobian = Eigen::Matrix<double, 3, 6>::Zero();
};

/// Collects one normalised equation's derivatives as triplets.
class ConstraintEvaluator::RowWriter {
 public:
  RowWriter(const ParameterLayout& layout, std::vector<Eigen::Triplet<double>>* out, int row,
            double row_scale)
      : layout_(layout), out_(out), row_(row), row_scale_(row_scale) {}

  /// Adds gradientᵀ · (the tracked vector's Jacobian).
  void add(const Eigen::Vector3d& gradient, const Tracked& tracked) {
    if (out_ == nullptr || tracked.body == kWorld) return;
    const Gradient row = gradient.transpose() * tracked.jacobian;
    const int column0 = layout_.bodyColumn(tracked.body);
    for (int k = 0; k < 6; ++k) {
      if (row[k] != 0.0) {
        out_->emplace_back(row_, column0 + k, row[k] * layout_.scale[column0 + k] / row_scale_);
      }
    }
  }

  void addVariable(int variable, double gradient) {
    if (out_ == nullptr || variable < 0) return;
    const int column = layout_.variableColumn(variable);
    out_->emplace_back(row_, column, gradient * layout_.scale[column] / row_scale_);
  }

 private:
  const ParameterLayout& layout_;
  std::vector<Eigen::Triplet<double>>* out_;
  int row_;
  double row_scale_;
};

ConstraintEvaluator::ConstraintEvaluator(const Problem& problem, const ParameterLayout& layout)
    : problem_(problem),
      layout_(layout),
      last_direction_(problem.constraints().size(), Eigen::Vector3d::Zero()),
      last_apart_(problem.constraints().size(), false) {
  for (const Body& body : problem.bodies())
    start_rotations_.push_back(body.pose.linear());
  setParameters(startParameters(problem, layout));
}

void ConstraintEvaluator::setParameters(const Eigen::VectorXd& x) {
  const int bodies = layout_.body_count;
  rotations_.resize(bodies);
  translations_.resize(bodies);
  right_jacobians_.resize(bodies);
  for (int b = 0; b < bodies; ++b)
    setBody(b, x);
  variables_ = x.tail(x.size() - 6 * bodies);
}

void ConstraintEvaluator::setBody(int body, const Eigen::VectorXd& x) {
  setBodyState(body, x.segment<3>(layout_.bodyColumn(body)),
               x.segment<3>(layout_.bodyColumn(body) + 3));
}

void ConstraintEvaluator::setBodyState(int body, const Eigen::Vector3d& translation,
                                       const Eigen::Vector3d& omega) {
  translations_[body] = translation;
  if (omega.isZero(0.0)) {  // exp(0) = I and J_r(0) = I, exactly (bodies that do not turn)
    rotations_[body] = start_rotations_[body];
    right_jacobians_[body].setIdentity();
    return;
  }
  rotations_[body] = start_rotations_[body] * expMap(omega);
  right_jacobians_[body] = rightJacobian(omega);
}

void ConstraintEvaluator::setBodyTranslation(int body, const Eigen::Vector3d& translation) {
  translations_[body] = translation;
}

void ConstraintEvaluator::setVariableValue(int variable, double value) {
  variables_[variable] = value;
}

void ConstraintEvaluator::setVariable(int variable, const Eigen::VectorXd& x) {
  variables_[variable] = x[layout_.variableColumn(variable)];
}

Pose ConstraintEvaluator::pose(int body) const {
  Pose pose = Pose::Identity();
  pose.linear() = rotations_[body];
  pose.translation() = translations_[body];
  return pose;
}

ConstraintEvaluator::Tracked ConstraintEvaluator::direction(const DirectionRef& ref) const {
  Tracked tracked;
  tracked.body = ref.body;
  if (ref.body == kWorld) {
    tracked.value = ref.local;
    return tracked;
  }
  const Eigen::Matrix3d& r = rotations_[ref.body];
  tracked.value = r * ref.local;
  tracked.jacobian.rightCols<3>() = -r * skew(ref.local) * right_jacobians_[ref.body];
  return tracked;
}

ConstraintEvaluator::Tracked ConstraintEvaluator::point(const PointRef& ref) const {
  // A point turns like the direction to it from the body's origin, and moves with the origin.
  Tracked tracked = direction(DirectionRef{ref.body, ref.local});
  if (ref.body == kWorld) return tracked;
  tracked.value += translations_[ref.body];
  tracked.jacobian.leftCols<3>().setIdentity();
  return tracked;
}

ConstraintEvaluator::Tracked ConstraintEvaluator::acrossDirection(const DirectionRef& ref,
                                                                  int which) const {
  return direction(DirectionRef{ref.body, across(ref.local, which)});
}

int ConstraintEvaluator::equationCount(ConstraintKind kind) {
  switch (kind) {
    case ConstraintKind::kCoincident:
      return 3;
    case ConstraintKind::kPointOnLine:
    case ConstraintKind::kParallel:
      return 2;
    case ConstraintKind::kPointOnPlane:
    case ConstraintKind::kDistance:
    case ConstraintKind::kClearance:
    case ConstraintKind::kAngle:
    case ConstraintKind::kPerpendicular:
      return 1;
    case ConstraintKind::kCoaxial:
      return 4;
  }
  return 0;
}

void ConstraintEvaluator::evaluate(const Constraint& c, int row0, Eigen::VectorXd& residuals,
                                   std::vector<Eigen::Triplet<double>>* jacobian) const {
  const double length = problem_.lengthScale();
  const auto target = [&] {
    return c.target.variable >= 0 ? variables_[c.target.variable] : c.target.value;
  };
  // Residual (p − q)·u, in lengths, with u a tracked direction.
  const auto offsetAlong = [&](int row, const Tracked& p, const Tracked& q, const Tracked& u) {
    const Eigen::Vector3d offset = p.value - q.value;
    residuals[row] = offset.dot(u.value) / length;
    RowWriter writer(layout_, jacobian, row, length);
    writer.add(u.value, p);
    writer.add(-u.value, q);
    writer.add(offset, u);
  };
  // Residual d·e − value, unitless.
  const auto dotProduct = [&](int row, const Tracked& d, const Tracked& e, double value) {
    residuals[row] = d.value.dot(e.value) - value;
    RowWriter writer(layout_, jacobian, row, 1.0);
    writer.add(e.value, d);
    writer.add(d.value, e);
  };
  switch (c.kind) {
    case ConstraintKind::kCoincident: {
      const Tracked p = point(c.p);
      const Tracked q = point(c.q);
      for (int k = 0; k < 3; ++k) {
        Tracked axis;
        axis.value = Eigen::Vector3d::Unit(k);
        offsetAlong(row0 + k, p, q, axis);
      }
      return;
    }
    case ConstraintKind::kPointOnPlane:
      offsetAlong(row0, point(c.p), point(c.q), direction(c.e));
      return;
    case ConstraintKind::kPointOnLine: {
      const Tracked p = point(c.p);
      const Tracked q = point(c.q);
      for (int k = 0; k < 2; ++k)
        offsetAlong(row0 + k, p, q, acrossDirection(c.e, k));
      return;
    }
    case ConstraintKind::kDistance: {
      const Tracked p = point(c.p);
      const Tracked q = point(c.q);
      const Eigen::Vector3d offset = p.value - q.value;
      const double distance = offset.norm();
      residuals[row0] = (distance - target()) / length;
      // At p = q the distance has no gradient; a zero row lets the rank analysis name it.
      const Eigen::Vector3d unit =
          distance > 0.0 ? Eigen::Vector3d(offset / distance) : Eigen::Vector3d::Zero();
      RowWriter writer(layout_, jacobian, row0, length);
      writer.add(unit, p);
      writer.add(-unit, q);
      writer.addVariable(c.target.variable, -1.0);
      return;
    }
    case ConstraintKind::kAngle: {
      const double angle = target();
      dotProduct(row0, direction(c.d), direction(c.e), std::cos(angle));
      RowWriter(layout_, jacobian, row0, 1.0).addVariable(c.target.variable, std::sin(angle));
      return;
    }
    case ConstraintKind::kParallel: {
      const Tracked d = direction(c.d);
      for (int k = 0; k < 2; ++k)
        dotProduct(row0 + k, d, acrossDirection(c.e, k), 0.0);
      return;
    }
    case ConstraintKind::kPerpendicular:
      dotProduct(row0, direction(c.d), direction(c.e), 0.0);
      return;
    case ConstraintKind::kCoaxial: {
      const Tracked d = direction(c.d);
      const Tracked p = point(c.p);
      const Tracked q = point(c.q);
      for (int k = 0; k < 2; ++k) {
        const Tracked across_k = acrossDirection(c.e, k);
        dotProduct(row0 + k, d, across_k, 0.0);
        offsetAlong(row0 + 2 + k, p, q, across_k);
      }
      return;
    }
    case ConstraintKind::kClearance:
      evaluateClearance(c, row0, target(), residuals, jacobian);
      return;
  }
}

Result<Separation> ConstraintEvaluator::measure(const Constraint& c, const Pose& pose_a,
                                                const Pose& pose_b) const {
  Result<Separation> measured =
      problem_.separationQuery()->measure(c.p.body, pose_a, c.q.body, pose_b);
  if (!measured.ok() && query_failure_.ok()) {
    query_failure_ = Status(
        measured.status().code(),
        "constraint '" + c.name + "': the distance query failed: " + measured.status().message());
  }
  return measured;
}

Eigen::Vector3d ConstraintEvaluator::originLine(const Pose& pose_a, const Pose& pose_b) {
  const Eigen::Vector3d along = pose_b.translation() - pose_a.translation();
  return along.squaredNorm() > 0.0 ? Eigen::Vector3d(along.normalized()) : Eigen::Vector3d::UnitZ();
}

double ConstraintEvaluator::partingDistance(const Constraint& c, const Pose& pose_a,
                                            const Pose& pose_b, const Eigen::Vector3d& direction,
                                            double step) const {
  // The least s >= 0 with B moved by s · direction apart from A. A move that parts them is found
  // by growing a rounding-size step (up to 16 length scales); from there the distance falls
  // along the direction at the rate direction · n (n from the closest points), which gives s.
  // Where that rate is small (the direction nearly along the contact), bisection to rounding.
  const auto probe = [&](double s) -> std::optional<Separation> {
    Pose moved = pose_b;
    moved.translation() += s * direction;
    Result<Separation> measured = measure(c, pose_a, moved);
    if (!measured.ok()) return std::nullopt;
    return measured.value();
  };
  double low = 0.0;
  double high = step;
  std::optional<Separation> parted;
  for (;;) {
    parted = probe(high);
    if (!parted) return std::numeric_limits<double>::quiet_NaN();
    if (parted->distance > 0.0) break;
    low = high;
    high *= 4.0;
    if (high > 16.0 * problem_.lengthScale()) return std::numeric_limits<double>::infinity();
  }
  const Eigen::Vector3d between = parted->point_b - parted->point_a;
  const double rate =
      between.norm() > 0.0 ? direction.dot(between.normalized()) : 0.0;  // d distance / d s
  if (rate > 0.2) return std::clamp(high - parted->distance / rate, low, high);
  const double resolution = 1e-6 * step;  // about the rounding of the coordinates
  while (high - low > resolution) {
    const double middle = 0.5 * (low + high);
    const std::optional<Separation> at = probe(middle);
    if (!at) return std::numeric_limits<double>::quiet_NaN();
    (at->distance > 0.0 ? high : low) = middle;
  }
  return low == 0.0 ? 0.0 : high;
}

std::size_t ConstraintEvaluator::indexOf(const Constraint& c) const {
  const std::ptrdiff_t index = &c - problem_.constraints().data();
  COLLIDO_ASSERT(index >= 0 && index < static_cast<std::ptrdiff_t>(last_direction_.size()),
                 "a clearance is evaluated as one of its problem's constraints");
  return static_cast<std::size_t>(index);
}

void ConstraintEvaluator::evaluateClearance(const Constraint& c, int row, double target,
                                            Eigen::VectorXd& residuals,
                                            std::vector<Eigen::Triplet<double>>* jacobian) const {
  const int a = c.p.body;
  const int b = c.q.body;
  const Pose pose_a = pose(a);
  const Pose pose_b = pose(b);
  Result<Separation> measured = measure(c, pose_a, pose_b);
  if (!measured.ok()) {
    residuals[row] = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  const Separation& s = measured.value();
  // The signed separation and the direction B leaves A along, from which the gradient follows
  // (the closest points held in their bodies: the derivative of a minimum distance is that of
  // the distance between its minimisers).
  double separation = 0.0;
  Eigen::Vector3d on_a = s.point_a;
  Eigen::Vector3d on_b = s.point_b;
  Eigen::Vector3d direction = on_b - on_a;
  Eigen::Vector3d& last = last_direction_[indexOf(c)];
  // The direction from the closest points is good to about ulp(coordinate) / distance; nearer
  // contact than that, the last direction seen is the better guess.
  const double trusted = 1e-8 * (problem_.lengthScale() + on_a.cwiseAbs().maxCoeff());
  last_apart_[indexOf(c)] = s.distance > 0.0 && direction.norm() > 0.0;
  if (last_apart_[indexOf(c)]) {
    separation = s.distance;
    direction.normalize();
    if (s.distance < trusted && last.squaredNorm() > 0.0) direction = last;
  } else if (s.depth && *s.depth > 0.0) {
    separation = -*s.depth;
    direction = s.normal.normalized();
    on_a = s.contact;
    on_b = s.contact - *s.depth * direction;
  } else {
    // Touching, or overlapping by a depth the query does not give: the overlap is measured
    // along the way they parted last (else the line of their origins) as the least move of B
    // that parts them, so the separation stays continuous through contact.
    if (last.squaredNorm() == 0.0) last = originLine(pose_a, pose_b);
    direction = last;
    const double depth = partingDistance(c, pose_a, pose_b, direction, trusted);
    if (std::isnan(depth)) {
      residuals[row] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    if (std::isinf(depth)) direction.setZero();  // nothing parts them: no gradient here
    separation = std::isinf(depth) ? 0.0 : -depth;
    on_b = on_a + separation * direction;
  }
  if (direction.squaredNorm() > 0.0) last = direction;
  const double length = problem_.lengthScale();
  residuals[row] = (separation - target) / length;
  RowWriter writer(layout_, jacobian, row, length);
  const auto local = [&](int body, const Pose& body_pose, const Eigen::Vector3d& world) {
    return PointRef{body, body_pose.linear().transpose() * (world - body_pose.translation())};
  };
  writer.add(direction, point(local(b, pose_b, on_b)));
  writer.add(-direction, point(local(a, pose_a, on_a)));
  writer.addVariable(c.target.variable, -1.0);
}

}  // namespace collido::constraints::detail
