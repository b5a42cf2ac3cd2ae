#include <collido/pose/pose_error.h>

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

namespace collido::pose {

PoseError poseError(const Eigen::Affine3d& recovered, const Pose& truth,
                    const Eigen::Ref<const Eigen::Matrix3Xd>& points) {
  PoseError error;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(recovered.linear(),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d signs(1.0, 1.0, 1.0);
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0) signs(2) = -1.0;
  const Eigen::Matrix3d rotation = svd.matrixU() * signs.asDiagonal() * svd.matrixV().transpose();
  const Eigen::AngleAxisd difference(truth.linear().transpose() * rotation);
  error.rotation_deg = std::abs(difference.angle()) * 180.0 / M_PI;
  error.translation = (recovered.translation() - truth.translation()).norm();
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    error.worst_vertex =
        std::max(error.worst_vertex, (recovered * points.col(i) - truth * points.col(i)).norm());
  }
  return error;
}

}  // namespace collido::pose
