// The triangle-triangle test (triangle_test.h) over exact signs on double inputs.
#include <collido/oracle/double_triangle_test.h>

#include <collido/oracle/orientation.h>
#include <collido/oracle/triangle_test.h>

namespace collido::exact {
namespace {

struct ExactDoubleKernel {
  using Point = Eigen::Vector3d;
  static int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    return exact::orient3d(a, b, c, d);
  }
  static int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    return exact::orient2d(a, b, c, drop);
  }
  static bool collinear(const Point& a, const Point& b, const Point& c) {
    return exact::collinear(a, b, c);
  }
  static int compare(const Point& a, const Point& b, int k) {
    return (a[k] > b[k]) - (a[k] < b[k]);
  }
};

}  // namespace

bool trianglesIntersect(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1,
                        const Eigen::Vector3d& r1, const Eigen::Vector3d& p2,
                        const Eigen::Vector3d& q2, const Eigen::Vector3d& r2) {
  ExactDoubleKernel kernel;
  return TriangleTest<ExactDoubleKernel>(kernel).intersect(p1, q1, r1, p2, q2, r2);
}

}  // namespace collido::exact
