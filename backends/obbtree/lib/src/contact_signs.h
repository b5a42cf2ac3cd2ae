// Exact signs for contact sets on posed triangle corners: the certified filter on the world
// doubles first (filtered_predicates.h), expansions on the exact world positions (R v + t, as the
// oracle places them) for the signs it cannot settle (exact_world.h). Corners exactly on the
// other triangle's plane, and exactly coplanar faces, are what CAD contacts are made of: each
// such sign costs one expansion determinant instead of a rational construction.
#pragma once

#include <array>
#include <optional>

#include <Eigen/Geometry>

#include <collido/obbtree/triangle_intersection.h>

#include "exact_world.h"
#include "plane_relations.h"

namespace collido::obbtree::detail {

/// A triangle corner: its world position in double with the radius of that rounding, and the
/// model point and pose that place it exactly.
struct PosedCorner {
  UncertainPoint world;
  PosedModelPoint exact;
};

/// The corner `model` placed by `pose` (which must outlive the corner).
PosedCorner posedCorner(const Eigen::Vector3d& model, const Eigen::Isometry3d& pose);

/// orient2d and compare on posed corners, exact. A sign neither the filter nor the
/// expansions could give (a coordinate outside the expansions' safe range, an overflow) is
/// returned as 0 and marks the kernel failed: the caller then computes the set on rationals.
class ContactSignKernel {
 public:
  using Point = PosedCorner;

  bool failed() const { return failed_; }
  int orient2d(const Point& a, const Point& b, const Point& c, int drop);
  int compare(const Point& a, const Point& b, int k);

 private:
  int settle(const std::optional<int>& sign);
  bool failed_ = false;
};

/// The sides of each of two triangles' corners of the other's plane, exact, and on request the
/// signed distances behind them (orientation determinants, n . (x - corner 0) with n by the
/// plane's winding, to within a few units in the last place). A corner the filter places costs
/// nothing; one it cannot, and a crossing point that needs the distance's value, share one
/// expansion determinant, computed once: near-coplanar CAD faces ask both of most corners.
class PlaneSides {
 public:
  /// The corners must outlive this.
  PlaneSides(const std::array<PosedCorner, 3>& a, const std::array<PosedCorner, 3>& b)
      : a_(a), b_(b) {}

  /// [0]: B's corners against A's plane, [1]: A's against B's (as PlaneSigns); nullopt
  /// when a sign was out of the expansions' reach (the caller then decides on rationals).
  std::optional<PlaneSigns> signs();
  /// The signed distance of corner k of B from A's plane (side 0), or of A's corner k from B's
  /// plane (side 1); nullopt out of the expansions' reach.
  std::optional<double> value(std::size_t side, std::size_t k);

 private:
  struct Memo {
    bool computed = false;
    std::optional<double> value;
  };
  const std::array<PosedCorner, 3>& a_;
  const std::array<PosedCorner, 3>& b_;
  std::array<std::array<Memo, 3>, 2> values_{};
};

}  // namespace collido::obbtree::detail
