#include <algorithm>
#include <cmath>
#include <limits>

#include <collido/scene/scene.h>

namespace collido {

double Scene::trackingSpreadAt(std::size_t object, const TriangleMesh& shape,
                               std::size_t frame) const {
  const SceneObject& o = objects[object];
  if (o.tracking) return o.tracking->frames[frame].sigma;
  if (!o.tracked_ancestor) return 0.0;
  const SceneObject& ancestor = objects[*o.tracked_ancestor];
  if (!ancestor.tracking) return 0.0;  // a scene at its true poses
  // The object rides on the ancestor's recovered pose, so a fitting error of the ancestor moves
  // it as a rigid extension: its corners, in the ancestor's frame, spread as the fit predicts
  // for points there (further from the markers, further moved by a rotation error).
  const pose::PoseEstimate& fit = ancestor.tracking->frames[frame].estimate;
  const Pose to_ancestor = ancestor.poseAt(frame).inverse() * o.poseAt(frame);
  const Eigen::Vector3d low = shape.vertices.rowwise().minCoeff();
  const Eigen::Vector3d high = shape.vertices.rowwise().maxCoeff();
  double spread = 0.0;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d corner((k & 1) != 0 ? high.x() : low.x(),
                                 (k & 2) != 0 ? high.y() : low.y(),
                                 (k & 4) != 0 ? high.z() : low.z());
    const double sigma = fit.pointSigma(to_ancestor * corner);
    if (std::isnan(sigma)) return std::numeric_limits<double>::quiet_NaN();
    spread = std::max(spread, sigma);
  }
  return spread;
}

}  // namespace collido
