#include <collido/motion.h>

#include <algorithm>
#include <cmath>

namespace collido {

Status checkRigidPose(const Pose& pose, const std::string& what) {
  const Eigen::Matrix3d rotation = pose.linear();
  if (!rotation.allFinite() || !pose.translation().allFinite()) {
    return {StatusCode::kInvalidArgument, what + ": pose has a non-finite entry"};
  }
  const double drift = (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm();
  if (drift > 1e-6 || rotation.determinant() < 0.0) {
    return {StatusCode::kInvalidArgument,
            what + ": not a rotation (|R^T R - I| = " + std::to_string(drift) +
                ", det = " + std::to_string(rotation.determinant()) +
                "; a pose must be rigid: orthonormal, determinant +1)"};
  }
  return {};
}

Result<StepMotion> StepMotion::between(const Pose& start, const Pose& end,
                                       const std::string& what) {
  if (Status s = checkRigidPose(start, what + ": start of the step"); !s.ok()) return s;
  if (Status s = checkRigidPose(end, what + ": end of the step"); !s.ok()) return s;
  return StepMotion(start, end);
}

StepMotion::StepMotion(const Pose& start, const Pose& end)
    : start_(start),
      end_(end),
      translation_length_((end.translation() - start.translation()).norm()) {
  // The turn from start to end in the world frame; Eigen takes the angle in [0, pi].
  const Eigen::AngleAxisd turn(Eigen::Matrix3d(end.linear() * start.linear().transpose()));
  angle_ = std::abs(turn.angle());
  if (angle_ > 0.0) axis_ = turn.angle() < 0.0 ? Eigen::Vector3d(-turn.axis()) : turn.axis();
}

Pose StepMotion::at(double t) const {
  // One formula over the whole step, t = 1 included, so the path has no jump at its end where
  // the end pose is not exactly the turned start (a rotation off by rounding).
  t = std::clamp(t, 0.0, 1.0);
  Pose pose = Pose::Identity();
  pose.linear() = Eigen::AngleAxisd(t * angle_, axis_).toRotationMatrix() * start_.linear();
  pose.translation() = start_.translation() + t * (end_.translation() - start_.translation());
  return pose;
}

}  // namespace collido
