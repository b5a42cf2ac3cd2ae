#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace collido::convex {

/// A convex set given by its support function: the point of the set farthest along a
/// direction. A set may be "inflated" by a radius (a sphere is a point with a radius, a capsule
/// a segment with one): the distance is then taken between the cores and the radii subtracted,
/// which keeps the iteration on polytopes.
class SupportFunction {
 public:
  virtual ~SupportFunction() = default;
  /// A point of the core maximising direction · x (direction need not be unit length).
  virtual Eigen::Vector3d support(const Eigen::Vector3d& direction) const = 0;
  /// Some point of the core, to start from.
  virtual Eigen::Vector3d anyPoint() const = 0;
  /// The radius the core is inflated by (>= 0).
  virtual double radius() const { return 0.0; }
};

/// The convex hull of points (columns, at least one), optionally posed rigidly and inflated:
/// its support function is the points' own (posed on the fly), so no hull is built and nothing
/// is copied. Like a string_view, it refers to the points: they must outlive it (a temporary
/// matrix is refused at compile time).
class PointSetSupport final : public SupportFunction {
 public:
  explicit PointSetSupport(const Eigen::Matrix3Xd& points,
                           const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity(),
                           double radius = 0.0);
  PointSetSupport(Eigen::Matrix3Xd&& points, const Eigen::Isometry3d& pose = {},
                  double radius = 0.0) = delete;
  Eigen::Vector3d support(const Eigen::Vector3d& direction) const override;
  Eigen::Vector3d anyPoint() const override;
  double radius() const override { return radius_; }

 private:
  const Eigen::Matrix3Xd& points_;
  Eigen::Isometry3d pose_;
  bool posed_;
  double radius_;
};

/// When the iteration stops.
struct GjkOptions {
  /// Stop when distance - lower_bound <= max(abs_tolerance, rel_tolerance * distance).
  double abs_tolerance = 1e-12;
  double rel_tolerance = 1e-12;
  int max_iterations = 128;
};

/// Why the iteration stopped.
enum class GjkStatus {
  kConverged,      ///< the bounds met the tolerance
  kIntersecting,   ///< the sets overlap or touch (distance and lower bound 0)
  kNoProgress,     ///< the support point was already in the simplex: the bounds are final
  kMaxIterations,  ///< the limit stopped it; both bounds are still valid
};

/// The distance between two convex sets, with witnesses and a certified lower bound.
struct GjkResult {
  /// An upper bound: |point_b - point_a|, the points lying in the (inflated) sets.
  double distance = 0.0;
  /// Never above the true distance, whatever the stop: the largest gap found between a
  /// separating plane's two sides (for direction v, min over A - B of v·x / |v|), less the
  /// rounding of its computation, less the radii.
  double lower_bound = 0.0;
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
  bool intersecting = false;
  int iterations = 0;
  GjkStatus status = GjkStatus::kConverged;
};

/// GJK on the Minkowski difference A - B: the simplex's closest point to the origin (the best
/// over all its faces, each solved by a least-squares projection, degenerate faces skipped —
/// robust on collinear, coplanar and repeated support points), a new support point against it,
/// until the certified lower bound meets the distance. Sets that touch within rounding are
/// reported intersecting only when the simplex encloses the origin or the distance is within
/// the tolerance of 0.
GjkResult gjkDistance(const SupportFunction& a, const SupportFunction& b,
                      const GjkOptions& options = {});

}  // namespace collido::convex
