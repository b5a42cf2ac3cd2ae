#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <collido/geometry.h>
#include <collido/status.h>

namespace collido::pose {

/// The markers fixed on one object: id → position in the object's own frame.
using MarkerLayout = std::map<int, Eigen::Vector3d>;

/// One marker as the tracker saw it in one frame (world frame). A marker not seen that frame
/// has no observation.
struct MarkerObservation {
  int id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double weight = 1.0;  ///< tracking confidence, > 0; the fits minimise weighted squares
};

/// How the transform is fitted to the markers.
enum class PoseSolver {
  /// The dissertation's method: least squares for the 12 coefficients of a 3x4 affine map,
  /// three independent 4x4 linear systems (one per row). Needs 4 markers not in one plane.
  kAffine,
  /// A rotation and a translation (weighted Horn/Umeyama by SVD). Needs 3 markers not on a line.
  kRigid,
};

/// "affine" or "rigid".
const char* poseSolverName(PoseSolver solver);

/// Options of fitPose.
struct FitOptions {
  PoseSolver solver = PoseSolver::kRigid;
  /// Reject markers the tracker mis-identified: RANSAC over minimal marker sets (every set when
  /// there are few, else `ransac_iterations` seeded draws), then a fit on the largest consensus.
  bool reject_outliers = false;
  double inlier_threshold = 0.0;  ///< with reject_outliers: a marker's residual limit, > 0
  int ransac_iterations = 500;
  std::uint64_t seed = 1;
  /// Degeneracy: the marker layout's condition number (largest over the smallest singular value
  /// of the centred marker positions that the solver needs: the second for the rigid fit, the
  /// third for the affine) must not exceed this.
  double max_condition = 1e6;
  /// Known marker noise (standard deviation per axis); 0: estimated from the residuals.
  double noise_sigma = 0.0;
};

/// A fitted pose, with what the fit says about its quality.
struct PoseEstimate {
  PoseSolver solver = PoseSolver::kRigid;
  /// The fitted map, object frame → world: rigid for kRigid, the 12 coefficients for kAffine.
  Eigen::Affine3d transform = Eigen::Affine3d::Identity();
  /// The rigid pose that drives the collision query: the fit itself for kRigid; for kAffine the
  /// rotation of the linear part's polar decomposition, placed so that the markers' weighted
  /// centroid maps where the affine map sends it.
  Pose pose = Pose::Identity();
  std::vector<int> inliers;   ///< marker ids the final fit used, ascending
  std::vector<int> outliers;  ///< marker ids rejected (reject_outliers), ascending
  double rms_residual = 0.0;  ///< over the inliers: sqrt(weighted mean of squared residuals)
  double max_residual = 0.0;  ///< over the inliers
  double condition = 0.0;     ///< the layout's condition number (FitOptions::max_condition)
  double noise_sigma = 0.0;   ///< per-axis marker noise used for the uncertainty
  /// Uncertainty: for kRigid the 6x6 covariance of (small rotation vector [rad], translation);
  /// for kAffine the 4x4 matrix C with each fitted row's covariance = C (every row alike, rows
  /// acting on [p - model_centroid; 1]). Empty when the noise is unknown (no redundant marker
  /// and no FitOptions::noise_sigma).
  Eigen::MatrixXd covariance;
  Eigen::Vector3d model_centroid = Eigen::Vector3d::Zero();  ///< inliers' weighted, object frame

  /// The standard deviation (per axis, RMS over the three) of where the fitted map puts the
  /// object point `p`, from the covariance: what tracking noise does to that point. NaN when
  /// the covariance is unknown.
  double pointSigma(const Eigen::Vector3d& p) const;
};

/// Fits the object's pose to one frame's observations. Errors (kInvalidArgument) name the
/// problem and the markers: too few seen, an id not in the layout or seen twice, a non-finite
/// position, a weight <= 0, markers on a line (rigid and affine) or in one plane (affine), too
/// few inliers after rejection.
Result<PoseEstimate> fitPose(const MarkerLayout& layout,
                             const std::vector<MarkerObservation>& observed,
                             const FitOptions& options = {});

}  // namespace collido::pose
