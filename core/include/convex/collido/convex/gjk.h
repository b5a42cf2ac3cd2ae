#pragma once

#include <type_traits>

#include <limits>

#include <Eigen/Core>

#include <collido/geometry.h>

namespace collido::convex {

/// What a support function answers for one direction. The slack is what makes GJK's lower bound
/// certified: the search for the extreme point and any transform round, so the set may reach a
/// little beyond the returned point along the direction, and the bound must know how far.
struct SupportPoint {
  /// A point of the set (its core, before inflation) farthest along the direction, as rounded.
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  /// max over the set of direction·x <= direction·point + slack in exact arithmetic, for the
  /// direction as passed (not normalised). >= 0; 0 only for an exact support.
  double slack = 0.0;
};

/// A convex set given by its support function, optionally inflated by a radius (a sphere is a
/// point with a radius, a capsule a segment with one). GJK runs on the cores and subtracts the
/// radii at the end: the iteration then stays on polytopes, which it solves in finitely many
/// steps, rather than creeping towards a curved surface.
class SupportFunction {
 public:
  virtual ~SupportFunction() = default;
  /// The extreme point of the core along `direction` (any length, not zero) and its slack.
  virtual SupportPoint support(const Eigen::Vector3d& direction) const = 0;
  /// The radius the core is inflated by (the swept-sphere radius), >= 0.
  virtual double inflation() const { return 0.0; }
};

/// The convex hull of points, optionally posed rigidly and inflated. The support of a point set
/// is that of its hull, so no hull is built: each query is one pass over the points. The search
/// runs on the points' offsets from their box centre, so its rounding (the slack) scales with
/// the set's size, not with its distance from the origin; a pose adds the rounding of the
/// transformed point, which does grow with the translation, so for sets far from the origin
/// pose B relative to A and leave A unposed (Box2D's "origin independent" distance input).
class PointSetSupport final : public SupportFunction {
 public:
  /// Borrows `points` (one column each; none: every query is invalid): they must outlive the
  /// support, so pass a matrix, a block of columns or a map, not an expression that Eigen would
  /// copy into a temporary. `pose` maps the points into the query frame (world = pose * point).
  explicit PointSetSupport(const Eigen::Ref<const Eigen::Matrix3Xd>& points,
                           const Pose& pose = Pose::Identity(), double inflation = 0.0);
  /// A temporary matrix would be gone before the first query.
  template <typename Temporary,
            std::enable_if_t<std::is_same_v<Temporary, Eigen::Matrix3Xd>, int> = 0>
  explicit PointSetSupport(Temporary&& points, const Pose& pose = Pose::Identity(),
                           double inflation = 0.0) = delete;

  SupportPoint support(const Eigen::Vector3d& direction) const override;
  double inflation() const override { return inflation_; }

 private:
  Eigen::Ref<const Eigen::Matrix3Xd> points_;
  Eigen::Vector3d center_;    // midpoint of the points' box, in their own frame
  double spread_;             // >= max |point - center_| per coordinate, rounded up
  bool posed_;                // false: the pose is exactly the identity
  Eigen::Matrix3d rotation_;  // the pose's linear part (any matrix: no orthogonality assumed)
  Eigen::Vector3d translation_;
  Eigen::Vector3d abs_row_sums_;  // sum_j |rotation_(i, j)|, for the slack
  double inflation_;
};

/// When the iteration stops. Upper and lower bounds are those of the inflated sets.
struct GjkOptions {
  /// Stop when distance - lower_bound <= max(abs_tolerance, rel_tolerance * distance).
  /// Tolerances below what rounding lets the bounds certify (a few units in the last place of
  /// the support points' size) are raised to that floor. Sets whose distance cannot be told
  /// from 0 within max(abs_tolerance, that floor) count as intersecting.
  double abs_tolerance = 0.0;
  double rel_tolerance = 1e-12;
  int max_iterations = 128;  ///< support-point pairs queried, the first included (>= 1)
  /// The first search direction, from B towards A (e.g. the previous answer's
  /// point_a - point_b for coherent queries); zero or not finite: +x.
  Eigen::Vector3d initial_direction = Eigen::Vector3d::UnitX();
  /// Stop as soon as the certified lower bound reaches this (status kLowerBoundReached): a
  /// caller that drops the pair above a cutoff needs no tighter bounds. Infinity: never.
  double stop_when_lower_reaches = std::numeric_limits<double>::infinity();
};

/// Why the iteration stopped. Whatever the reason, lower_bound never exceeds the true distance.
enum class GjkStatus {
  kConverged,          ///< the bounds met the tolerance, or the sets intersect
  kMaxIterations,      ///< the limit stopped it before the bounds met
  kDegenerate,         ///< rounding stalled the simplex (no closer point) and no other direction
                       ///< tried certified the rest: only near touching, at gaps of a few
                       ///< hundred ulps of the sets' size or coordinates
  kInvalidInput,       ///< a support point or slack was not finite (an empty set, NaN or infinite
                       ///< coordinates) or an inflation was negative or not finite
  kLowerBoundReached,  ///< the lower bound reached GjkOptions::stop_when_lower_reaches
};

/// "converged", "max_iterations", "degenerate", "invalid_input", "lower_bound_reached".
const char* gjkStatusName(GjkStatus status);

/// The distance between two convex sets, bracketed: lower_bound <= true distance <= distance
/// (the latter up to the rounding of the witnesses themselves).
struct GjkResult {
  /// An upper bound: the distance between the witnesses, which lie in the (inflated) sets.
  /// 0 when intersecting; +infinity for invalid input.
  double distance = 0.0;
  /// A certified lower bound, at every exit: the widest gap found between two parallel
  /// supporting planes (for a direction v, min over A of v·a - max over B of v·b, over |v|),
  /// less the support slacks and the rounding of its own computation, less the radii.
  double lower_bound = 0.0;
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();  ///< witness in A (a common point if
                                                      ///< intersecting, up to rounding)
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();  ///< witness in B
  /// The sets overlap or touch: the distance could not be told from 0 within max(abs_tolerance,
  /// the rounding floor). Then distance and lower_bound are 0; no penetration depth is computed.
  bool intersecting = false;
  int iterations = 0;  ///< support-point pairs queried
  GjkStatus status = GjkStatus::kConverged;
};

/// The distance between the convex sets A and B by GJK on their Minkowski difference A - B:
/// the simplex's point closest to the origin (signed-volume style sub-simplex solver that falls
/// back to the faces of a degenerate simplex: collinear, coplanar or repeated support points),
/// then a new support point against it, until the upper bound (that closest point) and the
/// certified lower bound (the gap along the search direction) meet the tolerance, or the
/// simplex stops getting closer.
GjkResult gjkDistance(const SupportFunction& a, const SupportFunction& b,
                      const GjkOptions& options = {});

}  // namespace collido::convex
