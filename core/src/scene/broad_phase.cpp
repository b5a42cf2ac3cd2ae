#include <algorithm>
#include <limits>

#include <collido/scene/broad_phase.h>

namespace collido {
namespace {

// Relative enlargement of every box: far above the rounding of the handful of operations that
// compute it (each within a few units of 2^-53 of the magnitudes involved).
constexpr double kRelativeMargin = 1e-12;

struct WorldBox {
  std::size_t object = 0;
  Eigen::Vector3d low;
  Eigen::Vector3d high;
};

}  // namespace

BroadPhase::BroadPhase(const Scene& scene, const SceneQuery& query) : scene_(scene), query_(query) {
  for (std::size_t index : query.objects()) {
    const SceneObject& object = scene.objects[index];
    LocalBox box;
    box.object = index;
    // A changing shape is bounded over every frame: one box for the whole scene.
    Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d high = -low;
    const auto extend = [&](const Eigen::Matrix3Xd& v) {
      if (v.cols() == 0) return;
      low = low.cwiseMin(v.rowwise().minCoeff());
      high = high.cwiseMax(v.rowwise().maxCoeff());
    };
    extend(object.mesh->vertices);
    if (object.changesShape()) {
      for (std::size_t f = 0; f < scene.frames; ++f)
        extend(object.shapeAt(f)->vertices);
    }
    if ((low.array() <= high.array()).all()) {
      box.centre = 0.5 * (low + high);
      box.half = 0.5 * (high - low) + kRelativeMargin * (low.cwiseAbs().cwiseMax(high.cwiseAbs()));
    }
    boxes_.push_back(box);
  }
}

std::vector<std::pair<std::size_t, std::size_t>> BroadPhase::pairsAt(std::size_t frame) const {
  std::vector<WorldBox> world;
  world.reserve(boxes_.size());
  for (const LocalBox& box : boxes_) {
    if (!scene_.objects[box.object].present.contains(frame)) continue;
    const Pose& pose = scene_.objects[box.object].poseAt(frame);
    const Eigen::Matrix3d r = pose.linear();
    const Eigen::Vector3d t = pose.translation();
    const Eigen::Vector3d centre = r * box.centre + t;
    const Eigen::Vector3d half =
        r.cwiseAbs() * box.half +
        kRelativeMargin * (r.cwiseAbs() * (box.centre.cwiseAbs() + box.half) + t.cwiseAbs() +
                           Eigen::Vector3d::Constant(1e-300));
    world.push_back(WorldBox{box.object, centre - half, centre + half});
  }
  std::sort(world.begin(), world.end(),
            [](const WorldBox& l, const WorldBox& r) { return l.low.x() < r.low.x(); });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < world.size(); ++i) {
    for (std::size_t j = i + 1; j < world.size() && world[j].low.x() <= world[i].high.x(); ++j) {
      const WorldBox& p = world[i];
      const WorldBox& q = world[j];
      if (p.low.y() <= q.high.y() && q.low.y() <= p.high.y() && p.low.z() <= q.high.z() &&
          q.low.z() <= p.high.z() && query_.asksPair(p.object, q.object)) {
        pairs.emplace_back(std::min(p.object, q.object), std::max(p.object, q.object));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace collido
