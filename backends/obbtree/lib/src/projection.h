// The 2D projection every kernel of the triangle test uses: dropping coordinate `drop` keeps the
// next two in cyclic order, (y, z), (z, x), (x, y). Orientation signs in 2D depend on that order,
// so the filtered and the exact kernels must share it: one decision may mix their signs.
#pragma once

namespace collido::obbtree::detail {

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

}  // namespace collido::obbtree::detail
