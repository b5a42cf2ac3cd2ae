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

/// Signs on world coordinates to about 106 bits, each certified or left undecided (then the
/// kernel is unsure and the pair goes on to the expansions): the cheap stage that settles poses
/// whose faces are parallel or coplanar only to within rounding (a solver's "upright" rotation
/// with 1e-18 off the diagonal, gears whose axes are parallel to 1e-19).
class TrackedWorldKernel {
 public:
  using Point = TrackedPoint;

  bool unsure() const { return unsure_; }

  // The triangle test asks for the corners of one triangle against the other's plane (a, b, c)
  // in a row: the last plane is kept, keyed by the corners' values.
  int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    if (!same(a, corners_[0]) || !same(b, corners_[1]) || !same(c, corners_[2]) || !has_plane_) {
      corners_[0] = a;
      corners_[1] = b;
      corners_[2] = c;
      plane_ = TrackedPlane(a, b, c);
      has_plane_ = true;
    }
    return signOf(plane_.orient3d(d));
  }

  int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    return signOf(trackedOrient2d(a, b, c, drop));
  }

  bool collinear(const Point& a, const Point& b, const Point& c) {
    for (int drop = 0; drop < 3; ++drop) {
      if (orient2d(a, b, c, drop) != 0) return false;
    }
    return true;
  }

  int compare(const Point& a, const Point& b, int k) { return signOf(a.x[k] - b.x[k]); }

 private:
  int signOf(const TrackedDoubleDouble& value) {
    const int sign = value.certainSign();
    if (sign != TrackedDoubleDouble::kUnsure) return sign;
    unsure_ = true;
    return 0;
  }

  static bool same(const Point& p, const Point& q) {
    for (int k = 0; k < 3; ++k) {
      const TrackedDoubleDouble& x = p.x[k];
      const TrackedDoubleDouble& y = q.x[k];
      if (x.hi != y.hi || x.lo != y.lo || x.radius != y.radius) return false;
    }
    return true;
  }

  bool unsure_ = false;
  bool has_plane_ = false;
  Point corners_[3];
  TrackedPlane plane_;
};

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
