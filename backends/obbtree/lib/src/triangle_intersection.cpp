// Exact triangle-triangle intersection on double coordinates.
//
// Cases, after classifying each triangle exactly as a proper triangle, a segment (collinear
// corners) or a point (equal corners):
//  1. triangle/triangle: if all corners of one lie strictly on one side of the other's plane,
//     they are disjoint. If coplanar, decide in a 2D projection (edges cross, or a corner of one
//     lies in the other). Otherwise the two meet on the line where their planes meet, and the
//     meeting set is the overlap of two intervals on it; two overlapping intervals always contain
//     an endpoint of one another, and every endpoint lies on a triangle edge, so the triangles
//     intersect iff some edge of one meets the other triangle.
//  2. segment/triangle: the segment crosses the plane (or lies in it: 2D test); the crossing is
//     inside the closed triangle iff the line is on the same side of the three edge lines
//     (orientations of (a, b, edge) all >= 0 or all <= 0).
//  3. point/triangle, segment/segment, segment/point, point/point: coplanarity and collinearity
//     tests, then 2D or 1D (lexicographic order along a line) containment.
// Every branch is decided by signs of orientation determinants, which the predicates compute
// exactly, so the answer is exact for the given doubles. 2D tests drop a coordinate along which
// the supporting plane is not vertical, which maps that plane one-to-one onto the 2D plane.
#include <collido/obbtree/triangle_intersection.h>

#include <algorithm>

#include "exact_predicates.h"

