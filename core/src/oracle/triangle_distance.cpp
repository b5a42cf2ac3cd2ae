// Closest points of triangles in double precision: the features where disjoint triangles are
// closest (vertex–triangle, edge–edge), and the piercing point of crossing ones.
#include <collido/oracle/triangle_distance.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace collido {
namespace {

using Vec = Eigen::Vector3d;

double clamp01(double x) {
  return std::clamp(x, 0.0, 1.0);
}

// The closest point of the three edges of a degenerate (zero-area) triangle.
Vec closestPointOnEdges(const Vec& p, const std::array<Vec, 3>& t) {
  Vec best = t[0];
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    Vec on_edge;
    Vec on_point;
    const double d2 = closestPointsOfSegments(t[i], t[(i + 1) % 3], p, p, on_edge, on_point);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = on_edge;
    }
  }
  return best;
}

// Where segment [p, q] crosses the interior or boundary of triangle t, if it does (t not
// degenerate, the segment not lying in its plane).
bool pierce(const Vec& p, const Vec& q, const std::array<Vec, 3>& t, Vec& at) {
  const Vec n = (t[1] - t[0]).cross(t[2] - t[0]);
  if (!(n.squaredNorm() > 0.0)) return false;
  const double sp = n.dot(p - t[0]);
  const double sq = n.dot(q - t[0]);
  if ((sp > 0.0 && sq > 0.0) || (sp < 0.0 && sq < 0.0) || sp == sq) return false;
  const Vec x = p + (sp / (sp - sq)) * (q - p);
  for (int i = 0; i < 3; ++i) {
    if ((t[(i + 1) % 3] - t[i]).cross(x - t[i]).dot(n) < 0.0) return false;
  }
  at = x;
  return true;
}

}  // namespace

double closestPointsOfSegments(const Vec& p0, const Vec& p1, const Vec& q0, const Vec& q1,
                               Vec& on_p, Vec& on_q) {
  const Vec u = p1 - p0;
  const Vec v = q1 - q0;
  const Vec r = p0 - q0;
  const double a = u.squaredNorm();
  const double e = v.squaredNorm();
  const double f = v.dot(r);
  double s = 0.0;
  double t = 0.0;
  if (a <= 0.0 && e <= 0.0) {
    // two points
  } else if (a <= 0.0) {
    t = clamp01(f / e);
  } else {
    const double c = u.dot(r);
    if (e <= 0.0) {
      s = clamp01(-c / a);
    } else {
      // Minimise |p0 + s u - q0 - t v|^2 over the square; parallel lines take s = 0 and let
      // the clamps below find the closest end.
      const double b = u.dot(v);
      const double denom = a * e - b * b;
      s = denom > 0.0 ? clamp01((b * f - c * e) / denom) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = clamp01(-c / a);
      } else if (t > 1.0) {
        t = 1.0;
        s = clamp01((b - c) / a);
      }
    }
  }
  on_p = p0 + s * u;
  on_q = q0 + t * v;
  return (on_p - on_q).squaredNorm();
}

Vec closestPointOnTriangle(const Vec& p, const std::array<Vec, 3>& t) {
  // Voronoi regions in turn: vertex a, vertex b, edge ab, vertex c, edge ac, edge bc, face.
  const Vec& a = t[0];
  const Vec& b = t[1];
  const Vec& c = t[2];
  const Vec ab = b - a;
  const Vec ac = c - a;
  const Vec ap = p - a;
  const double d1 = ab.dot(ap);
  const double d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec bp = p - b;
  const double d3 = ab.dot(bp);
  const double d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec cp = p - c;
  const double d5 = ab.dot(cp);
  const double d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0) || !std::isfinite(sum)) return closestPointOnEdges(p, t);
  return a + ab * (vb / sum) + ac * (vc / sum);
}

TriangleClosestPoints closestPointsOfTriangles(const std::array<Vec, 3>& a,
                                               const std::array<Vec, 3>& b) {
  TriangleClosestPoints best;
  double best_d2 = std::numeric_limits<double>::infinity();
  const auto consider = [&](const Vec& on_a, const Vec& on_b) {
    const double d2 = (on_a - on_b).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best.point_a = on_a;
      best.point_b = on_b;
    }
  };
  for (int i = 0; i < 3; ++i) {
    consider(a[i], closestPointOnTriangle(a[i], b));
    consider(closestPointOnTriangle(b[i], a), b[i]);
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Vec on_a;
      Vec on_b;
      closestPointsOfSegments(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3], on_a, on_b);
      consider(on_a, on_b);
    }
  }
  if (best_d2 > 0.0) {
    Vec at;
    for (int i = 0; i < 3 && best_d2 > 0.0; ++i) {
      if (pierce(a[i], a[(i + 1) % 3], b, at)) consider(at, at);
      if (best_d2 > 0.0 && pierce(b[i], b[(i + 1) % 3], a, at)) consider(at, at);
    }
  }
  best.distance = std::sqrt(best_d2);
  return best;
}

}  // namespace collido
