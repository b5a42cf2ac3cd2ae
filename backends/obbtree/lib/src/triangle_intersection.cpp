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

bool weightsInRange(const PreparedTriangle& t) {
  using prepared::kEps;
  const UncertainPoint* c = t.corners;
  return prepared::inRange((c[1].p - c[0].p).cwiseAbs() * (1.0 + kEps) + c[0].error + c[1].error) &&
         prepared::inRange((c[2].p - c[0].p).cwiseAbs() * (1.0 + kEps) + c[0].error + c[2].error);
}

void settleSides(const PreparedTriangle& t, const PreparedTriangle& other, int side[3]) {
  using prepared::kEps;
  const UncertainPoint& origin = t.corners[0];
  int weights_in_range = -1;  // weightsInRange(t), once asked
  for (int k = 0; k < 3; ++k) {
    const UncertainPoint& x = other.corners[k];
    if (side[k] == kUndecidedSign) side[k] = certainSide(t, x);  // not asked yet
    if (side[k] != 0) continue;
    // Unsure: zero by the filter's rule (filtered_predicates.h) when the inflated permanent is
    // exactly zero and no factor is small enough for a product of three to underflow.
    side[k] = kUndecidedSign;
    const Eigen::Vector3d bw = (x.p - origin.p).cwiseAbs() * (1.0 + kEps) + origin.error + x.error;
    if (t.inflated_weights.dot(bw) != 0.0 || !prepared::inRange(bw)) continue;
    if (weights_in_range < 0) weights_in_range = weightsInRange(t) ? 1 : 0;
    if (weights_in_range == 1) side[k] = 0;
  }
}

std::optional<bool> trianglesIntersectCertifiedKnowingSides(const PreparedTriangle& a,
                                                            const int side_a[3], bool a_proper,
                                                            const PreparedTriangle& b,
                                                            const int side_b[3], bool b_proper) {
  using Test = exact::TriangleTest<FilteredKernel>;
  static_assert(Test::kUnknownSide == kUndecidedSign, "one mark for a side not settled");
  FilteredKernel kernel;
  const bool answer =
      Test(kernel).intersectKnowingSides(a.corners, side_a, a_proper, b.corners, side_b, b_proper);
  if (kernel.unsure()) return std::nullopt;
  return answer;
}

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
