// How far two moving trees can go before any of their triangles may touch: conservative
// advancement with a motion bound per node pair along the pair's own separating direction (as
// C2A does), for firstContact().
#pragma once

#include <cstdint>

#include <Eigen/Geometry>

#include <collido/obbtree/tree.h>

namespace collido::obbtree::detail {

/// How the trees move from the current time on, per unit of the step's time: each origin along
/// a straight line, each tree turning about a fixed axis through its origin (StepMotion).
struct StepRates {
  Eigen::Vector3d closing_velocity;  ///< A's origin velocity less B's, world frame
  double turn_a = 0.0;               ///< A's turning rate, radians per unit time, >= 0
  double turn_b = 0.0;
  /// How far the poses computed along the path may stray from the exact path (rounding): taken
  /// off every gap.
  double allowance = 0.0;
};

/// The work an advance did.
struct AdvanceCounters {
  std::uint64_t box_tests = 0;
  std::uint64_t triangle_tests = 0;
};

/// A time tau in [0, limit] with no contact between the trees on [now, now + tau), proven; limit
/// when nothing can touch before it. Every pair of boxes, and at the leaves every pair of
/// triangles, is separated along a direction d (the boxes' or the triangles' approximate closest
/// points) by a certified gap g; the pair's points close along d no faster than
/// closing_velocity . d + turn_a r_a + turn_b r_b, with r each side's largest distance from its
/// origin, so that pair cannot touch before g over that rate. The least such time over the
/// triangle pairs, found best-first with node pairs pruned by their own, is the answer. Pairs
/// within rounding of each other give 0: the caller decides them by an exact test.
double certifiedAdvance(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
                        const Eigen::Isometry3d& pose_b, const StepRates& rates, double limit,
                        AdvanceCounters& counters);

}  // namespace collido::obbtree::detail
