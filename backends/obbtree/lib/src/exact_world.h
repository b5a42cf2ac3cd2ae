// The three exact deciders behind posedTrianglesIntersect, apart for the tests that hold each to
// the other and to the oracle.
#pragma once

#include <optional>

#include <collido/obbtree/triangle_intersection.h>

namespace collido::obbtree::detail {

/// posedTrianglesIntersect on double-doubles with certified radii (tracked_double_double.h);
/// std::nullopt when an input is outside the expansions' safe range or a sign was uncertain
/// (every exact zero is).
std::optional<bool> posedTrianglesIntersectByTrackedDoubles(const Eigen::Vector3d* a,
                                                            const Eigen::Isometry3d& pose_a,
                                                            const Eigen::Vector3d* b,
                                                            const Eigen::Isometry3d& pose_b);

/// posedTrianglesIntersect on floating-point expansions (expansion.h); std::nullopt when an
/// input is outside the expansions' safe range or an expansion outgrew its capacity.
std::optional<bool> posedTrianglesIntersectByExpansions(const Eigen::Vector3d* a,
                                                        const Eigen::Isometry3d& pose_a,
                                                        const Eigen::Vector3d* b,
                                                        const Eigen::Isometry3d& pose_b);

/// posedTrianglesIntersect on CGAL's lazy exact rationals: the last resort, any finite input.
bool posedTrianglesIntersectByRationals(const Eigen::Vector3d* a, const Eigen::Isometry3d& pose_a,
                                        const Eigen::Vector3d* b, const Eigen::Isometry3d& pose_b);

}  // namespace collido::obbtree::detail
