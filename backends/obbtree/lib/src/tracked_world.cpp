// The double-double stage of the exact fallback (tracked_double_double.h): world coordinates
// and signs to about 106 bits with certified radii, settling what the certified filter doubted
// because of the mapping error alone, and exact zeros whose every step was exact. An uncertain
// sign leaves the pair to the expansions (exact_world.cpp).
#include "tracked_world.h"

#include <collido/oracle/orientation.h>
#include <collido/oracle/triangle_test.h>

#include "exact_world.h"
#include "expansion.h"

namespace collido::obbtree::detail {
namespace {

using Tracked = TrackedDoubleDouble;

TrackedPoint placeTracked(const Eigen::Vector3d& v, const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  TrackedPoint p;
  for (int row = 0; row < 3; ++row) {
    p.x[row] = ((Tracked::exactly(t[row]) + Tracked::product(r(row, 0), v.x())) +
                Tracked::product(r(row, 1), v.y())) +
               Tracked::product(r(row, 2), v.z());
  }
  return p;
}

}  // namespace

template <typename Point>
PlaneThrough<Point>::PlaneThrough(const Point& a, const Point& b, const Point& c) : origin_(a) {
  Number u[3];
  Number v[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = b.x[k] - a.x[k];
    v[k] = c.x[k] - a.x[k];
  }
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3;
    const int j = (k + 2) % 3;
    normal_[k] = u[i] * v[j] - u[j] * v[i];
  }
}

template <typename Point>
typename PlaneThrough<Point>::Number PlaneThrough<Point>::orient3d(const Point& d) const {
  Number det = normal_[0] * (d.x[0] - origin_.x[0]);
  for (int k = 1; k < 3; ++k)
    det = det + normal_[k] * (d.x[k] - origin_.x[k]);
  return det;
}

template class PlaneThrough<TrackedPoint>;
template class PlaneThrough<BoundedPoint>;

TrackedDoubleDouble trackedOrient2d(const TrackedPoint& a, const TrackedPoint& b,
                                    const TrackedPoint& c, int drop) {
  const int i = exact::keptFirst(drop);
  const int j = exact::keptSecond(drop);
  return (b.x[i] - a.x[i]) * (c.x[j] - a.x[j]) - (b.x[j] - a.x[j]) * (c.x[i] - a.x[i]);
}

LazyWorldPoint::LazyWorldPoint(const Eigen::Vector3d& model, const Eigen::Isometry3d& pose,
                               bool pose_in_range)
    : model_(model), pose_(&pose), in_range_(pose_in_range && pointInExpansionRange(model)) {}

const TrackedPoint& LazyWorldPoint::world() {
  if (!placed_) {
    world_ = placeTracked(model_, *pose_);
    placed_ = true;
  }
  return world_;
}

std::optional<bool> posedTrianglesIntersectByTrackedDoubles(const Eigen::Vector3d* a,
                                                            const Eigen::Isometry3d& pose_a,
                                                            const Eigen::Vector3d* b,
                                                            const Eigen::Isometry3d& pose_b) {
  if (!posedCornersInExpansionRange(a, pose_a) || !posedCornersInExpansionRange(b, pose_b))
    return std::nullopt;
  TrackedWorldKernel kernel;
  const bool answer = exact::TriangleTest<TrackedWorldKernel>(kernel).intersect(
      placeTracked(a[0], pose_a), placeTracked(a[1], pose_a), placeTracked(a[2], pose_a),
      placeTracked(b[0], pose_b), placeTracked(b[1], pose_b), placeTracked(b[2], pose_b));
  if (kernel.unsure()) return std::nullopt;
  return answer;
}

}  // namespace collido::obbtree::detail
