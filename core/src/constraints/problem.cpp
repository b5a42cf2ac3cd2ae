#include <collido/constraints/problem.h>

#include <cmath>
#include <utility>

#include "angle_range.h"

namespace collido::constraints {
namespace {

const Eigen::Vector3d kOrigin = Eigen::Vector3d::Zero();

Status invalid(std::string message) {
  return Status(StatusCode::kInvalidArgument, std::move(message));
}

}  // namespace

const char* constraintKindName(ConstraintKind kind) {
  switch (kind) {
    case ConstraintKind::kCoincident:
      return "coincident";
    case ConstraintKind::kPointOnPlane:
      return "point_on_plane";
    case ConstraintKind::kPointOnLine:
      return "point_on_line";
    case ConstraintKind::kDistance:
      return "distance";
    case ConstraintKind::kAngle:
      return "angle";
    case ConstraintKind::kParallel:
      return "parallel";
    case ConstraintKind::kPerpendicular:
      return "perpendicular";
    case ConstraintKind::kCoaxial:
      return "coaxial";
    case ConstraintKind::kClearance:
      return "clearance";
  }
  return "unknown";
}

Problem::Problem(double length_scale) : length_scale_(length_scale) {
  COLLIDO_ASSERT(std::isfinite(length_scale) && length_scale > 0.0,
                 "the length scale must be finite and positive");
}

Status Problem::checkName(const std::string& what, const std::string& name) const {
  if (name.empty()) return invalid(what + " needs a name");
  const auto taken = names_.find(name);
  if (taken != names_.end()) {
    return invalid(what + " '" + name + "': the name is already used by " + taken->second);
  }
  return {};
}

Result<int> Problem::addBody(std::string name, const Pose& pose, double radius) {
  if (Status status = checkName("body", name); !status.ok()) return status;
  if (!pose.matrix().allFinite()) return invalid("body '" + name + "': the pose is not finite");
  const Eigen::Matrix3d r = pose.linear();
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-9 ||
      r.determinant() < 0.0) {
    return invalid("body '" + name + "': the pose's rotation is not a rotation");
  }
  if (!std::isfinite(radius) || radius <= 0.0) {
    return invalid("body '" + name + "': the radius must be finite and positive");
  }
  names_.emplace(name, "a body");
  bodies_.push_back(Body{std::move(name), pose, radius, false, false});
  return static_cast<int>(bodies_.size()) - 1;
}

Result<int> Problem::addVariable(std::string name, double value, double scale) {
  if (Status status = checkName("variable", name); !status.ok()) return status;
  if (!std::isfinite(value)) return invalid("variable '" + name + "': the value is not finite");
  if (!std::isfinite(scale) || scale <= 0.0) {
    return invalid("variable '" + name + "': the scale must be finite and positive");
  }
  names_.emplace(name, "a variable");
  variables_.push_back(Variable{std::move(name), value, scale, false});
  return static_cast<int>(variables_.size()) - 1;
}

Status Problem::fixBody(int body) {
  if (body < 0 || body >= static_cast<int>(bodies_.size())) {
    return invalid("fixed: no body " + std::to_string(body));
  }
  bodies_[body].fixed = true;
  return {};
}

Status Problem::fixRotation(int body) {
  if (body < 0 || body >= static_cast<int>(bodies_.size())) {
    return invalid("fixed rotation: no body " + std::to_string(body));
  }
  bodies_[body].rotation_fixed = true;
  return {};
}

Status Problem::fixVariable(int variable) {
  if (variable < 0 || variable >= static_cast<int>(variables_.size())) {
    return invalid("fixed: no variable " + std::to_string(variable));
  }
  variables_[variable].fixed = true;
  return {};
}

Status Problem::setVariable(int variable, double value) {
  if (variable >= 0 && variable < static_cast<int>(variables_.size()) && !std::isfinite(value)) {
    return invalid("variable '" + variables_[variable].name + "': the value is not finite");
  }
  if (Status status = fixVariable(variable); !status.ok()) return status;
  variables_[variable].value = value;
  return {};
}

Status Problem::checkPoint(const std::string& name, const char* field,
                           const PointRef& point) const {
  if (point.body != kWorld && (point.body < 0 || point.body >= static_cast<int>(bodies_.size()))) {
    return invalid("constraint '" + name + "': " + field + " names no body (" +
                   std::to_string(point.body) + ")");
  }
  if (!point.local.allFinite()) {
    return invalid("constraint '" + name + "': " + field + " is not finite");
  }
  return {};
}

