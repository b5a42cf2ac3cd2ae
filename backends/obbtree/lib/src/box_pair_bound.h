// A lower bound on the distance between two oriented boxes, for the distance search: the gap
// along the direction of the boxes' (approximate) closest points.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "frame_products.h"
#include "query_bounds.h"

namespace collido::obbtree::detail {

/// Two boxes with B given in A's box frame: A is the points u with |u_k| <= a_k; B is the points
/// t + r v with |v_k| <= b_k (`r`: B's axes as columns).
struct BoxPairInA {
  const Eigen::Matrix3d& r;
  const Eigen::Vector3d& t;
  const Eigen::Vector3d& a;
  const Eigen::Vector3d& b;
};

/// How far apart the boxes are along `direction` (pointing from A towards B): the distance of
/// their centres along it less both boxes' reach along it, all scaled by the direction's length.
/// Divided by that length it is a lower bound on the boxes' distance for every direction, and
/// their distance itself for the direction of their closest points.
inline double gapAlong(const BoxPairInA& boxes, const Eigen::Vector3d& direction) {
  return direction.dot(boxes.t) - boxes.a.dot(direction.cwiseAbs()) -
         boxes.b.dot(transposedTimesVector(boxes.r, direction).cwiseAbs());
}

/// A direction from A towards B near that of the boxes' closest points: one step of alternating
/// projections (the point of A closest to B's centre, the point of B closest to that, the point
/// of A closest to that). On the thin, near-parallel boxes of facing surfaces it lands on the
/// facing sides; more steps cut the box bounds a search takes by under 1% on the bundled
/// surfaces, for their cost on every bound.
/// Zero when a point of B lies in A (the boxes overlap).
inline Eigen::Vector3d closestPointsDirection(const BoxPairInA& boxes) {
  const Eigen::Vector3d near_centre = boxes.t.cwiseMax(-boxes.a).cwiseMin(boxes.a);
  const Eigen::Vector3d local =
      transposedTimesVector(boxes.r, near_centre - boxes.t).cwiseMax(-boxes.b).cwiseMin(boxes.b);
  const Eigen::Vector3d on_b = boxes.t + timesVector(boxes.r, local);
  return on_b - on_b.cwiseMax(-boxes.a).cwiseMin(boxes.a);
}

/// How far B's box, its centre mapped into A's frame by `map` (and its axes with it), may lie from
/// the exact box, as a distance: the mapped centre's error and the axes' over the half extents.
inline double mappedBoxError(const RelativeMap& map, const OrientedBox& box) {
  return map.bounds.pointError(box.center) * std::sqrt(3.0) +
         map.bounds.axis_error * box.half_extents.sum();
}

/// The slack boxPairLowerBound takes for boxes with B mapped by `map` (`mapped_error`:
/// mappedBoxError): 5 axis_error (|t|_1 + |a|_1 + |b|_1), plus B's mapping error.
inline double boxPairSlack(const RelativeMap& map, const BoxPairInA& boxes, double mapped_error) {
  return 5.0 * map.bounds.axis_error * (boxes.t.cwiseAbs().sum() + boxes.a.sum() + boxes.b.sum()) +
         mapped_error + kUnderflowGuard;
}

/// A lower bound on the distance between the boxes, never negative: the gap, less `slack`,
/// along the direction of their approximate closest points (closestPointsDirection), narrowed
/// by 8 units of rounding. The 15 axes of the separating-axis test are not tried: in the
/// distance search most pairs bounded are opened anyway, and those axes decided fewer than 2%
/// of the bounds on the bundled surfaces while tripling each bound's cost.
///
/// Why it holds with computed inputs: the gap is a sum of products of the direction's
/// components (at most its length in magnitude) with t, a or b, divided by that length; `slack`
/// (see boxesOverlap: 5 axis_error (|t|_1 + |a|_1 + |b|_1), plus B's mapping error) covers the
/// inputs' errors against the exact boxes and the roundings of these few sums, and the last
/// factor those of the square root and the division.
inline double boxPairLowerBound(const BoxPairInA& boxes, double slack) {
  constexpr double kNarrow = 1.0 - 8.0 * std::numeric_limits<double>::epsilon();
  // Below this squared length (components under about 1e-145) the square might lose relative
  // precision to subnormal rounding; such boxes are within 1e-145 of each other: bound 0.
  constexpr double kLeastLengthSquared = 1e-290;
  const Eigen::Vector3d towards_b = closestPointsDirection(boxes);
  const double length_squared = towards_b.squaredNorm();
  // A point in both boxes: they overlap, and 0 is their distance.
  if (!(length_squared > kLeastLengthSquared)) return 0.0;
  // The gap along the direction as it is, divided by its length once: the square root runs
  // beside the gap's products instead of before them.
  const double gap = gapAlong(boxes, towards_b) / std::sqrt(length_squared);
  return std::max(0.0, gap - slack) * kNarrow;
}

}  // namespace collido::obbtree::detail
