#pragma once

#include <Eigen/Geometry>

namespace collido {

/// A rigid transform; world point = pose * model point. Every pose in Collidoscope is one of these.
using Pose = Eigen::Isometry3d;

/// A triangle mesh borrowed for the duration of a call (no ownership, no copy).
struct MeshView {
  Eigen::Map<const Eigen::Matrix3Xd> vertices;   ///< one column per vertex, model frame
  Eigen::Map<const Eigen::Matrix3Xi> triangles;  ///< one column of vertex indices per triangle,
                                                 ///< counter-clockwise seen from outside
};

}  // namespace collido
