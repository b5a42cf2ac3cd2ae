#include "motion_reader.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>

#include <collido/mesh/triangle_mesh.h>

#include "pose_reader.h"
#include "scene_motion.h"

namespace collido::scene_reading {
namespace {

std::vector<Pose> readPoseList(const Reader& r, const Node& list, std::size_t frames) {
  r.expectArray(list);
  if (list.value.size() != frames) {
    r.fail(list, "has " + std::to_string(list.value.size()) + " poses but the scene has " +
                     std::to_string(frames) + " frames");
  }
  std::vector<Pose> poses;
  for (std::size_t f = 0; f < list.value.size(); ++f)
    poses.push_back(readPose(r, list.at(f)));
  return poses;
}

RandomOverlapMotion readRandom(const Reader& r, const Node& random) {
  r.expectObject(random, {"seed", "relative_to", "overlap"});
  RandomOverlapMotion spec;
  spec.seed = static_cast<std::uint64_t>(r.integer(random, "seed", 1, 0, INT64_MAX));
  if (!random.has("overlap")) r.fail(random, "missing 'overlap'");
  const Node overlap = random.at("overlap");
  if (overlap.value.is_array()) {
    if (overlap.value.size() != 2) r.fail(overlap, "expected [low, high] or a number");
    spec.overlap_low = r.number(overlap.at(0));
    spec.overlap_high = r.number(overlap.at(1));
  } else {
    spec.overlap_low = spec.overlap_high = r.number(overlap);
  }
  if (!(spec.overlap_low >= 0.0 && spec.overlap_low <= spec.overlap_high &&
        spec.overlap_high <= 1.0)) {
    r.fail(overlap, "overlap must satisfy 0 <= low <= high <= 1");
  }
  return spec;
}

LinearMotion readLinear(const Reader& r, const Node& linear) {
  r.expectObject(linear, {"from", "to"});
  for (const char* end : {"from", "to"}) {
    if (!linear.has(end)) r.fail(linear, std::string("missing '") + end + "'");
  }
  return LinearMotion{readPose(r, linear.at("from")), readPose(r, linear.at("to"))};
}

JitterMotion readJitter(const Reader& r, const Node& jitter) {
  r.expectObject(jitter, {"seed", "translation", "rotation_deg"});
  JitterMotion spec;
  spec.seed = static_cast<std::uint64_t>(r.integer(jitter, "seed", 1, 0, INT64_MAX));
  spec.translation = r.number(jitter, "translation", 0.0);
  spec.rotation_deg = r.number(jitter, "rotation_deg", 0.0);
  if (spec.translation < 0.0 || spec.rotation_deg < 0.0 || spec.rotation_deg > 180.0) {
    r.fail(jitter, "translation must be >= 0 and rotation_deg in [0, 180]");
  }
  return spec;
}

// The frames of a list of keys: each in [0, frames), strictly increasing.
std::size_t readKeyFrame(const Reader& r, const Node& key, std::size_t frames,
                         std::optional<std::size_t> previous) {
  if (!key.has("frame")) r.fail(key, "missing 'frame'");
  const auto frame = static_cast<std::size_t>(
      r.integer(key.at("frame"), 0, static_cast<std::int64_t>(frames) - 1));
  if (previous && frame <= *previous) {
    r.fail(key.at("frame"), "frame " + std::to_string(frame) +
                                " does not come after the previous key's frame " +
                                std::to_string(*previous) + " (keys go in increasing frames)");
  }
  return frame;
}

std::vector<Keyframe> readKeyframes(const Reader& r, const Node& list, std::size_t frames) {
  r.expectArray(list);
  if (list.value.empty()) r.fail(list, "give at least one keyframe");
  std::vector<Keyframe> keys;
  for (std::size_t k = 0; k < list.value.size(); ++k) {
    const Node key = list.at(k);
    r.expectObject(key, {"frame", "pose"});
    const std::size_t frame = readKeyFrame(
        r, key, frames, keys.empty() ? std::nullopt : std::optional(keys.back().frame));
    if (!key.has("pose")) r.fail(key, "missing 'pose'");
    keys.push_back(Keyframe{frame, readPose(r, key.at("pose"))});
  }
  return keys;
}

JointMotion readJoint(const Reader& r, const Node& joint, const Pose& base, std::size_t frames) {
  r.expectObject(joint, {"axis", "origin", "keys"});
  JointMotion spec;
  spec.base = base;
  if (!joint.has("axis")) r.fail(joint, "missing 'axis' (the joint's axis, in the object's frame)");
  const Eigen::Vector3d axis = r.vector3(joint.at("axis"));
  if (!(axis.norm() > 0.0) || !std::isfinite(axis.norm())) {
    r.fail(joint.at("axis"), "the axis must be a finite non-zero vector");
  }
  spec.axis = axis.normalized();
  if (joint.has("origin")) spec.origin = r.vector3(joint.at("origin"));
  if (spec.origin.cwiseAbs().maxCoeff() > kMaxCoordinate) {
    r.fail(joint.at("origin"), "beyond the coordinate limit (scenes/README.md)");
  }
  if (!joint.has("keys")) r.fail(joint, "missing 'keys' ([{frame, degrees}, ...])");
  const Node list = joint.at("keys");
  r.expectArray(list);
  if (list.value.empty()) r.fail(list, "give at least one key");
  for (std::size_t k = 0; k < list.value.size(); ++k) {
    const Node key = list.at(k);
    r.expectObject(key, {"frame", "degrees"});
    const std::size_t frame = readKeyFrame(
        r, key, frames, spec.keys.empty() ? std::nullopt : std::optional(spec.keys.back().first));
    if (!key.has("degrees")) r.fail(key, "missing 'degrees'");
    const double degrees = r.number(key.at("degrees"));
    if (std::abs(degrees) > 1e6) r.fail(key.at("degrees"), "|degrees| must be <= 1e6");
    spec.keys.emplace_back(frame, degrees);
  }
  return spec;
}

// A scene that loads holds finite poses only and, like its fixed poses, translations within the
// coordinate limit: finite inputs can still overflow in a motion (ends near the double maximum,
// a jitter added to a huge translation).
void checkPoses(const Reader& r, const Node& motion, const std::vector<Pose>& poses) {
  for (std::size_t f = 0; f < poses.size(); ++f) {
    if (!poses[f].matrix().allFinite()) {
      r.fail(motion, "frame " + std::to_string(f) +
                         ": the pose is not finite (the motion overflows the double range)");
    }
    if (poses[f].translation().cwiseAbs().maxCoeff() > kMaxCoordinate) {
      std::ostringstream text;
      text << "frame " << f << ": the translation (" << poses[f].translation().x() << ", "
           << poses[f].translation().y() << ", " << poses[f].translation().z()
           << ") is beyond the coordinate limit |t| <= " << kMaxCoordinate << " (scenes/README.md)";
      r.fail(motion, text.str());
    }
  }
}

}  // namespace

void readMotion(const Reader& r, const Node& node, const Scene& scene,
                const std::map<std::string, std::size_t>& index_of,
                std::vector<ObjectMotionSource>& sources, std::size_t object_index,
                SceneObject& object) {
  const Pose base = node.has("pose") ? readPose(r, node.at("pose")) : Pose::Identity();
  object.poses = {base};
  if (!node.has("motion")) return;
  const Node motion = node.at("motion");
  r.expectObject(motion, {"poses", "random", "jitter", "linear", "keyframes", "joint"});
  if (motion.value.size() - (motion.has("comment") ? 1 : 0) != 1) {
    r.fail(motion, "give exactly one of poses, random, jitter, linear, keyframes, joint");
  }
  ObjectMotionSource& source = sources[object_index];
  source.kind = motion.value.begin().key() == "comment" ? std::next(motion.value.begin()).key()
                                                        : motion.value.begin().key();
  // Motions that replace the fixed pose rather than start from it.
  for (const char* kind : {"poses", "keyframes", "linear"}) {
    if (motion.has(kind) && node.has("pose")) {
      r.fail(node.at("pose"), std::string("'pose' and motion '") + kind + "' exclude each other");
    }
  }
  if (motion.has("poses")) {
    object.poses = readPoseList(r, motion.at("poses"), scene.frames);
  } else if (motion.has("random")) {
    const Node random = motion.at("random");
    r.expectObject(random, {"seed", "relative_to", "overlap"});
    if (!random.has("relative_to")) r.fail(random, "missing 'relative_to'");
    const std::string other = r.string(random.at("relative_to"));
    const auto found = index_of.find(other);
    if (found == index_of.end()) {
      const bool exists = std::any_of(scene.objects.begin(), scene.objects.end(),
                                      [&](const SceneObject& o) { return o.name == other; });
      r.fail(random.at("relative_to"),
             exists ? "'" + other +
                          "' is not defined before this one (objects are read in file order, "
                          "each parent before its children)"
                    : "no object named '" + other + "' (it must be defined before this one)");
    }
    const RandomOverlapMotion spec = readRandom(r, random);
    sources[found->second].referenced = true;
    const SceneObject& reference = scene.objects[found->second];
    object.poses = randomOverlapPoses(spec, *reference.mesh, reference.poses, *object.mesh, base,
                                      scene.frames);
  } else if (motion.has("keyframes")) {
    object.poses =
        keyframePoses(readKeyframes(r, motion.at("keyframes"), scene.frames), scene.frames);
  } else if (motion.has("joint")) {
    object.poses = jointPoses(readJoint(r, motion.at("joint"), base, scene.frames), scene.frames);
  } else if (motion.has("linear")) {
    object.poses = linearPoses(readLinear(r, motion.at("linear")), scene.frames);
  } else {
    object.poses = jitterPoses(readJitter(r, motion.at("jitter")), base, scene.frames);
  }
  checkPoses(r, motion, object.poses);
}

}  // namespace collido::scene_reading
