// Exact elements of the reference oracle, shared by its intersection, closest-point and
// intersection-set code (internal to core/src/oracle).
//
// Cases of a triangle (after exact classification):
//   triangle - three non-collinear corners;
//   segment  - collinear corners, not all equal: the segment between the two extreme corners;
//   point    - all corners equal.
// A pair of elements is decided by a 3x3 dispatch table of CGAL do_intersect/has_on calls, all
// exact with the Epeck kernel. The world coordinates R*v + t are Epeck lazy numbers, so they are
// exact too; their interval approximations give conservative boxes for the grid prefilter.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <Eigen/Core>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>

namespace collido::exact {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = EK::Point_3;
using FT = EK::FT;

enum ElementKind { kTriangleElement = 0, kSegmentElement = 1, kPointElement = 2 };

struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

  void add(const Box& o) {
    lo = lo.cwiseMin(o.lo);
    hi = hi.cwiseMax(o.hi);
  }
  bool overlaps(const Box& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
  bool empty() const { return (lo.array() > hi.array()).any(); }
};

/// A triangle, segment or point with corners of kernel K: Epeck for the oracle's searches (most
/// decisions settle on the interval approximations), its exact kernel of rationals where every
/// point is constructed exactly anyway (the contact reference's intersection sets: there the lazy
/// kernel only adds its bookkeeping, a std::call_once per number).
template <class K>
struct ElementIn {
  ElementKind kind = kTriangleElement;
  typename K::Point_3 p[3];  // triangle corners; a segment uses p[0], p[1]; a point p[0]
  Box box;
};
using Element = ElementIn<EK>;
using ExactKernel = EK::Exact_kernel;
using ExactElement = ElementIn<ExactKernel>;
/// Epeck's approximate kernel (intervals): its predicates throw
/// CGAL::Uncertain_conversion_exception where the intervals cannot decide, so a result computed in
/// it without one is certain. Use under CGAL::Protect_FPU_rounding.
using IntervalKernel = EK::Approximate_kernel;
using IntervalElement = ElementIn<IntervalKernel>;

struct PosedMesh {
  std::vector<Element> elements;
  Box bounds;
};

/// The exact world points pose * v of every vertex of `mesh`.
std::vector<Point> poseVertices(const TriangleMesh& mesh, const Pose& pose);
/// The element three exact points make: a triangle, a segment or a point.
Element classify(const Point& a, const Point& b, const Point& c);
/// Every triangle of `mesh` posed exactly and classified, with the bounds of them all.
PosedMesh poseMesh(const TriangleMesh& mesh, const Pose& pose);
/// One triangle given by its model corners, posed exactly and classified.
Element posedElement(const std::array<Eigen::Vector3d, 3>& corners, const Pose& pose);
/// Triangle t of `mesh`, posed exactly and classified.
Element posedElement(const TriangleMesh& mesh, const Pose& pose, std::int32_t t);
/// One triangle given by its model corners, posed and classified in the exact kernel.
ExactElement posedExactElement(const std::array<Eigen::Vector3d, 3>& corners, const Pose& pose);
/// The same in intervals (may throw CGAL::Uncertain_conversion_exception).
IntervalElement posedIntervalElement(const std::array<Eigen::Vector3d, 3>& corners,
                                     const Pose& pose);

/// The element as CGAL's triangle (of its three corners) or segment (of its first two).
template <class K>
typename K::Triangle_3 triangleOf(const ElementIn<K>& e) {
  return {e.p[0], e.p[1], e.p[2]};
}
template <class K>
typename K::Segment_3 segmentOf(const ElementIn<K>& e) {
  return {e.p[0], e.p[1]};
}
/// The point pose * x with each coordinate computed in the number type N (exact for Epeck's and
/// its exact kernel's numbers, an enclosing interval for intervals).
template <class P>
P posedPoint(const Eigen::Vector3d& x, const Pose& pose) {
  using N = typename CGAL::Kernel_traits<P>::Kernel::FT;
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  N world[3];
  for (int row = 0; row < 3; ++row)
    world[row] =
        N(r(row, 0)) * N(x.x()) + N(r(row, 1)) * N(x.y()) + N(r(row, 2)) * N(x.z()) + N(t[row]);
  return P(world[0], world[1], world[2]);
}

/// Whether two elements share a point, decided exactly.
bool elementsIntersect(const Element& x, const Element& y);
bool elementsIntersect(const ExactElement& x, const ExactElement& y);
bool elementsIntersect(const IntervalElement& x, const IntervalElement& y);
/// The exact squared distance of two elements (0 when they share a point).
FT elementsSquaredDistance(const Element& x, const Element& y);
/// The points where two intersecting elements meet: a point, a segment's two ends or a coplanar
/// polygon's corners (empty when they do not meet).
std::vector<Point> intersectionPoints(const Element& x, const Element& y);
std::vector<ExactKernel::Point_3> intersectionPoints(const ExactElement& x, const ExactElement& y);
std::vector<IntervalKernel::Point_3> intersectionPoints(const IntervalElement& x,
                                                        const IntervalElement& y);
/// The closest points of two elements that do not meet.
void closestPointsOfElements(const Element& x, const Element& y, Point& on_x, Point& on_y);

/// A point rounded to the nearest doubles.
Eigen::Vector3d rounded(const Point& p);
Eigen::Vector3d rounded(const ExactKernel::Point_3& p);

}  // namespace collido::exact
