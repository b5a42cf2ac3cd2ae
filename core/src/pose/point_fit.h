// The two least-squares fits on matched point lists, without checks (marker_fit.cpp checks).
#pragma once

#include <Eigen/Geometry>

namespace collido::pose::detail {

/// Matched points: column i of `model` (object frame) was seen at column i of `world`.
struct PointSet {
  Eigen::Matrix3Xd model;
  Eigen::Matrix3Xd world;
  Eigen::VectorXd weights;
};

/// The weighted centroid of `points`.
Eigen::Vector3d weightedCentroid(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& weights);

/// Singular values (descending) of the model points centred on their weighted centroid, each
/// column scaled by sqrt(weight): how well the layout spans 1, 2 and 3 dimensions.
Eigen::Vector3d layoutSpread(const PointSet& set);

/// The rigid map minimising sum w |R p + t - q|^2 (weighted Horn/Umeyama by SVD of the
/// cross-covariance, reflection excluded). Needs 3 points not on a line.
Eigen::Affine3d fitRigid(const PointSet& set);

/// The dissertation's fit: the affine map minimising sum w |M [p; 1] - q|^2, each of M's three
/// rows from its own 4x4 normal equations (one matrix, factored once; model points centred
/// first, which changes nothing but the conditioning). Needs 4 points not in one plane.
/// `normal_inverse` receives the inverse of the centred normal matrix (for the uncertainty).
Eigen::Affine3d fitAffine(const PointSet& set, Eigen::Matrix4d* normal_inverse = nullptr);

/// |map * model_i - world_i| per point.
Eigen::VectorXd residuals(const Eigen::Affine3d& map, const PointSet& set);

}  // namespace collido::pose::detail
