// Generated marker tracks and the recovered poses of a tracked object.
#include <collido/scene/marker_tracking.h>

#include <algorithm>
#include <cmath>

#include <collido/pose/synthetic_markers.h>
#include <collido/random/portable_random.h>

namespace collido {

std::size_t MarkerTracking::lostFrames() const {
  return static_cast<std::size_t>(
      std::count_if(frames.begin(), frames.end(), [](const TrackedFrame& f) { return f.lost; }));
}

std::vector<std::vector<pose::MarkerObservation>> generateTracks(
    const pose::MarkerLayout& layout, const std::vector<Pose>& true_poses,
    const TrackNoise& noise) {
  PortableRandom random(noise.seed);
  std::vector<std::vector<pose::MarkerObservation>> frames;
  frames.reserve(true_poses.size());
  for (const Pose& truth : true_poses)
    frames.push_back(pose::observeMarkers(layout, truth, noise, random));
  return frames;
}

Result<std::vector<Pose>> recoverPoses(MarkerTracking& tracking,
                                       const std::vector<Eigen::Vector3d>& box_corners) {
  std::vector<Pose> poses;
  poses.reserve(tracking.frames.size());
  for (std::size_t f = 0; f < tracking.frames.size(); ++f) {
    TrackedFrame& frame = tracking.frames[f];
    const Result<pose::PoseEstimate> fit =
        pose::fitPose(tracking.layout, frame.observed, tracking.fit);
    if (!fit.ok()) {
      if (f == 0) {
        return Status(StatusCode::kInvalidArgument,
                      "frame 0: " + fit.status().message() +
                          " (the first frame must fit: there is no earlier pose to hold)");
      }
      frame.lost = true;
      frame.problem = fit.status().message();
      poses.push_back(poses.back());
      continue;
    }
    const pose::PoseEstimate& estimate = fit.value();
    frame.outliers = estimate.outliers;
    frame.rms_residual = estimate.rms_residual;
    frame.sigma = 0.0;
    for (const Eigen::Vector3d& corner : box_corners) {
      const double sigma = estimate.pointSigma(corner);
      frame.sigma = std::isnan(sigma) ? sigma : std::max(frame.sigma, sigma);
      if (std::isnan(sigma)) break;
    }
    poses.push_back(estimate.pose);
    frame.estimate = estimate;
  }
  return poses;
}

}  // namespace collido