namespace collido::obbtree {
namespace {

using Vec = Eigen::Vector3d;
using detail::collinear;
using detail::orient2d;
using detail::orient3d;

enum class Kind { kTriangle, kSegment, kPoint };

struct Shape {
  Kind kind = Kind::kTriangle;
  Vec p[3];  // triangle corners; a segment uses p[0] <= p[1] (lexicographic); a point p[0]
};

bool lexLess(const Vec& a, const Vec& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

Shape classify(const Vec& a, const Vec& b, const Vec& c) {
  Shape s;
  if (!collinear(a, b, c)) {
    s.kind = Kind::kTriangle;
    s.p[0] = a;
    s.p[1] = b;
    s.p[2] = c;
    return s;
  }
  Vec sorted[3] = {a, b, c};
  std::sort(std::begin(sorted), std::end(sorted), lexLess);
  if (sorted[0] == sorted[2]) {
    s.kind = Kind::kPoint;
    s.p[0] = sorted[0];
  } else {
    s.kind = Kind::kSegment;
    s.p[0] = sorted[0];
    s.p[1] = sorted[2];
  }
  return s;
}

// A coordinate to drop so that the non-collinear a, b, c stay non-collinear in 2D.
int projectionAxis(const Vec& a, const Vec& b, const Vec& c) {
  for (int drop = 0; drop < 2; ++drop) {
    if (orient2d(a, b, c, drop) != 0) return drop;
  }
  return 2;
}

// p is known to be collinear with a and b in the projection: is it between them?
bool withinBounds2d(const Vec& p, const Vec& a, const Vec& b, int drop) {
  for (int k = 0; k < 3; ++k) {
    if (k == drop) continue;
    if (p[k] < std::min(a[k], b[k]) || p[k] > std::max(a[k], b[k])) return false;
  }
  return true;
}

bool segmentsIntersect2d(const Vec& a, const Vec& b, const Vec& c, const Vec& d, int drop) {
  const int d1 = orient2d(c, d, a, drop);
  const int d2 = orient2d(c, d, b, drop);
  const int d3 = orient2d(a, b, c, drop);
  const int d4 = orient2d(a, b, d, drop);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && withinBounds2d(a, c, d, drop)) || (d2 == 0 && withinBounds2d(b, c, d, drop)) ||
         (d3 == 0 && withinBounds2d(c, a, b, drop)) || (d4 == 0 && withinBounds2d(d, a, b, drop));
}

bool pointInTriangle2d(const Vec& p, const Vec* t, int drop) {
  const int o1 = orient2d(t[0], t[1], p, drop);
  const int o2 = orient2d(t[1], t[2], p, drop);
  const int o3 = orient2d(t[2], t[0], p, drop);
  return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

bool coplanarSegmentTriangle(const Vec& a, const Vec& b, const Vec* t) {
  const int drop = projectionAxis(t[0], t[1], t[2]);
  if (pointInTriangle2d(a, t, drop) || pointInTriangle2d(b, t, drop)) return true;
  for (int i = 0; i < 3; ++i) {
    if (segmentsIntersect2d(a, b, t[i], t[(i + 1) % 3], drop)) return true;
  }
  return false;
}

bool coplanarTriangles(const Vec* t1, const Vec* t2) {
  const int drop = projectionAxis(t1[0], t1[1], t1[2]);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (segmentsIntersect2d(t1[i], t1[(i + 1) % 3], t2[j], t2[(j + 1) % 3], drop)) return true;
    }
  }
  // No edges cross: either one triangle contains the other or they are disjoint.
  return pointInTriangle2d(t2[0], t1, drop) || pointInTriangle2d(t1[0], t2, drop);
}

// Segment a-b against triangle t, given the orientations of a and b relative to t's plane.
bool segmentMeetsTriangle(const Vec& a, const Vec& b, int side_a, int side_b, const Vec* t) {
  if (side_a != 0 && side_a == side_b) return false;
  if (side_a == 0 && side_b == 0) return coplanarSegmentTriangle(a, b, t);
  const int s1 = orient3d(a, b, t[0], t[1]);
  const int s2 = orient3d(a, b, t[1], t[2]);
  const int s3 = orient3d(a, b, t[2], t[0]);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

bool allStrictlyOneSide(const int side[3]) {
  return (side[0] > 0 && side[1] > 0 && side[2] > 0) || (side[0] < 0 && side[1] < 0 && side[2] < 0);
}

bool triangleTriangle(const Vec* t1, const Vec* t2) {
  int side2[3];  // corners of t2 relative to t1's plane
  for (int i = 0; i < 3; ++i)
    side2[i] = orient3d(t1[0], t1[1], t1[2], t2[i]);
  if (allStrictlyOneSide(side2)) return false;
  int side1[3];  // corners of t1 relative to t2's plane
  for (int i = 0; i < 3; ++i)
    side1[i] = orient3d(t2[0], t2[1], t2[2], t1[i]);
  if (allStrictlyOneSide(side1)) return false;
  if (side2[0] == 0 && side2[1] == 0 && side2[2] == 0) return coplanarTriangles(t1, t2);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (segmentMeetsTriangle(t1[i], t1[j], side1[i], side1[j], t2)) return true;
    if (segmentMeetsTriangle(t2[i], t2[j], side2[i], side2[j], t1)) return true;
  }
  return false;
}

bool triangleSegment(const Vec* t, const Vec& a, const Vec& b) {
  return segmentMeetsTriangle(a, b, orient3d(t[0], t[1], t[2], a), orient3d(t[0], t[1], t[2], b),
                              t);
}

bool trianglePoint(const Vec* t, const Vec& p) {
  return orient3d(t[0], t[1], t[2], p) == 0 &&
         pointInTriangle2d(p, t, projectionAxis(t[0], t[1], t[2]));
}

// Both segments have endpoints in lexicographic order.
bool segmentSegment(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  if (orient3d(a, b, c, d) != 0) return false;  // skew lines
  const bool abc = collinear(a, b, c);
  const bool abd = collinear(a, b, d);
  if (abc && abd) return !(lexLess(b, c) || lexLess(d, a));  // one line: 1D overlap
  const int drop = abc ? projectionAxis(a, b, d) : projectionAxis(a, b, c);
  return segmentsIntersect2d(a, b, c, d, drop);
}

bool segmentPoint(const Vec& a, const Vec& b, const Vec& p) {
  return collinear(a, b, p) && !lexLess(p, a) && !lexLess(b, p);
}

bool shapesIntersect(const Shape& x, const Shape& y) {
  switch (x.kind) {
    case Kind::kTriangle:
      switch (y.kind) {
        case Kind::kTriangle:
          return triangleTriangle(x.p, y.p);
        case Kind::kSegment:
          return triangleSegment(x.p, y.p[0], y.p[1]);
        case Kind::kPoint:
          return trianglePoint(x.p, y.p[0]);
      }
      break;
    case Kind::kSegment:
      switch (y.kind) {
        case Kind::kTriangle:
          return triangleSegment(y.p, x.p[0], x.p[1]);
        case Kind::kSegment:
          return segmentSegment(x.p[0], x.p[1], y.p[0], y.p[1]);
        case Kind::kPoint:
          return segmentPoint(x.p[0], x.p[1], y.p[0]);
      }
      break;
    case Kind::kPoint:
      switch (y.kind) {
        case Kind::kTriangle:
          return trianglePoint(y.p, x.p[0]);
        case Kind::kSegment:
          return segmentPoint(y.p[0], y.p[1], x.p[0]);
        case Kind::kPoint:
          return x.p[0] == y.p[0];
      }
      break;
  }
  return false;
}

}  // namespace

bool trianglesIntersect(const Vec& p1, const Vec& q1, const Vec& r1, const Vec& p2, const Vec& q2,
                        const Vec& r2) {
  // Most pairs reaching this test are proper triangles; classify() costs one collinearity test.
  return shapesIntersect(classify(p1, q1, r1), classify(p2, q2, r2));
}

}  // namespace collido::obbtree
