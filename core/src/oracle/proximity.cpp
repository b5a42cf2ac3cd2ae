// Do two posed meshes come within a distance? A sweep over boxes grown by the distance, then
// CGAL's distances between the candidate triangles (or the segments and points degenerate
// triangles are).
#include <collido/oracle/proximity.h>

#include <algorithm>
#include <array>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>

#include <collido/oracle/exact_oracle.h>

#include "box_sweep.h"

namespace collido {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;

enum Kind { kTriangle, kSegment, kPoint };

struct Element {
  Kind kind = kTriangle;
  std::array<Point, 3> p;
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;
};

Element element(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Element e;
  e.p = {Point(a.x(), a.y(), a.z()), Point(b.x(), b.y(), b.z()), Point(c.x(), c.y(), c.z())};
  e.lo = a.cwiseMin(b).cwiseMin(c);
  e.hi = a.cwiseMax(b).cwiseMax(c);
  if (CGAL::collinear(e.p[0], e.p[1], e.p[2])) {
    // The segment between the two farthest corners, or a point.
    std::array<Point, 3> q = e.p;
    std::sort(q.begin(), q.end());
    e.kind = q[0] == q[2] ? kPoint : kSegment;
    e.p[0] = q[0];
    e.p[1] = q[2];
  }
  return e;
}

K::Triangle_3 triangle(const Element& e) {
  return {e.p[0], e.p[1], e.p[2]};
}
K::Segment_3 segment(const Element& e) {
  return {e.p[0], e.p[1]};
}

double triangleSegment(const Element& t, const Element& s) {
  const K::Triangle_3 tri = triangle(t);
  const K::Segment_3 seg = segment(s);
  if (CGAL::do_intersect(tri, seg)) return 0.0;
  double best = std::min(CGAL::squared_distance(seg.source(), tri),
                         CGAL::squared_distance(seg.target(), tri));
  for (int i = 0; i < 3; ++i)
    best = std::min(best, CGAL::squared_distance(seg, K::Segment_3(t.p[i], t.p[(i + 1) % 3])));
  return best;
}

// Squared distance between two elements.
double squaredDistance(const Element& x, const Element& y) {
  if (x.kind > y.kind) return squaredDistance(y, x);  // x is the "larger" kind
  switch (x.kind) {
    case kTriangle:
      if (y.kind == kTriangle) return CGAL::squared_distance(triangle(x), triangle(y));
      if (y.kind == kSegment) return triangleSegment(x, y);
      return CGAL::squared_distance(y.p[0], triangle(x));
    case kSegment:
      if (y.kind == kSegment) return CGAL::squared_distance(segment(x), segment(y));
      return CGAL::squared_distance(y.p[0], segment(x));
    case kPoint:
      return CGAL::squared_distance(x.p[0], y.p[0]);
  }
  return 0.0;
}

std::vector<Element> posed(const TriangleMesh& mesh, const Pose& pose) {
  std::vector<Element> out;
  out.reserve(mesh.triangleCount());
  const Eigen::Matrix3Xd world = pose * mesh.vertices;
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    out.push_back(element(world.col(mesh.triangles(0, t)), world.col(mesh.triangles(1, t)),
                          world.col(mesh.triangles(2, t))));
  }
  return out;
}

}  // namespace

ProximityAnswer meshesWithinDistance(const TriangleMesh& a, const Pose& pose_a,
                                     const TriangleMesh& b, const Pose& pose_b, double distance) {
  ProximityAnswer answer;
  if (!(distance > 0.0)) {
    const OracleAnswer exact = exactIntersectingPairs(a, pose_a, b, pose_b, OracleMode::kFirstPair);
    answer.within = exact.intersecting;
    if (exact.intersecting) answer.closest = 0.0;
    answer.candidate_pairs = exact.candidate_pairs;
    return answer;
  }
  const std::vector<Element> xs = posed(a, pose_a);
  const std::vector<Element> ys = posed(b, pose_b);
  // Sweep along x over both sets, A's boxes grown by the distance.
  const double limit = distance * distance;
  const auto near = [&](const Element& x, const Element& y) {
    return (x.lo.array() - distance <= y.hi.array()).all() &&
           (y.lo.array() <= x.hi.array() + distance).all();
  };
  detail::sweepPairs(
      xs.size(), [&](std::size_t i) { return xs[i].lo.x(); },
      [&](std::size_t i) { return xs[i].hi.x(); }, ys.size(),
      [&](std::size_t j) { return ys[j].lo.x(); }, [&](std::size_t j) { return ys[j].hi.x(); },
      distance,
      [&](std::size_t i, std::size_t j) {
        const Element& x = xs[i];
        const Element& y = ys[j];
        if (!near(x, y)) return true;
        ++answer.candidate_pairs;
        const double d2 = squaredDistance(x, y);
        answer.closest = std::min(answer.closest, std::sqrt(d2));
        answer.within = d2 <= limit;
        return !answer.within;  // the first pair within the distance answers it
      });
  return answer;
}

}  // namespace collido
