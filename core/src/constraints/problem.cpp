#include <collido/constraints/problem.h>

#include <cmath>
#include <utility>

namespace collido::constraints {
namespace {

Status invalid(std::string message) {
  return Status(StatusCode::kInvalidArgument, std::move(message));
}

constexpr double kPi = 3.14159265358979323846;

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
  }
  return "unknown";
}

Problem::Problem(double length_scale) : length_scale_(length_scale) {
  COLLIDO_ASSERT(std::isfinite(length_scale) && length_scale > 0.0,
                 "the length scale must be finite and positive");
}

Status Problem::checkName(const std::string& what, const std::string& name) const {
  if (name.empty()) return invalid(what + " needs a name");
  const auto taken = [&](const auto& items) {
    for (const auto& item : items) {
      if (item.name == name) return true;
    }
    return false;
  };
  if (taken(bodies_) || taken(variables_) || taken(constraints_)) {
    return invalid(what + " '" + name + "': the name is already used");
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
  bodies_.push_back(Body{std::move(name), pose, radius, false});
  return static_cast<int>(bodies_.size()) - 1;
}

Result<int> Problem::addVariable(std::string name, double value, double scale) {
  if (Status status = checkName("variable", name); !status.ok()) return status;
  if (!std::isfinite(value)) return invalid("variable '" + name + "': the value is not finite");
  if (!std::isfinite(scale) || scale <= 0.0) {
    return invalid("variable '" + name + "': the scale must be finite and positive");
  }
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
  constraints_.push_back(std::move(constraint));
  return static_cast<int>(constraints_.size()) - 1;
}

Result<int> Problem::addCoincident(std::string name, const PointRef& p, const PointRef& q) {
  Constraint c;
  c.kind = ConstraintKind::kCoincident;
  c.name = std::move(name);
  c.p = p;
  c.q = q;
  return add(std::move(c));
}

Result<int> Problem::addPointOnPlane(std::string name, const PointRef& p, const Plane& plane) {
  Constraint c;
  c.kind = ConstraintKind::kPointOnPlane;
  c.name = std::move(name);
  c.p = p;
  c.q = plane.point;
  c.e = plane.normal;
  return add(std::move(c));
}

Result<int> Problem::addPointOnLine(std::string name, const PointRef& p, const Axis& line) {
  Constraint c;
  c.kind = ConstraintKind::kPointOnLine;
  c.name = std::move(name);
  c.p = p;
  c.q = line.point;
  c.e = line.direction;
  return add(std::move(c));
}

Result<int> Problem::addDistance(std::string name, const PointRef& p, const PointRef& q,
                                 Target distance) {
  if (distance.variable == -1 && !(distance.value > 0.0)) {
    return invalid("constraint '" + name +
                   "': a distance must be positive (a distance of 0 is 'coincident')");
  }
  Constraint c;
  c.kind = ConstraintKind::kDistance;
  c.name = std::move(name);
  c.p = p;
  c.q = q;
  c.target = distance;
  return add(std::move(c));
}

Result<int> Problem::addAngle(std::string name, const DirectionRef& d, const DirectionRef& e,
                              Target radians) {
  if (radians.variable == -1 && !(radians.value > 1e-6 && radians.value < kPi - 1e-6)) {
    return invalid("constraint '" + name +
                   "': an angle must lie strictly between 0 and pi radians (0 and pi are "
                   "'parallel', pi/2 is 'perpendicular')");
  }
  Constraint c;
  c.kind = ConstraintKind::kAngle;
  c.name = std::move(name);
  c.d = d;
  c.e = e;
  c.target = radians;
  return add(std::move(c));
}

Result<int> Problem::addParallel(std::string name, const DirectionRef& d, const DirectionRef& e) {
  Constraint c;
  c.kind = ConstraintKind::kParallel;
  c.name = std::move(name);
  c.d = d;
  c.e = e;
  return add(std::move(c));
}

Result<int> Problem::addPerpendicular(std::string name, const DirectionRef& d,
                                      const DirectionRef& e) {
  Constraint c;
  c.kind = ConstraintKind::kPerpendicular;
  c.name = std::move(name);
  c.d = d;
  c.e = e;
  return add(std::move(c));
}

Result<int> Problem::addCoaxial(std::string name, const Axis& a, const Axis& b) {
  Constraint c;
  c.kind = ConstraintKind::kCoaxial;
  c.name = std::move(name);
  c.p = a.point;
  c.d = a.direction;
  c.q = b.point;
  c.e = b.direction;
  return add(std::move(c));
}

}  // namespace collido::constraints
