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
  /// Only the certified lower bound is wanted (conservative advancement): a pair apart is
  /// settled with its double-precision interval however wide, never refined to its exact closest
  /// points, so `lower_bound` stays certified while `distance` and the points may be off by that
  /// interval's width. Contact is still decided exactly.
  bool bound_only = false;
};

/// The distance between two posed trees, with where it is attained and the work done. The
/// exact distance (world corners pose * v evaluated exactly, as the exact oracle poses them)
/// lies in [lower_bound, upper_bound], and so does `distance`; the interval is at most
/// max(abs_tolerance, rel_tolerance * upper_bound) + 2^-19 upper_bound wide, and in practice
/// about 1e-13 of the coordinates' magnitude (README, "Distance"). `distance` is 0 exactly when
/// the meshes touch, decided by the exact triangle test.
struct DistanceAnswer {
  double distance = std::numeric_limits<double>::infinity();  ///< |point_b - point_a|; 0 on contact
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();          ///< world, on triangle_a
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();          ///< world, on triangle_b
  std::int32_t triangle_a = -1;                               ///< input triangle index in A
  std::int32_t triangle_b = -1;                               ///< input triangle index in B
  double lower_bound = 0.0;  ///< certified: at most the exact distance
  double upper_bound = std::numeric_limits<double>::infinity();  ///< certified: at least it
  std::uint64_t box_tests = 0;                                   ///< box-pair lower bounds computed
  std::uint64_t triangle_tests = 0;  ///< triangle-pair distances computed
  std::uint64_t exact_tests = 0;     ///< triangle pairs decided in exact arithmetic
};

/// The distance between two OBB trees by best-first simultaneous descent, in A's model frame:
/// node pairs wait in a heap ordered by a lower bound on the distance between their boxes (the
/// gap between the boxes' projections on the direction of their closest points, found by one
/// step of alternating projections, less the bound on the rounding of the relative map); the
/// pair with the smallest bound is taken next, both boxes split when they are of a size, else
/// the larger (or, at two leaves, every triangle pair's distance computed). A triangle pair is
/// measured unless the gap between its bounds in A's frame already rules it out.
/// Each triangle pair's distance is computed on the mapped corners in double precision with a
/// certified interval (the gap between the triangles' projections on the closest points'
/// direction from below, the closest points' length plus their rounding from above, both
/// widened by the map's error). A pair whose interval cannot rule out contact, or is wider than
/// 2^-20 of its lower end (nearly touching, slivers, near-parallel edges), is decided exactly:
/// contact by the certified double-precision triangle test and, where that cannot tell, the
/// exact one, else the exact squared distance of the world corners
/// (that one only when the pair, waiting at its certified lower end, is still a candidate).
/// The search stops when no pair left can be closer than the best pair's upper end by more than
/// the tolerance (at least rounding: the smaller of 1e-13 of the coordinates' magnitude and 2^-20
/// of the distance); what it set aside gives the lower end.
void distance(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
              const Eigen::Isometry3d& pose_b, const DistanceRequest& request,
              DistanceAnswer& answer);

}  // namespace collido::obbtree
