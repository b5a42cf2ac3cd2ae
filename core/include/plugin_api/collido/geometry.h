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

/// A read-only view of a NURBS surface in its model frame: degrees, clamped knot vectors, and
/// the homogeneous control net (w x, w y, w z, w) as columns, the u index outermost (column
/// i * count_v + j).
struct SurfaceView {
  int degree_u = 0;
  int degree_v = 0;
  int count_u = 0;
  int count_v = 0;
  Eigen::Map<const Eigen::VectorXd> knots_u{nullptr, 0};
  Eigen::Map<const Eigen::VectorXd> knots_v{nullptr, 0};
  Eigen::Map<const Eigen::Matrix4Xd> control{nullptr, 4, 0};
};

}  // namespace collido
