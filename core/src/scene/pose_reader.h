// Poses in scene files: a translation and one of a rotation matrix, a unit quaternion or an
// axis and an angle. Shared by every reader of poses (fixed poses, motions, keyframes).
#pragma once

#include <collido/geometry.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// A rotation ("matrix", "quaternion", or "axis" + "degrees"); a matrix must be orthonormal
/// with determinant +1 within 1e-9.
Eigen::Matrix3d readRotation(const Reader& r, const Node& node);

/// A rigid pose {"translation", "rotation"} (both optional), within the coordinate limit.
Pose readPose(const Reader& r, const Node& node);

}  // namespace collido::scene_reading
