#pragma once

#include <Eigen/Core>

namespace collido::constraints::detail {

/// [v]×: the matrix with [v]× w = v × w.
Eigen::Matrix3d skew(const Eigen::Vector3d& v);

/// The rotation by |ω| radians about ω (Rodrigues), exact near ω = 0.
Eigen::Matrix3d expMap(const Eigen::Vector3d& omega);

/// The right Jacobian of exp: exp(ω + δ) = exp(ω) exp(J_r(ω) δ) to first order in δ.
Eigen::Matrix3d rightJacobian(const Eigen::Vector3d& omega);

}  // namespace collido::constraints::detail
