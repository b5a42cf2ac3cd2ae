// The triangle-triangle intersection algorithm, written once over a predicate kernel so that the
// same decisions run on exact double inputs, on uncertain (mapped) points through a certified
// filter, and on exact rational world coordinates.
//
// Cases, after classifying each triangle as a proper triangle, a segment (collinear corners) or
// a point (equal corners):
//  1. triangle/triangle: if all corners of one lie strictly on one side of the other's plane,
//     they are disjoint. If coplanar, decide in a 2D projection (edges cross, or a corner of one
//     lies in the other). Otherwise each meets the other's plane in a segment on the line where
//     the planes meet, and they intersect iff the two segments overlap: with each triangle's
//     apex (the corner alone on its side of the other's plane) turned to the positive side, two
//     orientation signs of apex-to-corner edges compare the segments' ends (Guigue and Devillers,
//     "Fast and robust triangle-triangle overlap test using orientation predicates", 2003),
//     vertices on the other's plane included.
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

namespace collido::exact {

template <typename K>
class TriangleTest {
 public:
  using Point = typename K::Point;

  explicit TriangleTest(K& kernel) : k_(kernel) {}

  bool intersect(const Point& p1, const Point& q1, const Point& r1, const Point& p2,
                 const Point& q2, const Point& r2) {
    return shapesIntersect(classify(p1, q1, r1), classify(p2, q2, r2));
  }

  /// intersect() for two triangles whose corners' sides of the other's plane the caller has
  /// already decided: side1[i] = orient3d(t2[0], t2[1], t2[2], t1[i]), side2[i] =
  /// orient3d(t1[0], t1[1], t1[2], t2[i]), none of them zero (so both triangles are proper and
  /// not coplanar) and neither triangle strictly on one side of the other's plane. Skips the
  /// classification and those six orientations.
  bool crossingTrianglesIntersect(const Point* t1, const int side1[3], const Point* t2,
                                  const int side2[3]) {
    return crossingSegmentsOverlap(t1, side1, t2, side2);
  }

  /// A side a caller has not decided (intersectKnowingSides).
  static constexpr int kUnknownSide = 2;

  /// intersect() for triangles t1, t2 some of whose corners' sides of the other's plane the
  /// caller has decided (side1[i] = orient3d(t2[0], t2[1], t2[2], t1[i]), side2[i] =
  /// orient3d(t1[0], t1[1], t1[2], t2[i]); zeros allowed), kUnknownSide where it has not: only
  /// those are asked. A triangle the caller knows proper (corners not collinear: `t1_proper`, or
  /// a side of the other's corner known non-zero) is not classified.
  bool intersectKnowingSides(const Point* t1, const int side1[3], bool t1_proper, const Point* t2,
                             const int side2[3], bool t2_proper) {
    const bool proper1 = t1_proper || knownProper(side2);
    const bool proper2 = t2_proper || knownProper(side1);
    if (proper1 && proper2) return triangleTriangle(t1, t2, side2, side1);
    const Shape s1 = proper1 ? triangleShape(t1) : classify(t1[0], t1[1], t1[2]);
    const Shape s2 = proper2 ? triangleShape(t2) : classify(t2[0], t2[1], t2[2]);
    if (s1.kind != Kind::kTriangle || s2.kind != Kind::kTriangle) return shapesIntersect(s1, s2);
    return triangleTriangle(s1.p, s2.p, side2, side1);
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

  static bool knownProper(const int side[3]) {
    for (int i = 0; i < 3; ++i) {
      if (side[i] == 1 || side[i] == -1) return true;
    }
    return false;
  }

  static Shape triangleShape(const Point* t) {
    Shape s;
    s.p[0] = t[0];
    s.p[1] = t[1];
    s.p[2] = t[2];
    return s;
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

  // known2, known1: sides of t2's corners against t1's plane and of t1's against t2's that
  // the caller decided (kUnknownSide where not); null: none.
  bool triangleTriangle(const Point* t1, const Point* t2, const int* known2 = nullptr,
                        const int* known1 = nullptr) {
    int side2[3];  // corners of t2 relative to t1's plane
    for (int i = 0; i < 3; ++i) {
      side2[i] =
          known2 && known2[i] != kUnknownSide ? known2[i] : k_.orient3d(t1[0], t1[1], t1[2], t2[i]);
    }
    if (allStrictlyOneSide(side2)) return false;
    // t2's corners all on t1's plane, t2 a proper triangle: the planes are one, so t1's corners
    // are on t2's plane too and their three signs (each an exact zero, the costliest sign to
    // decide) need not be asked.
    if (side2[0] == 0 && side2[1] == 0 && side2[2] == 0) return coplanarTriangles(t1, t2);
    int side1[3];  // corners of t1 relative to t2's plane
    for (int i = 0; i < 3; ++i) {
      side1[i] =
          known1 && known1[i] != kUnknownSide ? known1[i] : k_.orient3d(t2[0], t2[1], t2[2], t1[i]);
    }
    if (allStrictlyOneSide(side1)) return false;
    return crossingSegmentsOverlap(t1, side1, t2, side2);
  }

  // The apex of a triangle that meets a plane without lying in it: the corner `apex` and a sign
  // such that sign * side[apex] >= 0 and sign * side[k] <= 0 for the other two, so the triangle
  // meets the plane in the segment between a point of edge apex-next and one of edge apex-prev.
  struct Apex {
    int corner = 0;
    int sign = 1;
  };
  static Apex apexOf(const int side[3]) {
    for (int sign : {1, -1}) {
      for (int k = 0; k < 3; ++k) {
        const int here = sign * side[k];
        const int next = sign * side[(k + 1) % 3];
        const int prev = sign * side[(k + 2) % 3];
        if (next > 0 || prev > 0 || here < 0) continue;
        if (here > 0 || (next < 0 && prev < 0)) return Apex{k, sign};
      }
    }
    return Apex{};  // unreachable for a triangle meeting the plane without lying in it
  }

  // Two proper triangles, neither strictly on one side of the other's plane and not coplanar:
  // each meets the other's plane in a segment on the line where the planes meet, and they
  // intersect iff the segments overlap. With each triangle turned so that its apex (apexOf) is
  // on the positive side of the other's plane (reversing a triangle's corner order flips its
  // plane's orientation), the overlap is two orientation signs (Guigue and Devillers, 2003).
  bool crossingSegmentsOverlap(const Point* t1, const int side1[3], const Point* t2,
                               const int side2[3]) {
    const Apex apex1 = apexOf(side1);  // t1 against t2's plane
    const Apex apex2 = apexOf(side2);  // t2 against t1's plane
    // Corner order from each apex; apex1.sign < 0 reverses t2 (which negates t1's sides), and
    // apex2.sign < 0 reverses t1.
    const Point& a1 = t1[apex1.corner];
    const Point& b1 = t1[(apex1.corner + (apex2.sign > 0 ? 1 : 2)) % 3];
    const Point& c1 = t1[(apex1.corner + (apex2.sign > 0 ? 2 : 1)) % 3];
    const Point& a2 = t2[apex2.corner];
    const Point& b2 = t2[(apex2.corner + (apex1.sign > 0 ? 1 : 2)) % 3];
    const Point& c2 = t2[(apex2.corner + (apex1.sign > 0 ? 2 : 1)) % 3];
    if (k_.orient3d(a1, b1, a2, b2) > 0) return false;
    return k_.orient3d(a1, c1, c2, a2) <= 0;
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

}  // namespace collido::exact
