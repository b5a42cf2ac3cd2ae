// The exact fallback of the certified triangle test: both triangles placed in world coordinates
// with exact (lazy rational) arithmetic, as the exact oracle places them, then decided with the
// same algorithm (collido/oracle/triangle_test.h) on CGAL's exact-constructions kernel.
#include <collido/obbtree/triangle_intersection.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <collido/oracle/orientation.h>
#include <collido/oracle/triangle_test.h>

namespace collido::obbtree {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using exact::dropCoordinate;

struct ExactWorldKernel {
  using Point = EK::Point_3;
  static int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    return static_cast<int>(CGAL::orientation(a, b, c, d));
  }
  static int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    return static_cast<int>(CGAL::orientation(dropCoordinate<EK::Point_2>(a, drop),
                                              dropCoordinate<EK::Point_2>(b, drop),
                                              dropCoordinate<EK::Point_2>(c, drop)));
  }
  static bool collinear(const Point& a, const Point& b, const Point& c) {
    return CGAL::collinear(a, b, c);
  }
  static int compare(const Point& a, const Point& b, int k) {
    return static_cast<int>(CGAL::compare(a.cartesian(k), b.cartesian(k)));
  }
};

EK::Point_3 place(const Eigen::Vector3d& v, const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  using FT = EK::FT;
  FT world[3];
  for (int row = 0; row < 3; ++row) {
    world[row] = FT(r(row, 0)) * FT(v.x()) + FT(r(row, 1)) * FT(v.y()) + FT(r(row, 2)) * FT(v.z()) +
                 FT(t[row]);
  }
  return {world[0], world[1], world[2]};
}

}  // namespace

bool posedTrianglesIntersect(const Eigen::Vector3d* a, const Eigen::Isometry3d& pose_a,
                             const Eigen::Vector3d* b, const Eigen::Isometry3d& pose_b) {
  ExactWorldKernel kernel;
  return exact::TriangleTest<ExactWorldKernel>(kernel).intersect(
      place(a[0], pose_a), place(a[1], pose_a), place(a[2], pose_a), place(b[0], pose_b),
      place(b[1], pose_b), place(b[2], pose_b));
}

}  // namespace collido::obbtree
