#pragma once

#include <cstdint>
#include <limits>

#include <Eigen/Geometry>

#include <collido/obbtree/tree.h>

namespace collido::obbtree {

/// How close to the true distance the answer must be.
struct DistanceRequest {
  /// The answer may exceed the true distance d by max(abs_tolerance, rel_tolerance * d); both 0
  /// asks for the exact distance (to rounding).
  double abs_tolerance = 0.0;
  double rel_tolerance = 0.0;
};

/// The distance between two posed trees, with where it is attained and the work done.
struct DistanceAnswer {
  double distance = std::numeric_limits<double>::infinity();  ///< |point_b - point_a|; 0 on contact
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();          ///< world, on triangle_a
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();          ///< world, on triangle_b
  std::int32_t triangle_a = -1;                               ///< input triangle index in A
  std::int32_t triangle_b = -1;                               ///< input triangle index in B
  /// A lower bound on the true distance: the smallest box-pair bound left unexplored when the
  /// search stopped (the distance itself when nothing was left).
  double lower_bound = 0.0;
  std::uint64_t box_tests = 0;       ///< box-pair lower bounds computed
  std::uint64_t triangle_tests = 0;  ///< triangle-pair distances computed
};

/// The distance between two OBB trees by best-first simultaneous descent, in A's model frame:
/// node pairs wait in a queue ordered by a lower bound on the distance between their boxes (the
/// largest gap between the boxes' projections on the 15 separating-axis candidates, each divided
/// by its axis length, and on the line of their centres, less the bound on the rounding of the
/// relative map); the pair with the
/// smallest bound is taken next, its larger box split (or, at two leaves, every triangle pair's
/// distance computed), and a pair is dropped once its bound reaches the best distance found less
/// the tolerance (never less than 1e-13 of the coordinates' magnitude, except near contact, so
/// that pairs tied to rounding with the best — parallel faces — are not all opened). A triangle
/// pair is measured unless the gap between its bounds in A's frame already rules it out.
/// Triangle distances are computed on the mapped corners in double; a pair within rounding of
/// contact is decided by the exact triangle test, so touching meshes answer exactly 0. Stops
/// with the queue's smallest bound as the certified lower bound.
void distance(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
              const Eigen::Isometry3d& pose_b, const DistanceRequest& request,
              DistanceAnswer& answer);

}  // namespace collido::obbtree
