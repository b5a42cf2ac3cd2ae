// The three exact deciders behind posedTrianglesIntersect, apart for the tests that hold each to
// the other and to the oracle.
#pragma once

#include <optional>

#include <collido/obbtree/triangle_intersection.h>

namespace collido::obbtree::detail {

/// Whether every entry of the pose's 3x4 matrix is in inExpansionRange(): checked once per query.
bool poseInExpansionRange(const Eigen::Isometry3d& pose);

/// Whether the point's coordinates are all in inExpansionRange().
bool pointInExpansionRange(const Eigen::Vector3d& point);

/// Whether the three corners' coordinates are all in inExpansionRange().
bool cornersInExpansionRange(const Eigen::Vector3d* corners);

/// Whether a posed triangle's corners and its pose are all in inExpansionRange().
bool posedCornersInExpansionRange(const Eigen::Vector3d* corners, const Eigen::Isometry3d& pose);

/// posedTrianglesIntersect on floating-point expansions (expansion.h); std::nullopt when an
/// input is outside the expansions' safe range or an expansion outgrew its capacity.
std::optional<bool> posedTrianglesIntersectByExpansions(const Eigen::Vector3d* a,
                                                        const Eigen::Isometry3d& pose_a,
                                                        const Eigen::Vector3d* b,
                                                        const Eigen::Isometry3d& pose_b);

/// posedTrianglesIntersect on CGAL's lazy exact rationals: the last resort, any finite input.
bool posedTrianglesIntersectByRationals(const Eigen::Vector3d* a, const Eigen::Isometry3d& pose_a,
                                        const Eigen::Vector3d* b, const Eigen::Isometry3d& pose_b);

/// The expansions, and where they step aside the rationals: what follows a double-double stage
/// that was unsure.
bool posedTrianglesIntersectByExpansionsOrRationals(const Eigen::Vector3d* a,
                                                    const Eigen::Isometry3d& pose_a,
                                                    const Eigen::Vector3d* b,
                                                    const Eigen::Isometry3d& pose_b);

}  // namespace collido::obbtree::detail
