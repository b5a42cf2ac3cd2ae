// The exact set where two posed triangles meet: the reference for contact geometry.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <CGAL/intersections.h>

#include <collido/oracle/exact_oracle.h>

#include "exact_elements.h"

namespace collido {
namespace exact {
namespace {

// The points of an exact intersection result: a point, a segment's ends, a triangle's corners
// or a polygon's (CGAL 5.5: a boost::optional of a boost::variant over those).
template <class K, typename Result>
void collectPoints(const Result& result, std::vector<typename K::Point_3>& points) {
  using P = typename K::Point_3;
  if (!result) return;
  if (const P* p = boost::relaxed_get<P>(&*result)) {
    points.push_back(*p);
  } else if (const auto* s = boost::relaxed_get<typename K::Segment_3>(&*result)) {
    points.push_back(s->source());
    points.push_back(s->target());
  } else if (const auto* t = boost::relaxed_get<typename K::Triangle_3>(&*result)) {
    for (int k = 0; k < 3; ++k)
      points.push_back(t->vertex(k));
  } else if (const auto* polygon = boost::relaxed_get<std::vector<P>>(&*result)) {
    points = *polygon;
  }
}

template <class K>
std::vector<typename K::Point_3> pointsWhereMeet(const ElementIn<K>& x, const ElementIn<K>& y) {
  std::vector<typename K::Point_3> points;
  if (x.kind == kPointElement) return {x.p[0]};
  if (y.kind == kPointElement) return {y.p[0]};
  if (x.kind == kTriangleElement && y.kind == kTriangleElement) {
    collectPoints<K>(CGAL::intersection(triangleOf(x), triangleOf(y)), points);
  } else if (x.kind == kTriangleElement) {
    collectPoints<K>(CGAL::intersection(triangleOf(x), segmentOf(y)), points);
  } else if (y.kind == kTriangleElement) {
    collectPoints<K>(CGAL::intersection(triangleOf(y), segmentOf(x)), points);
  } else {
    collectPoints<K>(CGAL::intersection(segmentOf(x), segmentOf(y)), points);
  }
  return points;
}

}  // namespace

std::vector<Point> intersectionPoints(const Element& x, const Element& y) {
  return pointsWhereMeet(x, y);
}
std::vector<ExactKernel::Point_3> intersectionPoints(const ExactElement& x, const ExactElement& y) {
  return pointsWhereMeet(x, y);
}
std::vector<IntervalKernel::Point_3> intersectionPoints(const IntervalElement& x,
                                                        const IntervalElement& y) {
  return pointsWhereMeet(x, y);
}

}  // namespace exact

using exact::ExactElement;
using exact::IntervalElement;

namespace {

ExactIntersection::Shape shapeOf(std::size_t points) {
  return points == 0   ? ExactIntersection::Shape::kEmpty
         : points == 1 ? ExactIntersection::Shape::kPoint
         : points == 2 ? ExactIntersection::Shape::kSegment
                       : ExactIntersection::Shape::kPolygon;
}

// A coordinate's interval is taken as the point's value (its midpoint) when it is at most this
// wide relative to its magnitude. The construction of a crossing segment takes tens of
// operations on intervals, which leave them 1e-13 to 1e-10 wide (relative) on a dense mesh's
// contacts; the exact kernel there costs about 1 ms a pair. Epeck's to_double, which this
// replaces, takes an interval's midpoint up to 1e-5.
constexpr double kIntervalPinned = 1e-9;

// In intervals, as Epeck's constructions first try: every decision certain (an undecided one
// throws) and every point pinned to within kIntervalPinned; nothing when either fails.
std::optional<ExactIntersection> intervalIntersectionOf(const std::array<Eigen::Vector3d, 3>& a,
                                                        const Pose& pose_a,
                                                        const std::array<Eigen::Vector3d, 3>& b,
                                                        const Pose& pose_b) {
  std::vector<std::array<std::pair<double, double>, 3>> bounds;
  try {
    const CGAL::Protect_FPU_rounding<true> rounding_up;
    const IntervalElement x = exact::posedIntervalElement(a, pose_a);
    const IntervalElement y = exact::posedIntervalElement(b, pose_b);
    if (!exact::elementsIntersect(x, y)) return ExactIntersection{};
    for (const auto& p : exact::intersectionPoints(x, y)) {
      bounds.push_back({});
      for (int k = 0; k < 3; ++k)
        bounds.back()[static_cast<std::size_t>(k)] = {p[k].inf(), p[k].sup()};
    }
  } catch (const CGAL::Uncertain_conversion_exception&) {
    return std::nullopt;
  }
  ExactIntersection answer;
  for (const auto& point : bounds) {
    Eigen::Vector3d value;
    for (int k = 0; k < 3; ++k) {
      const auto [lo, hi] = point[static_cast<std::size_t>(k)];
      if (!(hi - lo <= kIntervalPinned * std::max(std::abs(lo), std::abs(hi)))) return std::nullopt;
      value[k] = lo + (hi - lo) / 2;
    }
    answer.points.push_back(value);
  }
  answer.shape = shapeOf(answer.points.size());
  return answer;
}

// In the exact kernel: every point of the set constructed exactly and rounded to the nearest.
ExactIntersection exactIntersectionOf(const ExactElement& x, const ExactElement& y) {
  ExactIntersection answer;
  if (!exact::elementsIntersect(x, y)) return answer;
  for (const auto& p : exact::intersectionPoints(x, y))
    answer.points.push_back(exact::rounded(p));
  answer.shape = shapeOf(answer.points.size());
  return answer;
}

// Intervals first; the exact kernel where they cannot decide (touching, coplanar or degenerate
// triangles) or cannot pin a point.
ExactIntersection intersectionOf(const std::array<Eigen::Vector3d, 3>& a, const Pose& pose_a,
                                 const std::array<Eigen::Vector3d, 3>& b, const Pose& pose_b) {
  if (std::optional<ExactIntersection> answer = intervalIntersectionOf(a, pose_a, b, pose_b))
    return *std::move(answer);
  return exactIntersectionOf(exact::posedExactElement(a, pose_a),
                             exact::posedExactElement(b, pose_b));
}

std::array<Eigen::Vector3d, 3> cornersOf(const TriangleMesh& mesh, std::int32_t t) {
  std::array<Eigen::Vector3d, 3> corners;
  for (int k = 0; k < 3; ++k)
    corners[static_cast<std::size_t>(k)] = mesh.corner(static_cast<std::size_t>(t), k);
  return corners;
}

}  // namespace

ExactIntersection exactPairIntersection(const TriangleMesh& a, const Pose& pose_a,
                                        const TriangleMesh& b, const Pose& pose_b,
                                        const TrianglePair& pair) {
  return intersectionOf(cornersOf(a, pair.a), pose_a, cornersOf(b, pair.b), pose_b);
}

ExactIntersection exactPosedIntersection(const std::array<Eigen::Vector3d, 3>& a,
                                         const Pose& pose_a,
                                         const std::array<Eigen::Vector3d, 3>& b,
                                         const Pose& pose_b) {
  return intersectionOf(a, pose_a, b, pose_b);
}

}  // namespace collido
