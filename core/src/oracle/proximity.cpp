// Do two posed meshes come within a distance? A sweep over boxes grown by the distance, then
// CGAL's distances between the candidate triangles (or the segments and points degenerate
// triangles are).
#include <collido/oracle/proximity.h>

#include <algorithm>
#include <array>
#include <limits>
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
  std::array<Eigen::Vector3d, 3> corners;  // p in doubles, for the plane bound
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;
  // A triangle's plane for the bound of separatedByPlaneOf, worked out once per triangle rather
  // than once per candidate pair: (p1 - p0) x (p2 - p0) and its length, 0 where there is no
  // usable plane (a segment, a point, or a sliver whose computed normal can point far off: its
  // error grows as 1 / sin of the smallest angle, and below sin 1e-3 the slack would not cover
  // it).
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double normal_length = 0.0;
};

Element element(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Element e;
  e.p = {Point(a.x(), a.y(), a.z()), Point(b.x(), b.y(), b.z()), Point(c.x(), c.y(), c.z())};
  e.corners = {a, b, c};
  e.lo = a.cwiseMin(b).cwiseMin(c);
  e.hi = a.cwiseMax(b).cwiseMax(c);
  if (CGAL::collinear(e.p[0], e.p[1], e.p[2])) {
    // The segment between the two farthest corners, or a point.
    std::array<Point, 3> q = e.p;
    std::sort(q.begin(), q.end());
    e.kind = q[0] == q[2] ? kPoint : kSegment;
    e.p[0] = q[0];
    e.p[1] = q[2];
    for (std::size_t i = 0; i < 2; ++i)
      e.corners[i] = Eigen::Vector3d(e.p[i].x(), e.p[i].y(), e.p[i].z());
    return e;
  }
  const Eigen::Vector3d u = b - a;
  const Eigen::Vector3d v = c - a;
  const Eigen::Vector3d normal = u.cross(v);
  const double length = normal.norm();
  if (length > 1e-3 * u.norm() * v.norm()) {
    e.normal = normal;
    e.normal_length = length;
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

// Whether the plane of triangle `x` proves `y` farther than `distance`: every corner of `y` more
// than that (and a rounding slack) on one side of it. A cheap bound that settles most candidate
// pairs of two near-parallel faces (a docking face, a tracked part resting on another) before
// CGAL's triangle distance, which was most of a tracked scene's run time.
bool separatedByPlaneOf(const Element& x, const Element& y, double distance) {
  if (x.normal_length == 0.0) return false;
  const Eigen::Vector3d& origin = x.corners[0];
  const int corners = y.kind == kTriangle ? 3 : y.kind == kSegment ? 2 : 1;
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  double scale = origin.cwiseAbs().maxCoeff();
  for (int i = 0; i < corners; ++i) {
    const Eigen::Vector3d& corner = y.corners[static_cast<std::size_t>(i)];
    const double side = x.normal.dot(corner - origin) / x.normal_length;
    lowest = std::min(lowest, side);
    highest = std::max(highest, side);
    scale = std::max(scale, corner.cwiseAbs().maxCoeff());
  }
  const double bound = distance + 1e-10 * (distance + scale);
  return lowest > bound || highest < -bound;
}

// The posed triangles of `mesh` whose boxes, grown by `reach`, meet `region`: only those can come
// within the distance of the other mesh. Two modules docking end to end keep the triangles near
// their docking faces, not the whole hulls the sweep would otherwise pair along its axis.
std::vector<Element> posedNear(const TriangleMesh& mesh, const Eigen::Matrix3Xd& world,
                               const Eigen::AlignedBox3d& region, double reach) {
  std::vector<Element> out;
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    const Eigen::Vector3d& a = world.col(mesh.triangles(0, t));
    const Eigen::Vector3d& b = world.col(mesh.triangles(1, t));
    const Eigen::Vector3d& c = world.col(mesh.triangles(2, t));
    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c).array() - reach;
    const Eigen::Vector3d hi = a.cwiseMax(b).cwiseMax(c).array() + reach;
    if ((lo.array() <= region.max().array()).all() && (region.min().array() <= hi.array()).all())
      out.push_back(element(a, b, c));
  }
  return out;
}

Eigen::AlignedBox3d boundsOf(const std::vector<Element>& elements) {
  Eigen::AlignedBox3d box;
  for (const Element& e : elements) {
    box.extend(e.lo);
    box.extend(e.hi);
  }
  return box;
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
  const Eigen::Matrix3Xd world_a = pose_a * a.vertices;
  const Eigen::Matrix3Xd world_b = pose_b * b.vertices;
  Eigen::AlignedBox3d all_b;
  for (Eigen::Index v = 0; v < world_b.cols(); ++v)
    all_b.extend(Eigen::Vector3d(world_b.col(v)));
  const std::vector<Element> xs = posedNear(a, world_a, all_b, distance);
  const std::vector<Element> ys = posedNear(b, world_b, boundsOf(xs), distance);
  // Sweep over both sets, A's boxes grown by the distance, along the axis the kept triangles
  // spread along most (the fewest open at once).
  const Eigen::Index axis = [&] {
    Eigen::Index longest = 0;
    const Eigen::AlignedBox3d kept = boundsOf(ys);
    if (!kept.isEmpty()) kept.sizes().maxCoeff(&longest);
    return longest;
  }();
  const double limit = distance * distance;
  const auto near = [&](const Element& x, const Element& y) {
    return (x.lo.array() - distance <= y.hi.array()).all() &&
           (y.lo.array() <= x.hi.array() + distance).all();
  };
  detail::sweepPairs(
      xs.size(), [&](std::size_t i) { return xs[i].lo[axis]; },
      [&](std::size_t i) { return xs[i].hi[axis]; }, ys.size(),
      [&](std::size_t j) { return ys[j].lo[axis]; }, [&](std::size_t j) { return ys[j].hi[axis]; },
      distance,
      [&](std::size_t i, std::size_t j) {
        const Element& x = xs[i];
        const Element& y = ys[j];
        if (!near(x, y)) return true;
        ++answer.candidate_pairs;
        if (separatedByPlaneOf(x, y, distance) || separatedByPlaneOf(y, x, distance)) return true;
        const double d2 = squaredDistance(x, y);
        answer.closest = std::min(answer.closest, std::sqrt(d2));
        answer.within = d2 <= limit;
        return !answer.within;  // the first pair within the distance answers it
      });
  return answer;
}

}  // namespace collido
