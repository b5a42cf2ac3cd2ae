// The triangle-triangle test (triangle_test.h) on exact double inputs and on uncertain points
// through the certified filter.
#include <collido/obbtree/triangle_intersection.h>

#include "exact_predicates.h"
#include "filtered_predicates.h"
#include "triangle_test.h"

namespace collido::obbtree {
namespace {

// Exact signs on double inputs (CGAL's filtered predicates).
struct ExactDoubleKernel {
  using Point = Eigen::Vector3d;
  static int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    return detail::orient3d(a, b, c, d);
  }
  static int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    return detail::orient2d(a, b, c, drop);
  }
  static bool collinear(const Point& a, const Point& b, const Point& c) {
    return detail::collinear(a, b, c);
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
  return detail::TriangleTest<ExactDoubleKernel>(kernel).intersect(p1, q1, r1, p2, q2, r2);
}

std::optional<bool> trianglesIntersectCertified(const UncertainPoint& p1, const UncertainPoint& q1,
                                                const UncertainPoint& r1, const UncertainPoint& p2,
                                                const UncertainPoint& q2,
                                                const UncertainPoint& r2) {
  detail::FilteredKernel kernel;
  const bool answer =
      detail::TriangleTest<detail::FilteredKernel>(kernel).intersect(p1, q1, r1, p2, q2, r2);
  if (kernel.unsure()) return std::nullopt;
  return answer;
}

}  // namespace collido::obbtree
