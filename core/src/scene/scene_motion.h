#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>

namespace collido {

/// Random poses of an object around a reference object, with a target overlap of their bounding
/// spheres: each frame draws a uniform random rotation, a uniform random direction, and an
/// overlap o in [overlap_low, overlap_high]; the object's bounding-sphere centre is placed at
/// distance (1 - o) * (r_reference + r_object) from the reference's, so o = 0 means the spheres
/// just touch and o = 1 that the centres coincide.
struct RandomOverlapMotion {
  std::uint64_t seed = 1;
  double overlap_low = 0.5;
  double overlap_high = 0.5;
};

/// Random perturbations of a base pose: per frame a rotation about a uniform random axis by an
/// angle uniform in [0, rotation_deg], about the object's origin, and a translation uniform in
/// the cube [-translation, translation]^3.
struct JitterMotion {
  std::uint64_t seed = 1;
  double translation = 0.0;
  double rotation_deg = 0.0;
};

/// A straight approach between two poses: frame f of F has the translation
/// from + ((to - from) f) / (F - 1) (in that order) and the rotation slerp(from, to, f / (F - 1))
/// (the shorter arc between the two orientations). Frame 0 is `from` and frame F - 1 is `to`,
/// exactly as given; with one frame it is `from`. When both rotations are equal, every frame keeps
/// that rotation exactly, and a translation component equal at both ends stays exactly that value.
struct LinearMotion {
  Pose from = Pose::Identity();
  Pose to = Pose::Identity();
};

/// A pose at a frame of a keyframed motion.
struct Keyframe {
  std::size_t frame = 0;
  Pose pose = Pose::Identity();
};

/// A revolute joint (a manipulator link on its parent): the pose is
/// base * T(origin) * R(axis, angle) * T(-origin), about `axis` through `origin` (both in the
/// object's own frame), the angle piecewise linear between keys of (frame, degrees).
struct JointMotion {
  Pose base = Pose::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< unit length
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::vector<std::pair<std::size_t, double>> keys;  ///< (frame, degrees), frames increasing
};

/// One pose per frame. The reference's poses have one entry per frame or one for all; the
/// object's `base` rotation is composed with the random one (so a shape's own orientation is
/// kept in the mix). Deterministic for a seed on every platform (own sampling on mt19937_64).
std::vector<Pose> randomOverlapPoses(const RandomOverlapMotion& spec,
                                     const TriangleMesh& reference_mesh,
                                     const std::vector<Pose>& reference_poses,
                                     const TriangleMesh& mesh, const Pose& base,
                                     std::size_t frames);

/// One pose per frame around `base`.
std::vector<Pose> jitterPoses(const JitterMotion& spec, const Pose& base, std::size_t frames);

/// One pose per frame from `spec.from` to `spec.to`.
std::vector<Pose> linearPoses(const LinearMotion& spec, std::size_t frames);

/// One pose per frame through `keys` (at least one, frames increasing and below `frames`):
/// between two consecutive keys as LinearMotion between them (each key exactly as given), held
/// before the first key and after the last.
std::vector<Pose> keyframePoses(const std::vector<Keyframe>& keys, std::size_t frames);

/// One pose per frame of the joint (keys as for keyframePoses; the angle held at the ends).
std::vector<Pose> jointPoses(const JointMotion& spec, std::size_t frames);

}  // namespace collido
