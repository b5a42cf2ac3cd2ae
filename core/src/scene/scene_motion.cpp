#include "scene_motion.h"

#include <algorithm>
#include <cmath>

#include <collido/random/portable_random.h>

namespace collido {
namespace {

// Scenes' poses must be the same with any standard library (PortableRandom says why).
using Sampler = PortableRandom;

}  // namespace

std::vector<Pose> randomOverlapPoses(const RandomOverlapMotion& spec,
                                     const TriangleMesh& reference_mesh,
                                     const std::vector<Pose>& reference_poses,
                                     const TriangleMesh& mesh, const Pose& base,
                                     std::size_t frames) {
  Sampler sampler(spec.seed);
  const BoundingSphere reference = boundingSphere(reference_mesh);
  const BoundingSphere own = boundingSphere(mesh);
  std::vector<Pose> poses;
  poses.reserve(frames);
  for (std::size_t f = 0; f < frames; ++f) {
    const Pose& reference_pose =
        reference_poses.size() == 1 ? reference_poses[0] : reference_poses[f];
    const Eigen::Matrix3d rotation = sampler.rotation() * base.linear();
    const Eigen::Vector3d direction = sampler.direction();
    const double overlap = sampler.uniform(spec.overlap_low, spec.overlap_high);
    const double distance = (1.0 - overlap) * (reference.radius + own.radius);
    const Eigen::Vector3d target = reference_pose * reference.centre + distance * direction;
    Pose pose = Pose::Identity();
    pose.linear() = rotation;
    pose.translation() = target - rotation * own.centre;
    poses.push_back(pose);
  }
  return poses;
}

std::vector<Pose> jitterPoses(const JitterMotion& spec, const Pose& base, std::size_t frames) {
  Sampler sampler(spec.seed);
  std::vector<Pose> poses;
  poses.reserve(frames);
  for (std::size_t f = 0; f < frames; ++f) {
    const Eigen::Vector3d axis = sampler.direction();
    const double angle = sampler.uniform(0.0, spec.rotation_deg) * M_PI / 180.0;
    const Eigen::Vector3d shift(sampler.uniform(-spec.translation, spec.translation),
                                sampler.uniform(-spec.translation, spec.translation),
                                sampler.uniform(-spec.translation, spec.translation));
    Pose pose = base;
    pose.linear() = Eigen::AngleAxisd(angle, axis).toRotationMatrix() * base.linear();
    pose.translation() = base.translation() + shift;
    poses.push_back(pose);
  }
  return poses;
}

std::vector<Pose> linearPoses(const LinearMotion& spec, std::size_t frames) {
  std::vector<Pose> poses;
  poses.reserve(frames);
  const bool same_rotation = spec.from.linear() == spec.to.linear();
  const Eigen::Quaterniond from_rotation(spec.from.linear());
  const Eigen::Quaterniond to_rotation(spec.to.linear());
  for (std::size_t f = 0; f < frames; ++f) {
    // The ends are the given poses themselves, not the interpolation's rounding of them.
    if (f == 0) {
      poses.push_back(spec.from);
      continue;
    }
    if (f + 1 == frames) {
      poses.push_back(spec.to);
      continue;
    }
    const double s = static_cast<double>(f) / static_cast<double>(frames - 1);
    Pose pose = Pose::Identity();
    // (to - from) f / (F - 1), multiplied before dividing: when the step is a multiple of F - 1
    // in binary (e.g. 23 * 2^-9 over 24 frames) every operation is exact, so a scene can put a
    // frame exactly at a contact whatever the rounding mode or FMA contraction.
    pose.translation() =
        spec.from.translation() + (spec.to.translation() - spec.from.translation()) *
                                      static_cast<double>(f) / static_cast<double>(frames - 1);
    // Eigen's slerp takes the shorter arc (it flips the sign of one quaternion when their dot
    // product is negative); normalising keeps the matrix a rotation to rounding.
    pose.linear() = same_rotation
                        ? Eigen::Matrix3d(spec.from.linear())
                        : from_rotation.slerp(s, to_rotation).normalized().toRotationMatrix();
    poses.push_back(pose);
  }
  return poses;
}

std::vector<Pose> keyframePoses(const std::vector<Keyframe>& keys, std::size_t frames) {
  std::vector<Pose> poses(frames, keys.front().pose);
  for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
    const std::size_t first = keys[k].frame;
    const std::vector<Pose> span =
        linearPoses(LinearMotion{keys[k].pose, keys[k + 1].pose}, keys[k + 1].frame - first + 1);
    std::copy(span.begin(), span.end(), poses.begin() + static_cast<std::ptrdiff_t>(first));
  }
  std::fill(poses.begin() + static_cast<std::ptrdiff_t>(keys.back().frame), poses.end(),
            keys.back().pose);
  return poses;
}

std::vector<Pose> jointPoses(const JointMotion& spec, std::size_t frames) {
  std::vector<Pose> poses;
  poses.reserve(frames);
  std::size_t key = 0;
  for (std::size_t f = 0; f < frames; ++f) {
    while (key + 1 < spec.keys.size() && spec.keys[key + 1].first <= f)
      ++key;
    double degrees = spec.keys[key].second;
    if (key + 1 < spec.keys.size() && f > spec.keys[key].first) {
      const auto [f0, d0] = spec.keys[key];
      const auto [f1, d1] = spec.keys[key + 1];
      degrees = d0 + (d1 - d0) * static_cast<double>(f - f0) / static_cast<double>(f1 - f0);
    }
    Pose turn = Pose::Identity();
    turn.linear() = Eigen::AngleAxisd(degrees * M_PI / 180.0, spec.axis).toRotationMatrix();
    turn.translation() = spec.origin - turn.linear() * spec.origin;
    poses.push_back(spec.base * turn);
  }
  return poses;
}

}  // namespace collido
