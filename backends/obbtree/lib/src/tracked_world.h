// The double-double stage of the exact fallback, on triangles placed in world coordinates: alone
// on a posed pair (posedTrianglesIntersectByTrackedDoubles, as posedTrianglesIntersect runs it)
// or, through its planes and points, behind the certified filter on vertices placed on first use
// (the descent's path, face_signs.h).
#pragma once

#include <optional>
#include <type_traits>

#include <Eigen/Geometry>

#include <collido/obbtree/triangle_intersection.h>

#include "bounded_double_double.h"
#include "tracked_double_double.h"

namespace collido::obbtree::detail {

/// A point of world coordinates as bounded double-doubles (bounded_double_double.h).
struct BoundedPoint {
  BoundedDoubleDouble x[3];
};

/// A tracked point's coordinates as bounded double-doubles, their radii the errors.
inline BoundedPoint boundedOf(const TrackedPoint& p) {
  return {{boundedOf(p.x[0]), boundedOf(p.x[1]), boundedOf(p.x[2])}};
}

/// Whether every coordinate of the point is exactly hi + lo (radius 0).
inline bool exactlyKnown(const TrackedPoint& p) {
  return p.x[0].radius == 0.0 && p.x[1].radius == 0.0 && p.x[2].radius == 0.0;
}

/// The plane through three points (TrackedPoint or BoundedPoint), its normal ((b - a) x (c - a))
/// kept: orientation determinants of further points against it cost three products each. The
/// triangle test asks a plane about three corners in a row, and a contact's signs ask each plane
/// about three.
template <typename Point>
class PlaneThrough {
 public:
  using Number = std::remove_const_t<std::remove_reference_t<decltype(Point{}.x[0])>>;

  PlaneThrough() = default;
  PlaneThrough(const Point& a, const Point& b, const Point& c);
  /// det(b - a, c - a, d - a) = ((b - a) x (c - a)) . (d - a), with its radius or error bound.
  Number orient3d(const Point& d) const;

 private:
  Point origin_;
  Number normal_[3];
};

using TrackedPlane = PlaneThrough<TrackedPoint>;
using BoundedPlane = PlaneThrough<BoundedPoint>;
extern template class PlaneThrough<TrackedPoint>;
extern template class PlaneThrough<BoundedPoint>;

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
  // in a row: the last plane is kept, keyed by the corners' values. Where a corner is already
  // inexact no zero can be certified, and the bounded double-doubles settle every sign the
  // tracked ones would, but those within about 2^-100 of the permanent, at a fraction of the
  // cost; what they leave, and every sign of exact corners (where zeros are), takes the tracked
  // radii.
  int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    if (!same(a, corners_[0]) || !same(b, corners_[1]) || !same(c, corners_[2]) || !has_plane_) {
      corners_[0] = a;
      corners_[1] = b;
      corners_[2] = c;
      plane_inexact_ = !exactlyKnown(a) || !exactlyKnown(b) || !exactlyKnown(c);
      has_plane_ = true;
      has_bounded_plane_ = false;
      has_tracked_plane_ = false;
    }
    if (plane_inexact_ || !exactlyKnown(d)) {
      if (!has_bounded_plane_) {
        bounded_plane_ = BoundedPlane(boundedOf(a), boundedOf(b), boundedOf(c));
        has_bounded_plane_ = true;
      }
      const int sign = bounded_plane_.orient3d(boundedOf(d)).certainSign();
      if (sign != TrackedDoubleDouble::kUnsure) return sign;
    }
    if (!has_tracked_plane_) {
      plane_ = TrackedPlane(a, b, c);
      has_tracked_plane_ = true;
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
  bool has_plane_ = false;  // corners_ hold the last plane's corners
  bool plane_inexact_ = false;
  bool has_bounded_plane_ = false;
  bool has_tracked_plane_ = false;
  Point corners_[3];
  BoundedPlane bounded_plane_;
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
