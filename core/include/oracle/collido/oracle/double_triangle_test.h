#pragma once

#include <Eigen/Core>

namespace collido::exact {

/// Whether two closed triangles share at least one point, decided exactly for their double
/// coordinates (touching counts). Every decision is the sign of an orientation determinant,
/// evaluated by CGAL's filtered exact predicates; a degenerate triangle is treated as the
/// segment or point it is. The fastest exact test we have: the OBB tree's leaves decide with
/// the same algorithm, and the study's floor (one such test per truly intersecting pair) is
/// timed with it.
bool trianglesIntersect(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1,
                        const Eigen::Vector3d& r1, const Eigen::Vector3d& p2,
                        const Eigen::Vector3d& q2, const Eigen::Vector3d& r2);

}  // namespace collido::exact
