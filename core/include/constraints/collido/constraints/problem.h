#pragma once

#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include <collido/geometry.h>
#include <collido/status.h>

namespace collido::constraints {

/// The body index of the world frame: references on it never move.
inline constexpr int kWorld = -1;

/// A point fixed in a body's frame (its model frame), or in the world for kWorld.
struct PointRef {
  int body = kWorld;
  Eigen::Vector3d local = Eigen::Vector3d::Zero();
};

/// A direction fixed in a body's frame, or in the world for kWorld; stored normalised.
struct DirectionRef {
  int body = kWorld;
  Eigen::Vector3d local = Eigen::Vector3d::UnitZ();
};

/// A line (or an axis of revolution) through a point along a direction.
struct Axis {
  PointRef point;
  DirectionRef direction;
};

/// A plane through a point with a normal.
struct Plane {
  PointRef point;
  DirectionRef normal;
};

/// The value a dimensional constraint holds: a constant, or a named variable of the problem
/// (a scene dimension), which the solver may change unless it is fixed.
struct Target {
  double value = 0.0;
  int variable = -1;  ///< a variable index, or -1 for the constant `value`
};

/// The kinds of equation a constraint adds (the number of scalar equations in parentheses).
enum class ConstraintKind {
  kCoincident,     ///< p = q (3)
  kPointOnPlane,   ///< (p − plane point) · normal = 0 (1)
  kPointOnLine,    ///< p on the line, along two directions across it (2)
  kDistance,       ///< |p − q| = target (1); target > 0, coincident is its own kind
  kAngle,          ///< angle between two directions = target radians, in (0, π) (1)
  kParallel,       ///< two directions parallel or opposite (2)
  kPerpendicular,  ///< two directions at a right angle (1)
  kCoaxial,        ///< two axes on one line: parallel, and a point of one on the other (4)
  kClearance,      ///< the distance between two bodies' shapes = target >= 0, 0 for contact (1)
};

/// "coincident", "point_on_plane", ...
const char* constraintKindName(ConstraintKind kind);

/// One constraint as added; the fields its kind does not use keep their defaults.
struct Constraint {
  ConstraintKind kind = ConstraintKind::kCoincident;
  std::string name;  ///< how errors name it; unique within a problem
  PointRef p;
  PointRef q;  ///< the second point, or the plane's / line's / axis' point
  DirectionRef d;
  DirectionRef e;  ///< the second direction, or the plane's normal / line's direction
  Target target;
};

/// How far apart two bodies' shapes are, in the world frame, as a distance query answers it.
struct Separation {
  double distance = 0.0;  ///< >= 0; 0 when the shapes share a point
  /// Closest points of A and of B; their difference gives the direction when distance > 0.
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
  /// Where the shapes overlap and the query can tell: how deep (> 0), along `normal` (unit, from
  /// A towards B: moving B along it reduces the overlap), at `contact` (a point of A in the
  /// overlap). Empty when they are apart, or the query measures distances only.
  std::optional<double> depth;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();
};

/// The distance query a clearance constraint goes through (a backend's, or the exact oracle's):
/// the separation of two bodies' shapes at the given poses. The solver calls it many times per
/// iteration; a failure ends the solve with its status.
class SeparationQuery {
 public:
  virtual ~SeparationQuery() = default;
  virtual Result<Separation> measure(int body_a, const Pose& pose_a, int body_b,
                                     const Pose& pose_b) = 0;
};

/// A movable object: its pose is 6 parameters, a translation and a rotation vector ω relative to
/// the pose it started the solve with (R = R_start · exp(ω), so |ω| is the angle it turned).
struct Body {
  std::string name;
  Pose pose = Pose::Identity();
  /// The length that turns angles into distances when changes are weighed: a rotation by θ
  /// counts as a move of θ·radius (use the object's bounding radius).
  double radius = 1.0;
  bool fixed = false;
  /// Its rotation is kept (a point, or a part that only slides): 3 parameters instead of 6.
  bool rotation_fixed = false;
};

/// A named scalar the constraints may refer to (a dimension: a length, an angle).
struct Variable {
  std::string name;
  double value = 0.0;
  double scale = 1.0;  ///< its unit of change: a change of `scale` weighs as one length_scale
  bool fixed = false;
};

/// m equations over n parameters (body poses and variables) with m < n in general: the problem
/// the least-change solver (solve.h) works on. Build it with the add/fix calls, which refuse bad
/// references and values with the constraint's name and the reason.
class Problem {
 public:
  /// `length_scale`: the change of a coordinate that counts as one unit (e.g. the scene's size).
  explicit Problem(double length_scale = 1.0);

  Result<int> addBody(std::string name, const Pose& pose, double radius);
  Result<int> addVariable(std::string name, double value, double scale);

  /// The "fixed" constraint: the body's pose or the variable's value is not changed; its
  /// parameters drop out of the solve.
  Status fixBody(int body);
  Status fixVariable(int variable);
  /// The body may move but not turn: its rotation parameters drop out of the solve.
  Status fixRotation(int body);
  /// A changed dimension: sets the variable and fixes it (the solve then follows it in steps).
  Status setVariable(int variable, double value);

  Result<int> addCoincident(std::string name, const PointRef& p, const PointRef& q);
  Result<int> addPointOnPlane(std::string name, const PointRef& p, const Plane& plane);
  Result<int> addPointOnLine(std::string name, const PointRef& p, const Axis& line);
  Result<int> addDistance(std::string name, const PointRef& p, const PointRef& q, Target distance);
  Result<int> addAngle(std::string name, const DirectionRef& d, const DirectionRef& e,
                       Target radians);
  Result<int> addParallel(std::string name, const DirectionRef& d, const DirectionRef& e);
  Result<int> addPerpendicular(std::string name, const DirectionRef& d, const DirectionRef& e);
  Result<int> addCoaxial(std::string name, const Axis& a, const Axis& b);
  /// The distance between the shapes of bodies a and b (world excluded) held at `clearance`
  /// (>= 0; 0: touching) through the problem's separation query. The gradient comes from the
  /// closest points; where the shapes touch or overlap it comes from the query's depth and
  /// normal, or else from the last direction seen apart.
  Result<int> addClearance(std::string name, int body_a, int body_b, Target clearance);

  /// The query clearance constraints measure with; solve() refuses them without one.
  void setSeparationQuery(std::shared_ptr<SeparationQuery> query) { query_ = std::move(query); }
  SeparationQuery* separationQuery() const { return query_.get(); }

  double lengthScale() const { return length_scale_; }
  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<Variable>& variables() const { return variables_; }
  const std::vector<Constraint>& constraints() const { return constraints_; }

  /// The solver's write access: the state it found, or the one it restores.
  std::vector<Body>& mutableBodies() { return bodies_; }
  std::vector<Variable>& mutableVariables() { return variables_; }

 private:
  Status checkName(const std::string& what, const std::string& name) const;
  Status checkPoint(const std::string& name, const char* field, const PointRef& point) const;
  Status checkDirection(const std::string& name, const char* field, DirectionRef& direction) const;
  Status checkTarget(const std::string& name, const Target& target) const;
  Result<int> add(Constraint constraint);

  double length_scale_;
  std::vector<Body> bodies_;
  std::vector<Variable> variables_;
  std::vector<Constraint> constraints_;
  std::shared_ptr<SeparationQuery> query_;
  /// Every name in use, with what holds it: names are unique among all three.
  std::unordered_map<std::string, const char*> names_;
};

}  // namespace collido::constraints
