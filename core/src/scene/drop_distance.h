// How far points can fall along a direction before they meet a mesh: the geometry behind the
// "drape" deformation rule (a sheet settling onto an object).
#pragma once

#include <vector>

#include <Eigen/Core>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>

namespace collido::scene_reading {

/// For each column of `points` (world frame), the distance along the unit `direction` to the
/// first triangle of `target` (placed by `target_pose`) that the ray from the point meets, or
/// infinity when it meets none. Triangles behind the point are ignored. Double-precision ray
/// casting (Moller-Trumbore) through a uniform grid over the triangles' shadows on the plane
/// across the direction: it shapes a scene, it answers no collision question.
std::vector<double> dropDistances(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& direction,
                                  const TriangleMesh& target, const Pose& target_pose);

}  // namespace collido::scene_reading
