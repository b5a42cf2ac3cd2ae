#include <collido/scene/tracking_summary.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include <collido/pose/pose_error.h>

namespace collido {
namespace {

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

double largest(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

}  // namespace

TrackingSummary summarizeTracking(const SceneObject& object) {
  const MarkerTracking& tracking = *object.tracking;
  TrackingSummary summary;
  summary.frames = tracking.frames.size();
  std::vector<double> rotation;
  std::vector<double> translation;
  std::vector<double> worst;
  std::vector<double> sigma;
  double seen = 0.0;
  for (std::size_t f = 0; f < tracking.frames.size(); ++f) {
    const TrackedFrame& frame = tracking.frames[f];
    summary.lost += frame.lost ? 1 : 0;
    summary.outliers += frame.outliers.size();
    seen += static_cast<double>(frame.observed.size());
    const pose::PoseError error = pose::poseError(Eigen::Affine3d(object.poseAt(f).matrix()),
                                                  tracking.true_poses[f], object.mesh->vertices);
    rotation.push_back(error.rotation_deg);
    translation.push_back(error.translation);
    worst.push_back(error.worst_vertex);
    if (!std::isnan(frame.sigma)) sigma.push_back(frame.sigma);
  }
  summary.markers_seen = summary.frames == 0 ? 0.0 : seen / static_cast<double>(summary.frames);
  summary.rotation_deg_median = median(rotation);
  summary.rotation_deg_max = largest(rotation);
  summary.translation_median = median(translation);
  summary.translation_max = largest(translation);
  summary.worst_vertex_median = median(worst);
  summary.worst_vertex_max = largest(worst);
  summary.sigma_median = median(sigma);
  return summary;
}

std::string TrackingSummary::text(const MarkerTracking& tracking) const {
  std::ostringstream out;
  out.precision(3);
  out << tracking.layout.size() << " markers (" << tracking.source << "), "
      << pose::poseSolverName(tracking.fit.solver) << " fit"
      << (tracking.fit.reject_outliers ? " with outlier rejection" : "") << ": " << markers_seen
      << " seen a frame, " << outliers << " rejected, " << lost << " of " << frames
      << " frames lost; error against the true poses: worst vertex median " << worst_vertex_median
      << " (max " << worst_vertex_max << "), rotation median " << rotation_deg_median
      << " deg (max " << rotation_deg_max << "), translation median " << translation_median
      << " (max " << translation_max << "); predicted spread median " << sigma_median;
  return out.str();
}

}  // namespace collido
