// A lower bound on the distance between two oriented boxes, for the distance search: the gap
// along the direction of the boxes' (approximate) closest points, then along the 15 candidate
// axes of the separating-axis test, stopping once a gap reaches what the caller can prune.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include <collido/obbtree/separating_axis.h>

#include "frame_products.h"

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
/// surfaces, for their cost on every bound (where edges meet at an angle, the edge axes serve).
/// Zero when a point of B lies in A (the boxes overlap).
inline Eigen::Vector3d closestPointsDirection(const BoxPairInA& boxes) {
  const Eigen::Vector3d near_centre = boxes.t.cwiseMax(-boxes.a).cwiseMin(boxes.a);
  const Eigen::Vector3d local =
      transposedTimesVector(boxes.r, near_centre - boxes.t).cwiseMax(-boxes.b).cwiseMin(boxes.b);
  const Eigen::Vector3d on_b = boxes.t + timesVector(boxes.r, local);
  return on_b - on_b.cwiseMax(-boxes.a).cwiseMin(boxes.a);
}

/// A lower bound on the distance between the boxes, never negative: the largest gap, less
/// `slack`, along the closest points' direction, the 6 face normals and the 9 edge cross
/// products (each divided by its length), narrowed by 8 units of rounding. Returns as soon as
/// the bound reaches `enough` (the caller sets aside any pair at or beyond it), so a pruned
/// pair mostly costs the first direction.
///
/// Why it holds with computed inputs: every gap is a sum of products of a direction's
/// components (at most 1 in magnitude for a unit direction, the rotation's entries for an axis
/// the test names) with t, a or b; `slack` (see boxesOverlap: 5 axis_error (|t|_1 + |a|_1 +
/// |b|_1), plus B's mapping error) covers the inputs' errors against the exact boxes and the
/// roundings of these few sums, and the last factor those of the divisions by the lengths.
inline double boxPairLowerBound(const BoxPairInA& boxes, double slack,
                                double enough = std::numeric_limits<double>::infinity()) {
  constexpr double kNarrow = 1.0 - 8.0 * std::numeric_limits<double>::epsilon();
  const Eigen::Vector3d towards_b = closestPointsDirection(boxes);
  const double length = towards_b.norm();
  // A point in both boxes: they overlap, and 0 is their distance.
  if (!(length > 0.0)) return 0.0;
  double gap = std::max(0.0, gapAlong(boxes, towards_b / length) - slack);
  if (gap * kNarrow >= enough) return gap * kNarrow;

  const Eigen::Matrix3d& r = boxes.r;
  const Eigen::Vector3d& t = boxes.t;
  const Eigen::Vector3d& a = boxes.a;
  const Eigen::Vector3d& b = boxes.b;
  const Eigen::Matrix3d abs_r = r.cwiseAbs();
  const auto apart = [slack](const AxisProjection& axis) {
    return axis.distance - axis.radius_sum - slack;
  };
  for (int i = 0; i < 3; ++i)
    gap = std::max(gap, apart(faceAxisOfA(abs_r, t, a, b, i)));
  for (int j = 0; j < 3; ++j)
    gap = std::max(gap, apart(faceAxisOfB(r, abs_r, t, a, b, j)));
  if (gap * kNarrow >= enough) return gap * kNarrow;
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3;
    const int i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const double separation = apart(edgeAxis(r, abs_r, t, a, b, i, j));
      if (!(separation > 0.0)) continue;
      // Axis e_i x B_j has length sqrt(r(i1,j)^2 + r(i2,j)^2) (entries of a rotation: no over-
      // or underflow that matters, and the final narrowing covers the roundings); nearly
      // parallel edges give a degenerate axis whose bound the face axes already cover. The
      // square root is taken only for an axis that raises the gap.
      const double length_squared = r(i1, j) * r(i1, j) + r(i2, j) * r(i2, j);
      if (length_squared < 1e-12) continue;
      if (separation * separation <= gap * gap * length_squared) continue;
      gap = std::max(gap, separation / std::sqrt(length_squared));
    }
  }
  return gap * kNarrow;
}

}  // namespace collido::obbtree::detail
