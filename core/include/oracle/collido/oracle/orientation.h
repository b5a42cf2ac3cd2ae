// Exact orientation signs on double inputs, and the 2D projection every caller shares: the
// building blocks of the exact triangle-triangle test (triangle_test.h). Dropping coordinate
// `drop` keeps the next two in cyclic order, (y, z), (z, x), (x, y); orientation signs in 2D
// depend on that order, so every kernel that decides one pair must share it.
#pragma once

#include <Eigen/Core>

namespace collido::exact {

/// The first kept coordinate when `drop` is dropped.
constexpr int keptFirst(int drop) {
  return (drop + 1) % 3;
}
/// The second kept coordinate when `drop` is dropped.
constexpr int keptSecond(int drop) {
  return (drop + 2) % 3;
}

/// p (with x(), y(), z(): an Eigen vector or a CGAL point) projected by dropping `drop`.
template <typename Point2, typename Point3>
Point2 dropCoordinate(const Point3& p, int drop) {
  const auto coordinate = [&p](int k) { return k == 0 ? p.x() : (k == 1 ? p.y() : p.z()); };
  return Point2(coordinate(keptFirst(drop)), coordinate(keptSecond(drop)));
}

/// Sign (-1, 0, +1) of the orientation of d relative to the plane through a, b, c; exact for any
/// finite double inputs. The sign convention is CGAL's: +1 when (a, b, c, d) is positively
/// oriented. Only the comparison of signs matters to the callers.
int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d);

/// Sign of the 2D orientation of (a, b, c) after dropping coordinate `drop` (0, 1 or 2); exact.
int orient2d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             int drop);

/// Whether a, b, c lie on one line (repeated points included); exact.
bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace collido::exact
