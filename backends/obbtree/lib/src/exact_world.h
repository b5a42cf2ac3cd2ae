// The three exact deciders behind posedTrianglesIntersect, apart for the tests that hold each to
// the other and to the oracle.
#pragma once

#include <optional>

#include <collido/obbtree/triangle_intersection.h>

#include "tracked_double_double.h"

namespace collido::obbtree::detail {

/// A triangle's corners placed in world coordinates (R v + t) as tracked double-doubles: what
/// the double-double stage needs of a triangle, made once per query and triangle by the
/// descent. `in_range`: the corners and pose are in the expansions' safe range (else only the
/// rationals decide; the corners are not set).
struct WorldTriangle {
  TrackedPoint corners[3];
  bool in_range = false;
};

/// Whether every entry of the pose's 3x4 matrix is in inExpansionRange(): checked once per query.
bool poseInExpansionRange(const Eigen::Isometry3d& pose);

/// Places the triangle with corners `corners` by `pose` (`pose_in_range`: the pose's check).
void placeWorldTriangle(const Eigen::Vector3d* corners, const Eigen::Isometry3d& pose,
                        bool pose_in_range, WorldTriangle& out);

/// The double-double stage on placed triangles; std::nullopt when either is out of range or a
/// sign was uncertain.
std::optional<bool> worldTrianglesIntersectByTrackedDoubles(const WorldTriangle& a,
                                                            const WorldTriangle& b);

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

/// The expansions, and where they step aside the rationals: what follows a double-double stage
/// that was unsure.
bool posedTrianglesIntersectByExpansionsOrRationals(const Eigen::Vector3d* a,
                                                    const Eigen::Isometry3d& pose_a,
                                                    const Eigen::Vector3d* b,
                                                    const Eigen::Isometry3d& pose_b);

}  // namespace collido::obbtree::detail
