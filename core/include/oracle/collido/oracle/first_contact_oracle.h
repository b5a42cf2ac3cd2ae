#pragma once

#include <cstddef>

#include <collido/mesh/triangle_mesh.h>
#include <collido/motion.h>
#include <collido/query.h>

namespace collido {

/// The exact reference's answer to "when do these two moving meshes first touch over the step?"
struct ExactFirstContact {
  enum class Outcome {
    kApart,      ///< proven: the closed meshes share no point at any t in [0, 1]
    kTouch,      ///< proven: no shared point before t_lo, a shared point at t_hi
    kUndecided,  ///< no shared point before t_lo is proven; past it the meshes came within
                 ///< rounding of each other without a shared point found (a grazing pass), or
                 ///< the evaluations ran out
  };
  Outcome outcome = Outcome::kApart;
  double t_lo = 1.0;     ///< no shared point on [0, t_lo): proven in every outcome
  double t_hi = 1.0;     ///< kTouch: the meshes share a point at t_hi, t_lo <= t_hi <= t_lo + width
  TrianglePair witness;  ///< kTouch: a pair that intersects at t_hi (decided exactly)
  std::size_t distance_evaluations = 0;  ///< exact distances computed (advancement steps)
  std::size_t intersection_tests = 0;    ///< exact intersection tests at trial ends
};

/// The first contact of A moving by `motion_a` and B by `motion_b` over the step, by
/// conservative advancement on exact distances: at time t the exact distance d (exactMeshDistance,
/// less a rounding allowance of 1e-12 of the scene's extent) bounds how far the meshes are from
/// touching, and no point of A or B moves faster than StepMotion::speedBound of its mesh's
/// radius about its origin, so nothing touches before t + d / (sum of the bounds). Once that
/// advance is shorter than `width`, the meshes are tested exactly for a shared point at t + width
/// and at halvings of it down to the advance: a shared point there closes the bracket. Gives up
/// as kUndecided after `max_evaluations` distances, or when the distance is within the rounding
/// allowance without a shared point. `width` must be > 0; meshes must not be empty.
ExactFirstContact exactFirstContact(const TriangleMesh& a, const StepMotion& motion_a,
                                    const TriangleMesh& b, const StepMotion& motion_b, double width,
                                    std::size_t max_evaluations = 4096);

}  // namespace collido
