#pragma once

#include <Eigen/Geometry>

#include <collido/geometry.h>

namespace collido::pose {

/// How far a recovered pose is from the true one.
struct PoseError {
  double rotation_deg = 0.0;  ///< angle of R_true^T R_recovered
  double translation = 0.0;   ///< |t_recovered - t_true|
  double worst_vertex = 0.0;  ///< largest |recovered * v - truth * v| over the given points
};

/// The error of `recovered` (a rigid pose, or an affine fit's map) against `truth` over
/// `points` (the object's mesh vertices, its own frame). The rotation angle uses the nearest
/// rotation of recovered's linear part.
PoseError poseError(const Eigen::Affine3d& recovered, const Pose& truth,
                    const Eigen::Ref<const Eigen::Matrix3Xd>& points);

}  // namespace collido::pose
