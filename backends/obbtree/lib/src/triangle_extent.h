// A triangle's extent along a direction, with a bound on its rounding, and the certified lower
// bound on two triangles' distance that two such extents give: the separation test shared by
// the certified triangle distance and the distance search's filter on triangle pairs.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace collido::obbtree::detail {

/// The least and largest of n . (c - o) over a triangle's corners c as computed, and a bound on
/// how far either is from the exact projection of the exact corners given: each projection rounds
/// the three differences and the dot product, an error below 6 u sum_k |n_k| |c_k - o_k| (u =
/// 2^-53), bounded for all three corners at once by n . (their largest |c_k - o_k| per
/// coordinate).
struct TriangleExtent {
  double least = std::numeric_limits<double>::infinity();
  double largest = -std::numeric_limits<double>::infinity();
  double rounding = 0.0;
};

inline TriangleExtent extentAlong(const Eigen::Vector3d& n, const std::array<Eigen::Vector3d, 3>& t,
                                  const Eigen::Vector3d& origin) {
  constexpr double kUnitRoundoff = 0x1p-53;
  const Eigen::Vector3d w0 = t[0] - origin;
  const Eigen::Vector3d w1 = t[1] - origin;
  const Eigen::Vector3d w2 = t[2] - origin;
  const double p0 = n.dot(w0);
  const double p1 = n.dot(w1);
  const double p2 = n.dot(w2);
  const Eigen::Vector3d reach = w0.cwiseAbs().cwiseMax(w1.cwiseAbs()).cwiseMax(w2.cwiseAbs());
  // The bound's own product and sum round too (3 u on a sum of non-negative products).
  return {std::min(p0, std::min(p1, p2)), std::max(p0, std::max(p1, p2)),
          6.0 * kUnitRoundoff * n.cwiseAbs().dot(reach) * (1.0 + 4.0 * kUnitRoundoff)};
}

/// The extent that holds both.
inline TriangleExtent unionOf(const TriangleExtent& a, const TriangleExtent& b) {
  return {std::min(a.least, b.least), std::max(a.largest, b.largest),
          std::max(a.rounding, b.rounding)};
}

/// What turns the gap between two extents along n into a distance: 1 / |n|, rounded down far
/// enough to cover the norm's and the division's roundings and the product with the gap; 0 for a
/// zero or non-finite n (no bound).
inline double inverseLengthBelow(const Eigen::Vector3d& n) {
  constexpr double kUnitRoundoff = 0x1p-53;
  const double length = n.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return 0.0;
  const double inverse = (1.0 - 8.0 * kUnitRoundoff) / length;
  return std::isfinite(inverse) ? inverse : 0.0;
}

/// A certified lower bound on the distance between triangle a (exact corners) and the triangle
/// whose exact corners lie within `b_error` (Euclidean) of b's, from their extents along one
/// direction n (`inverse_length`: inverseLengthBelow(n)): every point of each triangle projects
/// within its extent, so they are at least the gap between the extents over |n| apart. 0 when
/// the extents overlap.
inline double separationOfExtents(const TriangleExtent& a, const TriangleExtent& b,
                                  double inverse_length, double b_error) {
  constexpr double kUnitRoundoff = 0x1p-53;
  // Relative bounds fail where products and sums underflow; this covers what they can lose.
  constexpr double kTiny = 1e-290;
  const double apart = std::max(b.least - a.largest, a.least - b.largest);
  const double gap =
      apart * (1.0 - kUnitRoundoff) - (a.rounding + b.rounding) * (1.0 + kUnitRoundoff);
  if (!(gap > 0.0)) return 0.0;
  // The last factor covers the final subtraction's rounding.
  const double lower =
      (gap * inverse_length - b_error * (1.0 + kUnitRoundoff)) * (1.0 - 2.0 * kUnitRoundoff) -
      kTiny;
  return std::max(0.0, lower);
}

}  // namespace collido::obbtree::detail
