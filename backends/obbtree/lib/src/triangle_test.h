// The triangle-triangle intersection algorithm, written once over a predicate kernel so that the
// same decisions run on exact double inputs, on uncertain (mapped) points through a certified
// filter, and on exact rational world coordinates.
//
// Cases, after classifying each triangle as a proper triangle, a segment (collinear corners) or
// a point (equal corners):
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
// Every branch is decided by the sign of an orientation determinant or of a coordinate
// difference. 2D tests drop a coordinate along which the supporting plane is not vertical, which
// maps that plane one-to-one onto the 2D plane; any such coordinate gives the same answer.
//
// A kernel K provides `Point` and four sign functions: orient3d(a, b, c, d), orient2d(a, b, c,
// drop), collinear(a, b, c) and compare(a, b, k) (sign of a[k] - b[k]). A kernel that cannot
// decide a sign may return anything and remember that it was unsure; the caller then discards
// the answer (the algorithm is straight-line code, so any sign sequence terminates).
#pragma once

#include <algorithm>
#include <utility>

namespace collido::obbtree::detail {

template <typename K>
class TriangleTest {
 public:
  using Point = typename K::Point;

  explicit TriangleTest(K& kernel) : k_(kernel) {}

  bool intersect(const Point& p1, const Point& q1, const Point& r1, const Point& p2,
                 const Point& q2, const Point& r2) {
    return shapesIntersect(classify(p1, q1, r1), classify(p2, q2, r2));
  }

 private:
  enum class Kind { kTriangle, kSegment, kPoint };

  struct Shape {
    Kind kind = Kind::kTriangle;
    Point p[3];  // triangle corners; a segment uses p[0] <= p[1] (lexicographic); a point p[0]
  };

  bool lexLess(const Point& a, const Point& b) {
    for (int k = 0; k < 3; ++k) {
      const int s = k_.compare(a, b, k);
      if (s != 0) return s < 0;
    }
    return false;
  }

  bool equal(const Point& a, const Point& b) {
    return k_.compare(a, b, 0) == 0 && k_.compare(a, b, 1) == 0 && k_.compare(a, b, 2) == 0;
  }

