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
  using Triangle = typename K::Triangle_3;
  using Segment = typename K::Segment_3;
  const auto triangle = [](const ElementIn<K>& e) { return Triangle(e.p[0], e.p[1], e.p[2]); };
  const auto segment = [](const ElementIn<K>& e) { return Segment(e.p[0], e.p[1]); };
  std::vector<typename K::Point_3> points;
  if (x.kind == kPointElement) return {x.p[0]};
  if (y.kind == kPointElement) return {y.p[0]};
  if (x.kind == kTriangleElement && y.kind == kTriangleElement) {
    collectPoints<K>(CGAL::intersection(triangle(x), triangle(y)), points);
  } else if (x.kind == kTriangleElement) {
    collectPoints<K>(CGAL::intersection(triangle(x), segment(y)), points);
  } else if (y.kind == kTriangleElement) {
    collectPoints<K>(CGAL::intersection(triangle(y), segment(x)), points);
  } else {
    collectPoints<K>(CGAL::intersection(segment(x), segment(y)), points);
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

}  // namespace exact

using exact::ExactElement;
using exact::posedExactElement;

namespace {

// In the exact kernel: every point of the set is constructed exactly and rounded.
ExactIntersection intersectionOf(const ExactElement& x, const ExactElement& y) {
  ExactIntersection answer;
  if (!exact::elementsIntersect(x, y)) return answer;
  const auto points = exact::intersectionPoints(x, y);
  for (const auto& p : points)
    answer.points.push_back(exact::rounded(p));
  answer.shape = points.empty()       ? ExactIntersection::Shape::kEmpty
                 : points.size() == 1 ? ExactIntersection::Shape::kPoint
                 : points.size() == 2 ? ExactIntersection::Shape::kSegment
                                      : ExactIntersection::Shape::kPolygon;
  return answer;
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
  return intersectionOf(posedExactElement(cornersOf(a, pair.a), pose_a),
                        posedExactElement(cornersOf(b, pair.b), pose_b));
}

ExactIntersection exactPosedIntersection(const std::array<Eigen::Vector3d, 3>& a,
                                         const Pose& pose_a,
                                         const std::array<Eigen::Vector3d, 3>& b,
                                         const Pose& pose_b) {
  return intersectionOf(posedExactElement(a, pose_a), posedExactElement(b, pose_b));
}

}  // namespace collido
