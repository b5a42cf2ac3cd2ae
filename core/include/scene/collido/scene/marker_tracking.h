#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <collido/geometry.h>
#include <collido/pose/marker_fit.h>
#include <collido/pose/synthetic_markers.h>

namespace collido {

/// One frame of an object's tracking: what the fit had and made of it.
struct TrackedFrame {
  std::vector<pose::MarkerObservation> observed;  ///< the markers seen (none: all dropped)
  std::vector<int> outliers;                      ///< markers the fit rejected
  /// The fit failed (too few markers, a degenerate layout, no consensus): the object keeps the
  /// previous frame's recovered pose, as a tracker that lost the object would.
  bool lost = false;
  std::string problem;        ///< why, when lost
  double rms_residual = 0.0;  ///< of the fit, over its inliers
  /// The largest predicted spread (PoseEstimate::pointSigma) over the mesh's bounding-box
  /// corners, an upper bound over its vertices: how far tracking noise may move the mesh.
  /// NaN when unknown (no redundancy and no given noise) or lost.
  double sigma = std::numeric_limits<double>::quiet_NaN();
  /// The fit itself (no covariance when lost): the spread of points other than the corners,
  /// such as those of objects mounted on this one, comes from its covariance.
  pose::PoseEstimate estimate;
};

/// Where a tracked object's poses come from (scene key "markers"): its marker layout, the
/// observations per frame (a tracks file, or generated from the true motion with chosen noise,
/// dropouts and outliers) and the solver. SceneObject::poses holds the recovered poses, which
/// drive every query; `true_poses` the motion the scene describes (the ground truth).
struct MarkerTracking {
  pose::MarkerLayout layout;
  pose::FitOptions fit;
  std::vector<Pose> true_poses;  ///< one per frame
  std::vector<TrackedFrame> frames;
  std::string source;  ///< for people: the tracks file, or the generator's settings

  std::size_t lostFrames() const;
};

/// How generated tracks deviate from the truth (scene "markers": {"generate": ...}), and the
/// seed that makes them.
struct TrackNoise : pose::MarkerNoise {
  std::uint64_t seed = 1;
};

/// Observations of `layout` on an object moving through `true_poses`, per frame, with `noise`.
/// The same seed gives the same tracks with any standard library.
std::vector<std::vector<pose::MarkerObservation>> generateTracks(
    const pose::MarkerLayout& layout, const std::vector<Pose>& true_poses, const TrackNoise& noise);

/// Fits every frame of `tracking` (observations already in `tracking.frames`) and returns the
/// recovered poses, filling each frame's outcome; `box_corners` are the mesh's bounding-box
/// corners (object frame) for TrackedFrame::sigma. The first frame must fit (an error naming
/// it otherwise: there is no earlier pose to hold).
Result<std::vector<Pose>> recoverPoses(MarkerTracking& tracking,
                                       const std::vector<Eigen::Vector3d>& box_corners);

}  // namespace collido
