#include "rotation.h"

#include <cmath>

namespace collido::constraints::detail {
namespace {

/// (1 − cos θ) / θ², as 2 sin²(θ/2) / θ²: 1 − cos θ loses most digits for small θ (at θ = 1e-6
/// about four), and the Hessians by differences step the rotation by about that.
double oneMinusCosOverSquare(double angle) {
  const double half_sine = std::sin(0.5 * angle);
  return 2.0 * half_sine * half_sine / (angle * angle);
}

}  // namespace

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
         oneMinusCosOverSquare(angle) * k * k;
}

Eigen::Matrix3d rightJacobian(const Eigen::Vector3d& omega) {
  const double angle_squared = omega.squaredNorm();
  const Eigen::Matrix3d k = skew(omega);
  if (angle_squared < 1e-16) return Eigen::Matrix3d::Identity() - 0.5 * k + k * k / 6.0;
  const double angle = std::sqrt(angle_squared);
  // (θ − sin θ) / θ³ cancels like 1 − cos θ; below 1e-2 its series is exact to rounding.
  const double third =
      angle < 1e-2 ? 1.0 / 6.0 - angle_squared / 120.0 + angle_squared * angle_squared / 5040.0
                   : (angle - std::sin(angle)) / (angle_squared * angle);
  return Eigen::Matrix3d::Identity() - oneMinusCosOverSquare(angle) * k + third * k * k;
}

}  // namespace collido::constraints::detail