  Shape classify(const Point& a, const Point& b, const Point& c) {
    Shape s;
    if (!k_.collinear(a, b, c)) {
      s.kind = Kind::kTriangle;
      s.p[0] = a;
      s.p[1] = b;
      s.p[2] = c;
      return s;
    }
    // Sort three points lexicographically (a fixed network: no comparator contract to break if
    // an unsure kernel answers inconsistently).
    Point sorted[3] = {a, b, c};
    if (lexLess(sorted[1], sorted[0])) std::swap(sorted[0], sorted[1]);
    if (lexLess(sorted[2], sorted[1])) std::swap(sorted[1], sorted[2]);
    if (lexLess(sorted[1], sorted[0])) std::swap(sorted[0], sorted[1]);
    if (equal(sorted[0], sorted[2])) {
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
  int projectionAxis(const Point& a, const Point& b, const Point& c) {
    for (int drop = 0; drop < 2; ++drop) {
      if (k_.orient2d(a, b, c, drop) != 0) return drop;
    }
    return 2;
  }

  // p is known to be collinear with a and b in the projection: is it between them?
  bool withinBounds2d(const Point& p, const Point& a, const Point& b, int drop) {
    for (int k = 0; k < 3; ++k) {
      if (k == drop) continue;
      const int pa = k_.compare(p, a, k);
      const int pb = k_.compare(p, b, k);
      if (pa * pb > 0) return false;  // beyond both ends on this coordinate
    }
    return true;
  }

  bool segmentsIntersect2d(const Point& a, const Point& b, const Point& c, const Point& d,
                           int drop) {
    const int d1 = k_.orient2d(c, d, a, drop);
    const int d2 = k_.orient2d(c, d, b, drop);
    const int d3 = k_.orient2d(a, b, c, drop);
    const int d4 = k_.orient2d(a, b, d, drop);
    if (d1 * d2 < 0 && d3 * d4 < 0) return true;
    return (d1 == 0 && withinBounds2d(a, c, d, drop)) ||
           (d2 == 0 && withinBounds2d(b, c, d, drop)) ||
           (d3 == 0 && withinBounds2d(c, a, b, drop)) || (d4 == 0 && withinBounds2d(d, a, b, drop));
  }

  bool pointInTriangle2d(const Point& p, const Point* t, int drop) {
    const int o1 = k_.orient2d(t[0], t[1], p, drop);
    const int o2 = k_.orient2d(t[1], t[2], p, drop);
    const int o3 = k_.orient2d(t[2], t[0], p, drop);
    return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
  }

  bool coplanarSegmentTriangle(const Point& a, const Point& b, const Point* t) {
    const int drop = projectionAxis(t[0], t[1], t[2]);
    if (pointInTriangle2d(a, t, drop) || pointInTriangle2d(b, t, drop)) return true;
    for (int i = 0; i < 3; ++i) {
      if (segmentsIntersect2d(a, b, t[i], t[(i + 1) % 3], drop)) return true;
    }
    return false;
  }

  bool coplanarTriangles(const Point* t1, const Point* t2) {
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
  bool segmentMeetsTriangle(const Point& a, const Point& b, int side_a, int side_b,
                            const Point* t) {
    if (side_a != 0 && side_a == side_b) return false;
    if (side_a == 0 && side_b == 0) return coplanarSegmentTriangle(a, b, t);
    const int s1 = k_.orient3d(a, b, t[0], t[1]);
    const int s2 = k_.orient3d(a, b, t[1], t[2]);
    const int s3 = k_.orient3d(a, b, t[2], t[0]);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
  }

  static bool allStrictlyOneSide(const int side[3]) {
    return (side[0] > 0 && side[1] > 0 && side[2] > 0) ||
           (side[0] < 0 && side[1] < 0 && side[2] < 0);
  }

  bool triangleTriangle(const Point* t1, const Point* t2) {
    int side2[3];  // corners of t2 relative to t1's plane
    for (int i = 0; i < 3; ++i)
      side2[i] = k_.orient3d(t1[0], t1[1], t1[2], t2[i]);
    if (allStrictlyOneSide(side2)) return false;
    int side1[3];  // corners of t1 relative to t2's plane
    for (int i = 0; i < 3; ++i)
      side1[i] = k_.orient3d(t2[0], t2[1], t2[2], t1[i]);
    if (allStrictlyOneSide(side1)) return false;
    if (side2[0] == 0 && side2[1] == 0 && side2[2] == 0) return coplanarTriangles(t1, t2);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (segmentMeetsTriangle(t1[i], t1[j], side1[i], side1[j], t2)) return true;
      if (segmentMeetsTriangle(t2[i], t2[j], side2[i], side2[j], t1)) return true;
    }
    return false;
  }

  bool triangleSegment(const Point* t, const Point& a, const Point& b) {
    return segmentMeetsTriangle(a, b, k_.orient3d(t[0], t[1], t[2], a),
                                k_.orient3d(t[0], t[1], t[2], b), t);
  }

  bool trianglePoint(const Point* t, const Point& p) {
    return k_.orient3d(t[0], t[1], t[2], p) == 0 &&
           pointInTriangle2d(p, t, projectionAxis(t[0], t[1], t[2]));
  }

  // Both segments have endpoints in lexicographic order.
  bool segmentSegment(const Point& a, const Point& b, const Point& c, const Point& d) {
    if (k_.orient3d(a, b, c, d) != 0) return false;  // skew lines
    const bool abc = k_.collinear(a, b, c);
    const bool abd = k_.collinear(a, b, d);
    if (abc && abd) return !(lexLess(b, c) || lexLess(d, a));  // one line: 1D overlap
    const int drop = abc ? projectionAxis(a, b, d) : projectionAxis(a, b, c);
    return segmentsIntersect2d(a, b, c, d, drop);
  }

  bool segmentPoint(const Point& a, const Point& b, const Point& p) {
    return k_.collinear(a, b, p) && !lexLess(p, a) && !lexLess(b, p);
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
            return equal(x.p[0], y.p[0]);
        }
        break;
    }
    return false;
  }

  K& k_;
};

}  // namespace collido::obbtree::detail