Status Problem::checkDirection(const std::string& name, const char* field,
                               DirectionRef& direction) const {
  if (Status status = checkPoint(name, field, PointRef{direction.body, direction.local});
      !status.ok()) {
    return status;
  }
  const double length = direction.local.norm();
  if (!(length > 1e-12)) {
    return invalid("constraint '" + name + "': " + field + " is a zero vector");
  }
  direction.local /= length;
  return {};
}

Status Problem::checkTarget(const std::string& name, const Target& target) const {
  if (target.variable >= static_cast<int>(variables_.size()) || target.variable < -1) {
    return invalid("constraint '" + name + "': the target names no variable (" +
                   std::to_string(target.variable) + ")");
  }
  if (target.variable == -1 && !std::isfinite(target.value)) {
    return invalid("constraint '" + name + "': the target is not finite");
  }
  return {};
}

Result<int> Problem::add(Constraint constraint) {
  if (Status status = checkName("constraint", constraint.name); !status.ok()) return status;
  const std::string& name = constraint.name;
  for (const auto& [point, field] :
       {std::pair{&constraint.p, "the point"}, std::pair{&constraint.q, "the second point"}}) {
    if (Status status = checkPoint(name, field, *point); !status.ok()) return status;
  }
  for (const auto& [direction, field] : {std::pair{&constraint.d, "the direction"},
                                         std::pair{&constraint.e, "the second direction"}}) {
    if (Status status = checkDirection(name, field, *direction); !status.ok()) return status;
  }
  if (Status status = checkTarget(name, constraint.target); !status.ok()) return status;
  names_.emplace(name, "a constraint");
  constraints_.push_back(std::move(constraint));
  return static_cast<int>(constraints_.size()) - 1;
}

Result<int> Problem::addCoincident(std::string name, const PointRef& p, const PointRef& q) {
  return add({ConstraintKind::kCoincident, std::move(name), p, q, {}, {}, {}});
}

Result<int> Problem::addPointOnPlane(std::string name, const PointRef& p, const Plane& plane) {
  return add(
      {ConstraintKind::kPointOnPlane, std::move(name), p, plane.point, {}, plane.normal, {}});
}

Result<int> Problem::addPointOnLine(std::string name, const PointRef& p, const Axis& line) {
  return add(
      {ConstraintKind::kPointOnLine, std::move(name), p, line.point, {}, line.direction, {}});
}

Result<int> Problem::addDistance(std::string name, const PointRef& p, const PointRef& q,
                                 Target distance) {
  if (distance.variable == -1 && !(distance.value > 0.0)) {
    return invalid("constraint '" + name +
                   "': a distance must be positive (a distance of 0 is 'coincident')");
  }
  return add({ConstraintKind::kDistance, std::move(name), p, q, {}, {}, distance});
}

Result<int> Problem::addAngle(std::string name, const DirectionRef& d, const DirectionRef& e,
                              Target radians) {
  if (radians.variable == -1 && !detail::angleTargetInRange(radians.value)) {
    return invalid("constraint '" + name +
                   "': an angle must lie strictly between 0 and pi radians (0 and pi are "
                   "'parallel', pi/2 is 'perpendicular')");
  }
  return add({ConstraintKind::kAngle, std::move(name), {}, {}, d, e, radians});
}

Result<int> Problem::addParallel(std::string name, const DirectionRef& d, const DirectionRef& e) {
  return add({ConstraintKind::kParallel, std::move(name), {}, {}, d, e, {}});
}

Result<int> Problem::addPerpendicular(std::string name, const DirectionRef& d,
                                      const DirectionRef& e) {
  return add({ConstraintKind::kPerpendicular, std::move(name), {}, {}, d, e, {}});
}

Result<int> Problem::addCoaxial(std::string name, const Axis& a, const Axis& b) {
  return add(
      {ConstraintKind::kCoaxial, std::move(name), a.point, b.point, a.direction, b.direction, {}});
}

Result<int> Problem::addClearance(std::string name, int body_a, int body_b, Target clearance) {
  for (const auto& [body, field] :
       {std::pair{body_a, "the first body"}, std::pair{body_b, "the second body"}}) {
    if (body < 0 || body >= static_cast<int>(bodies_.size())) {
      return invalid("constraint '" + name + "': " + field + " names no body (" +
                     std::to_string(body) + "; a clearance is between two bodies' shapes)");
    }
  }
  if (body_a == body_b) {
    return invalid("constraint '" + name + "': a clearance needs two different bodies");
  }
  if (clearance.variable == -1 && !(clearance.value >= 0.0)) {
    return invalid("constraint '" + name + "': a clearance must be >= 0 (0 is contact)");
  }
  return add({ConstraintKind::kClearance,
              std::move(name),
              PointRef{body_a, kOrigin},
              PointRef{body_b, kOrigin},
              {},
              {},
              clearance});
}

}  // namespace collido::constraints
