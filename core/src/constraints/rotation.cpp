#include "rotation.h"

#include <cmath>

namespace collido::constraints::detail {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

Eigen::Matrix3d expMap(const Eigen::Vector3d& omega) {
  const double angle_squared = omega.squaredNorm();
  const Eigen::Matrix3d k = skew(omega);
  // Below 1e-8 rad the series' next terms are under double precision.
  if (angle_squared < 1e-16) return Eigen::Matrix3d::Identity() + k + 0.5 * k * k;
  const double angle = std::sqrt(angle_squared);
  return Eigen::Matrix3d::Identity() + (std::sin(angle) / angle) * k +
         ((1.0 - std::cos(angle)) / angle_squared) * k * k;
}

Eigen::Matrix3d rightJacobian(const Eigen::Vector3d& omega) {
  const double angle_squared = omega.squaredNorm();
  const Eigen::Matrix3d k = skew(omega);
  if (angle_squared < 1e-16) return Eigen::Matrix3d::Identity() - 0.5 * k + k * k / 6.0;
  const double angle = std::sqrt(angle_squared);
  return Eigen::Matrix3d::Identity() - ((1.0 - std::cos(angle)) / angle_squared) * k +
         ((angle - std::sin(angle)) / (angle_squared * angle)) * k * k;
}

}  // namespace collido::constraints::detail
