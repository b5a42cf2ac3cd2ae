#include "point_fit.h"

#include <Eigen/SVD>

namespace collido::pose::detail {

Eigen::Vector3d weightedCentroid(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& weights) {
  return points * weights / weights.sum();
}

Eigen::Vector3d layoutSpread(const PointSet& set) {
  const Eigen::Vector3d centre = weightedCentroid(set.model, set.weights);
  Eigen::Matrix3Xd centred = set.model.colwise() - centre;
  for (Eigen::Index i = 0; i < centred.cols(); ++i)
    centred.col(i) *= std::sqrt(set.weights(i));
  // The spread is the square root of the eigenvalues of the 3x3 scatter matrix.
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(centred * centred.transpose());
  return svd.singularValues().cwiseMax(0.0).cwiseSqrt();
}

Eigen::Affine3d fitRigid(const PointSet& set) {
  const Eigen::Vector3d p_bar = weightedCentroid(set.model, set.weights);
  const Eigen::Vector3d q_bar = weightedCentroid(set.world, set.weights);
  Eigen::Matrix3d cross = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < set.model.cols(); ++i) {
    cross += set.weights(i) * (set.model.col(i) - p_bar) * (set.world.col(i) - q_bar).transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cross, Eigen::ComputeFullU | Eigen::ComputeFullV);
  // A reflection fits a mirrored layout better than any rotation; the last axis is flipped
  // so the answer stays a rotation (Umeyama 1991).
  Eigen::Vector3d signs(1.0, 1.0, 1.0);
  if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0) signs(2) = -1.0;
  const Eigen::Matrix3d rotation = svd.matrixV() * signs.asDiagonal() * svd.matrixU().transpose();
  Eigen::Affine3d map = Eigen::Affine3d::Identity();
  map.linear() = rotation;
  map.translation() = q_bar - rotation * p_bar;
  return map;
}

Eigen::Affine3d fitAffine(const PointSet& set, Eigen::Matrix4d* normal_inverse) {
  const Eigen::Vector3d p_bar = weightedCentroid(set.model, set.weights);
  Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
  Eigen::Matrix<double, 4, 3> right = Eigen::Matrix<double, 4, 3>::Zero();
  for (Eigen::Index i = 0; i < set.model.cols(); ++i) {
    Eigen::Vector4d a;
    a << set.model.col(i) - p_bar, 1.0;
    normal += set.weights(i) * a * a.transpose();
    right += set.weights(i) * a * set.world.col(i).transpose();
  }
  const Eigen::FullPivLU<Eigen::Matrix4d> lu(normal);
  // Row k of M solves normal * m_k = right.col(k): three systems over one matrix.
  Eigen::Matrix<double, 3, 4> rows;
  for (int k = 0; k < 3; ++k)
    rows.row(k) = lu.solve(right.col(k)).transpose();
  if (normal_inverse != nullptr) *normal_inverse = lu.inverse();
  // world = L (p - p_bar) + c  =>  linear L, translation c - L p_bar.
  Eigen::Affine3d map = Eigen::Affine3d::Identity();
  map.linear() = rows.leftCols<3>();
  map.translation() = rows.col(3) - map.linear() * p_bar;
  return map;
}

Eigen::VectorXd residuals(const Eigen::Affine3d& map, const PointSet& set) {
  Eigen::VectorXd out(set.model.cols());
  for (Eigen::Index i = 0; i < set.model.cols(); ++i)
    out(i) = (map * set.model.col(i) - set.world.col(i)).norm();
  return out;
}

}  // namespace collido::pose::detail
