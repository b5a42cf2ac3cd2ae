// The double-double stage of the exact fallback, on triangles placed in world coordinates: alone
// on a posed pair (posedTrianglesIntersectByTrackedDoubles, as posedTrianglesIntersect runs it)
// or, through its planes and points, behind the certified filter on vertices placed on first use
// (the descent's path, face_signs.h).
#pragma once

#include <optional>

#include <Eigen/Geometry>

#include <collido/obbtree/triangle_intersection.h>

#include "tracked_double_double.h"

namespace collido::obbtree::detail {

/// The plane through three tracked points, its normal ((b - a) x (c - a)) kept: orientation
/// determinants of further points against it cost three products each. The triangle test asks a
/// plane about three corners in a row, and a contact's signs ask each plane about three.
class TrackedPlane {
 public:
  TrackedPlane() = default;
  TrackedPlane(const TrackedPoint& a, const TrackedPoint& b, const TrackedPoint& c);
  /// det(b - a, c - a, d - a) = ((b - a) x (c - a)) . (d - a), with its certified radius.
  TrackedDoubleDouble orient3d(const TrackedPoint& d) const;

 private:
  TrackedPoint origin_;
  TrackedDoubleDouble normal_[3];
};

/// The 2D orientation determinant of a, b, c after dropping coordinate `drop` (the exact
/// kernels' projection order, orientation.h), with its certified radius.
TrackedDoubleDouble trackedOrient2d(const TrackedPoint& a, const TrackedPoint& b,
                                    const TrackedPoint& c, int drop);

/// A vertex's world position as tracked double-doubles, placed on first use: the query's
/// fallback makes one per vertex that reaches it and places only those a sign needs.
class LazyWorldPoint {
 public:
  /// `pose_in_range`: the pose's poseInExpansionRange().
  LazyWorldPoint() = default;
  LazyWorldPoint(const Eigen::Vector3d& model, const Eigen::Isometry3d& pose, bool pose_in_range);
  /// Whether the vertex and its pose are in the expansions' safe range (else never placed).
  bool inRange() const { return in_range_; }
  /// The world position, placed now if not yet (only when inRange()).
  const TrackedPoint& world();

 private:
  Eigen::Vector3d model_ = Eigen::Vector3d::Zero();
  const Eigen::Isometry3d* pose_ = nullptr;
  bool in_range_ = false;
  bool placed_ = false;
  TrackedPoint world_;
};

/// posedTrianglesIntersect on double-doubles with certified radii (tracked_double_double.h);
/// std::nullopt when an input is outside the expansions' safe range or a sign was uncertain
/// (every exact zero is).
std::optional<bool> posedTrianglesIntersectByTrackedDoubles(const Eigen::Vector3d* a,
                                                            const Eigen::Isometry3d& pose_a,
                                                            const Eigen::Vector3d* b,
                                                            const Eigen::Isometry3d& pose_b);

}  // namespace collido::obbtree::detail
