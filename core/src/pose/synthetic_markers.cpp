#include <collido/pose/synthetic_markers.h>

namespace collido::pose {

std::vector<MarkerObservation> observeMarkers(const MarkerLayout& layout, const Pose& truth,
                                              const MarkerNoise& noise, PortableRandom& random) {
  std::vector<MarkerObservation> seen;
  seen.reserve(layout.size());
  for (const auto& [id, point] : layout) {
    const double dropped = random.uniform();
    const double swapped = random.uniform();
    Eigen::Vector3d error;
    for (int k = 0; k < 3; ++k) {
      const double n = random.normal();  // one draw per statement: a fixed order
      error(k) = noise.noise * n;
    }
    const Eigen::Vector3d away = random.direction();
    if (dropped < noise.dropout) continue;
    MarkerObservation o;
    o.id = id;
    o.position = truth * point + error;
    if (swapped < noise.outliers) o.position += noise.outlier_offset * away;
    seen.push_back(o);
  }
  return seen;
}

}  // namespace collido::pose
