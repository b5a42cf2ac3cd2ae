// The triangle-triangle test (collido/oracle/triangle_test.h) on uncertain points through the
// certified filter.
#include <collido/obbtree/triangle_intersection.h>

#include <collido/oracle/triangle_test.h>

#include "filtered_predicates.h"
#include "prepared_triangle.h"

namespace collido::obbtree {

std::optional<bool> trianglesIntersectCertified(const UncertainPoint& p1, const UncertainPoint& q1,
                                                const UncertainPoint& r1, const UncertainPoint& p2,
                                                const UncertainPoint& q2,
                                                const UncertainPoint& r2) {
  detail::FilteredKernel kernel;
  const bool answer =
      exact::TriangleTest<detail::FilteredKernel>(kernel).intersect(p1, q1, r1, p2, q2, r2);
  if (kernel.unsure()) return std::nullopt;
  return answer;
}

namespace detail {

std::optional<bool> crossingTrianglesIntersectCertified(const PreparedTriangle& a,
                                                        const int side_a[3],
                                                        const PreparedTriangle& b,
                                                        const int side_b[3]) {
  FilteredKernel kernel;
  const bool answer = exact::TriangleTest<FilteredKernel>(kernel).crossingTrianglesIntersect(
      a.corners, side_a, b.corners, side_b);
  if (kernel.unsure()) return std::nullopt;
  return answer;
}

}  // namespace detail

}  // namespace collido::obbtree
