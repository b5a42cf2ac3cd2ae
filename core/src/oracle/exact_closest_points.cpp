// Exact distances and closest points of posed triangles (degenerate ones as their segment or
// point), in CGAL's exact constructions, rounded once at the end.
#include <algorithm>
#include <utility>
#include <vector>

#include <CGAL/squared_distance_3.h>

#include <collido/assert.h>
#include <collido/oracle/distance_oracle.h>

#include "exact_elements.h"

namespace collido {
namespace exact {
namespace {

// Exact squared distances, by the same dispatch; 0 for elements that share a point.
FT triTriDistance(const Element& x, const Element& y) {
  if (elementsIntersect(x, y)) return FT(0);
  return CGAL::squared_distance(triangleOf(x), triangleOf(y));
}
FT triSegDistance(const Element& x, const Element& y) {
  if (elementsIntersect(x, y)) return FT(0);
  const EK::Triangle_3 t = triangleOf(x);
  const EK::Segment_3 s = segmentOf(y);
  FT best = CGAL::min(CGAL::squared_distance(s.source(), t), CGAL::squared_distance(s.target(), t));
  for (int i = 0; i < 3; ++i)
    best = CGAL::min(best, CGAL::squared_distance(s, EK::Segment_3(x.p[i], x.p[(i + 1) % 3])));
  return best;
}
FT triPointDistance(const Element& x, const Element& y) {
  return CGAL::squared_distance(y.p[0], triangleOf(x));
}
FT segTriDistance(const Element& x, const Element& y) {
  return triSegDistance(y, x);
}
FT segSegDistance(const Element& x, const Element& y) {
  return CGAL::squared_distance(segmentOf(x), segmentOf(y));
}
FT segPointDistance(const Element& x, const Element& y) {
  return CGAL::squared_distance(y.p[0], segmentOf(x));
}
FT pointTriDistance(const Element& x, const Element& y) {
  return triPointDistance(y, x);
}
FT pointSegDistance(const Element& x, const Element& y) {
  return segPointDistance(y, x);
}
FT pointPointDistance(const Element& x, const Element& y) {
  return CGAL::squared_distance(x.p[0], y.p[0]);
}

using ExactDistance = FT (*)(const Element&, const Element&);
constexpr ExactDistance kExactDistances[3][3] = {
    {&triTriDistance, &triSegDistance, &triPointDistance},
    {&segTriDistance, &segSegDistance, &segPointDistance},
    {&pointTriDistance, &pointSegDistance, &pointPointDistance},
};

// The corners of an element: 3, 2 or 1.
int cornerCount(const Element& e) {
  return e.kind == kTriangleElement ? 3 : e.kind == kSegmentElement ? 2 : 1;
}

FT clamp01(const FT& x) {
  if (x < FT(0)) return FT(0);
  if (x > FT(1)) return FT(1);
  return x;
}

// The closest points of segments [p0, p1] and [q0, q1] (either may be a point), exactly: the
// minimiser over the parameter square, clamped (parallel segments take s = 0 first).
void closestOnSegments(const Point& p0, const Point& p1, const Point& q0, const Point& q1,
                       Point& on_p, Point& on_q) {
  const EK::Vector_3 u = p1 - p0;
  const EK::Vector_3 v = q1 - q0;
  const EK::Vector_3 r = p0 - q0;
  const FT a = u * u;
  const FT e = v * v;
  const FT f = v * r;
  FT s(0);
  FT t(0);
  if (a == FT(0) && e == FT(0)) {
    // two points
  } else if (a == FT(0)) {
    t = clamp01(f / e);
  } else {
    const FT c = u * r;
    if (e == FT(0)) {
      s = clamp01(-c / a);
    } else {
      const FT b = u * v;
      const FT denominator = a * e - b * b;
      s = denominator > FT(0) ? clamp01((b * f - c * e) / denominator) : FT(0);
      t = (b * s + f) / e;
      if (t < FT(0)) {
        t = FT(0);
        s = clamp01(-c / a);
      } else if (t > FT(1)) {
        t = FT(1);
        s = clamp01((b - c) / a);
      }
    }
  }
  on_p = p0 + s * u;
  on_q = q0 + t * v;
}

// The edges of an element as segments (a segment's one, a point's degenerate one).
std::vector<std::pair<Point, Point>> edgesOf(const Element& e) {
  if (e.kind == kPointElement) return {{e.p[0], e.p[0]}};
  if (e.kind == kSegmentElement) return {{e.p[0], e.p[1]}};
  return {{e.p[0], e.p[1]}, {e.p[1], e.p[2]}, {e.p[2], e.p[0]}};
}

}  // namespace

FT elementsSquaredDistance(const Element& x, const Element& y) {
  return kExactDistances[x.kind][y.kind](x, y);
}

// The closest points of two elements that do not meet: for disjoint closed triangles (segments,
// points) the minimum is attained between two edges or between a corner and the other's face.
void closestPointsOfElements(const Element& x, const Element& y, Point& on_x, Point& on_y) {
  bool found = false;
  FT best(0);
  const auto consider = [&](const Point& p, const Point& q) {
    const FT d2 = CGAL::squared_distance(p, q);
    if (!found || d2 < best) {
      found = true;
      best = d2;
      on_x = p;
      on_y = q;
    }
  };
  for (const auto& [p0, p1] : edgesOf(x)) {
    for (const auto& [q0, q1] : edgesOf(y)) {
      Point p;
      Point q;
      closestOnSegments(p0, p1, q0, q1, p, q);
      consider(p, q);
    }
  }
  // A corner against the other's face, where its projection falls inside the face.
  const auto corner_face = [&](const Element& face, const Element& corners, bool face_is_x) {
    if (face.kind != kTriangleElement) return;
    const EK::Plane_3 plane(face.p[0], face.p[1], face.p[2]);
    const EK::Triangle_3 triangle = triangleOf(face);
    for (int i = 0; i < cornerCount(corners); ++i) {
      const Point projected = plane.projection(corners.p[i]);
      if (!triangle.has_on(projected)) continue;
      if (face_is_x) {
        consider(projected, corners.p[i]);
      } else {
        consider(corners.p[i], projected);
      }
    }
  };
  corner_face(x, y, true);
  corner_face(y, x, false);
}

}  // namespace exact

using exact::closestPointsOfElements;
using exact::Element;
using exact::elementsIntersect;
using exact::elementsSquaredDistance;
using exact::FT;
using exact::intersectionPoints;
using exact::Point;
using exact::posedElement;
using exact::rounded;

double exactPairSquaredDistance(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                                const Pose& pose_b, const TrianglePair& pair) {
  const Element x = posedElement(a, pose_a, pair.a);
  const Element y = posedElement(b, pose_b, pair.b);
  const FT d2 = elementsSquaredDistance(x, y);
  return CGAL::to_double(d2.exact());
}

ExactClosestPoints exactPosedClosestPoints(const std::array<Eigen::Vector3d, 3>& a,
                                           const Pose& pose_a,
                                           const std::array<Eigen::Vector3d, 3>& b,
                                           const Pose& pose_b) {
  const Element x = posedElement(a, pose_a);
  const Element y = posedElement(b, pose_b);
  ExactClosestPoints answer;
  Point best_a;
  Point best_b;
  if (elementsIntersect(x, y)) {
    const std::vector<Point> shared = intersectionPoints(x, y);
    COLLIDO_ASSERT(!shared.empty(), "exact intersection of intersecting elements is empty");
    best_a = shared.front();  // a point both share
    best_b = best_a;
  } else {
    closestPointsOfElements(x, y, best_a, best_b);
  }
  const FT d2 = CGAL::squared_distance(best_a, best_b);
  const auto& exact = d2.exact();
  const std::pair<double, double> bounds = CGAL::to_interval(exact);
  answer.squared_distance = ExactInterval{bounds.first, CGAL::to_double(exact), bounds.second};
  answer.point_a = rounded(best_a);
  answer.point_b = rounded(best_b);
  return answer;
}

}  // namespace collido
