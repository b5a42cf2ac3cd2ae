// The exact set where two posed triangles meet: the reference for contact geometry.
#include <vector>

#include <CGAL/intersections.h>

#include <collido/oracle/exact_oracle.h>

#include "exact_elements.h"

namespace collido {
namespace exact {
namespace {

// The points of an exact intersection result: a point, a segment's ends, a triangle's corners
// or a polygon's (CGAL 5.5: a boost::optional of a boost::variant over those).
template <typename Result>
void collectPoints(const Result& result, std::vector<Point>& points) {
  if (!result) return;
  if (const Point* p = boost::get<Point>(&*result)) {
    points.push_back(*p);
  } else if (const EK::Segment_3* s = boost::get<EK::Segment_3>(&*result)) {
    points.push_back(s->source());
    points.push_back(s->target());
  }
}

}  // namespace

std::vector<Point> intersectionPoints(const Element& x, const Element& y) {
  std::vector<Point> points;
  if (x.kind == kPointElement) return {x.p[0]};
  if (y.kind == kPointElement) return {y.p[0]};
  if (x.kind == kTriangleElement && y.kind == kTriangleElement) {
    const auto result = CGAL::intersection(triangleOf(x), triangleOf(y));
    if (!result) return points;
    if (const EK::Triangle_3* t = boost::get<EK::Triangle_3>(&*result)) {
      for (int k = 0; k < 3; ++k)
        points.push_back(t->vertex(k));
    } else if (const auto* polygon = boost::get<std::vector<Point>>(&*result)) {
      points = *polygon;
    } else {
      collectPoints(result, points);
    }
  } else if (x.kind == kTriangleElement) {
    collectPoints(CGAL::intersection(triangleOf(x), segmentOf(y)), points);
  } else if (y.kind == kTriangleElement) {
    collectPoints(CGAL::intersection(triangleOf(y), segmentOf(x)), points);
  } else {
    collectPoints(CGAL::intersection(segmentOf(x), segmentOf(y)), points);
  }
  return points;
}

}  // namespace exact

using exact::Element;
using exact::elementsIntersect;
using exact::intersectionPoints;
using exact::Point;
using exact::posedElement;

namespace {

ExactIntersection intersectionOf(const Element& x, const Element& y) {
  ExactIntersection answer;
  if (!elementsIntersect(x, y)) return answer;
  const std::vector<Point> points = intersectionPoints(x, y);
  for (const Point& p : points)
    answer.points.push_back(exact::rounded(p));
  answer.shape = points.empty()       ? ExactIntersection::Shape::kEmpty
                 : points.size() == 1 ? ExactIntersection::Shape::kPoint
                 : points.size() == 2 ? ExactIntersection::Shape::kSegment
                                      : ExactIntersection::Shape::kPolygon;
  return answer;
}

}  // namespace

ExactIntersection exactPairIntersection(const TriangleMesh& a, const Pose& pose_a,
                                        const TriangleMesh& b, const Pose& pose_b,
                                        const TrianglePair& pair) {
  return intersectionOf(posedElement(a, pose_a, pair.a), posedElement(b, pose_b, pair.b));
}

ExactIntersection exactPosedIntersection(const std::array<Eigen::Vector3d, 3>& a,
                                         const Pose& pose_a,
                                         const std::array<Eigen::Vector3d, 3>& b,
                                         const Pose& pose_b) {
  return intersectionOf(posedElement(a, pose_a), posedElement(b, pose_b));
}

}  // namespace collido
