#pragma once

#include <string>

#include <collido/geometry.h>
#include <collido/status.h>

namespace collido {

/// How one object moves over a step, from its pose in frame k (t = 0) to its pose in frame k+1
/// (t = 1): its origin moves along the straight line between the two at a constant rate, and it
/// turns at a constant rate about one fixed axis through its origin, by the rotation between the
/// two poses taken the short way (an angle in [0, pi]). This is FCL's interpolated motion
/// (InterpMotion) with the reference point at the object's origin, and what a planner's linear
/// interpolation with slerp does, so every backend and the oracle follow the same path.
class StepMotion {
 public:
  /// The motion from `start` to `end`; refused, naming `what`, when a pose has an entry that is
  /// not finite or a rotation that is not one (|R^T R - I| above 1e-6, or a reflection).
  static Result<StepMotion> between(const Pose& start, const Pose& end, const std::string& what);

  /// The pose at t, clamped to [0, 1]: `start` at 0, `end` at 1 up to rounding.
  Pose at(double t) const;

  /// A bound on how far, per unit of t, any point within `radius` of the object's origin moves:
  /// the origin's speed plus the turning rate times the radius.
  double speedBound(double radius) const { return translation_length_ + angle_ * radius; }

  const Pose& start() const { return start_; }
  const Pose& end() const { return end_; }
  double angle() const { return angle_; }  ///< radians turned over the step, in [0, pi]

 private:
  StepMotion(const Pose& start, const Pose& end);

  Pose start_;
  Pose end_;
  Eigen::Vector3d axis_ = Eigen::Vector3d::UnitZ();  ///< world frame, unit
  double angle_ = 0.0;
  double translation_length_ = 0.0;
};

/// The poses' check StepMotion::between makes, for callers that receive a single pose: empty
/// when `pose` is rigid, else what is wrong with it, prefixed by `what`.
Status checkRigidPose(const Pose& pose, const std::string& what);

}  // namespace collido
