// Exact signs for contact sets on posed triangle corners: the certified filter on the world
// doubles first (filtered_predicates.h), expansions on the exact world positions (R v + t, as the
// oracle places them) for the signs it cannot settle (exact_world.h). Corners exactly on the
// other triangle's plane, and exactly coplanar faces, are what CAD contacts are made of: each
// such sign costs one expansion determinant instead of a rational construction.
#pragma once

#include <Eigen/Geometry>

#include <collido/obbtree/triangle_intersection.h>

#include "exact_world.h"

namespace collido::obbtree::detail {

/// A triangle corner: its world position in double with the radius of that rounding, and the
/// model point and pose that place it exactly.
struct PosedCorner {
  UncertainPoint world;
  PosedModelPoint exact;
};

/// The corner `model` placed by `pose` (which must outlive the corner).
PosedCorner posedCorner(const Eigen::Vector3d& model, const Eigen::Isometry3d& pose);

/// orient3d, orient2d and compare on posed corners, exact. A sign neither the filter nor the
/// expansions could give (a coordinate outside the expansions' safe range, an overflow) is
/// returned as 0 and marks the kernel failed: the caller then computes the set on rationals.
class ContactSignKernel {
 public:
  using Point = PosedCorner;

  bool failed() const { return failed_; }
  int orient3d(const Point& a, const Point& b, const Point& c, const Point& d);
  int orient2d(const Point& a, const Point& b, const Point& c, int drop);
  int compare(const Point& a, const Point& b, int k);

 private:
  int settle(const std::optional<int>& sign);
  bool failed_ = false;
};

}  // namespace collido::obbtree::detail
