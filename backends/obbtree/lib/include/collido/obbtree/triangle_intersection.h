#pragma once

#include <Eigen/Core>

namespace collido::obbtree {

/// Whether two closed triangles share at least one point, decided exactly for their double
/// coordinates (touching counts). Every decision is the sign of an orientation determinant,
/// evaluated by exact predicates; a degenerate triangle is treated as the segment or point it is.
bool trianglesIntersect(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1,
                        const Eigen::Vector3d& r1, const Eigen::Vector3d& p2,
                        const Eigen::Vector3d& q2, const Eigen::Vector3d& r2);

}  // namespace collido::obbtree
