// The reference contact of a triangle pair (docs/DESIGN.md, "Contact geometry").
#include <collido/oracle/contact_reference.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <collido/oracle/triangle_distance.h>

namespace collido {
namespace {

std::optional<Eigen::Vector3d> unitNormal(const std::array<Eigen::Vector3d, 3>& t) {
  const Eigen::Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]);
  const double length = n.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
  return Eigen::Vector3d(n / length);
}

// How far the corners of `other` reach behind the plane through `on_plane` with unit `normal`.
double depthBehind(const Eigen::Vector3d& normal, const Eigen::Vector3d& on_plane,
                   const std::array<Eigen::Vector3d, 3>& other) {
  double depth = 0.0;
  for (const Eigen::Vector3d& v : other)
    depth = std::max(depth, normal.dot(on_plane - v));
  return depth;
}

}  // namespace

ContactFrame contactFrame(const std::array<Eigen::Vector3d, 3>& a,
                          const std::array<Eigen::Vector3d, 3>& b) {
  ContactFrame frame;
  frame.normal_a = unitNormal(a);
  if (const std::optional<Eigen::Vector3d> n_b = unitNormal(b)) frame.normal_b = -*n_b;
  if (frame.normal_a) frame.depth_a = depthBehind(*frame.normal_a, a[0], b);
  // Behind B's plane means on the side its normal points away from: -n_B is stored.
  if (frame.normal_b) frame.depth_b = depthBehind(-*frame.normal_b, b[0], a);
  if (frame.normal_a && (!frame.normal_b || frame.depth_a <= frame.depth_b)) {
    frame.owner = NormalOwner::kA;
    frame.normal = *frame.normal_a;
    frame.depth = frame.depth_a;
  } else if (frame.normal_b) {
    frame.owner = NormalOwner::kB;
    frame.normal = *frame.normal_b;
    frame.depth = frame.depth_b;
  }
  return frame;
}

PairContact exactPairContact(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                             const Pose& pose_b, const TrianglePair& pair) {
  PairContact contact;
  contact.set = exactPairIntersection(a, pose_a, b, pose_b, pair);
  contact.point = intersectionMean(contact.set);
  contact.frame = contactFrame(posedTriangle(a, pose_a, pair.a), posedTriangle(b, pose_b, pair.b));
  return contact;
}

Eigen::Vector3d intersectionMean(const ExactIntersection& set) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : set.points)
    sum += p;
  return set.points.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(set.points.size()));
}

double distanceToIntersection(const ExactIntersection& set, const Eigen::Vector3d& p) {
  const std::vector<Eigen::Vector3d>& q = set.points;
  switch (set.shape) {
    case ExactIntersection::Shape::kEmpty:
      return std::numeric_limits<double>::infinity();
    case ExactIntersection::Shape::kPoint:
      return (p - q[0]).norm();
    case ExactIntersection::Shape::kSegment: {
      Eigen::Vector3d on_segment;
      Eigen::Vector3d on_point;
      return std::sqrt(closestPointsOfSegments(q[0], q[1], p, p, on_segment, on_point));
    }
    case ExactIntersection::Shape::kPolygon:
      break;
  }
  // A convex polygon: a fan of triangles from its first corner, each measured as a closed
  // triangle that may be degenerate (exact sets can be slivers with corners a rounding apart).
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i + 1 < q.size(); ++i)
    best = std::min(best, distanceToTriangle(p, {q[0], q[i], q[i + 1]}));
  return best;
}

std::array<Eigen::Vector3d, 3> posedTriangle(const TriangleMesh& mesh, const Pose& pose,
                                             std::int32_t t) {
  std::array<Eigen::Vector3d, 3> corners;
  for (int k = 0; k < 3; ++k)
    corners[static_cast<std::size_t>(k)] = pose * mesh.corner(static_cast<std::size_t>(t), k);
  return corners;
}

double distanceToTriangle(const Eigen::Vector3d& p, const std::array<Eigen::Vector3d, 3>& t) {
  const TriangleClosestPoints closest = closestPointsOfTriangles({p, p, p}, t);
  return (closest.point_b - closest.point_a).norm();
}

double intersectionLength(const ExactIntersection& set) {
  const std::vector<Eigen::Vector3d>& q = set.points;
  if (set.shape == ExactIntersection::Shape::kSegment) return (q[1] - q[0]).norm();
  if (set.shape != ExactIntersection::Shape::kPolygon) return 0.0;
  double perimeter = 0.0;
  for (std::size_t i = 0; i < q.size(); ++i)
    perimeter += (q[(i + 1) % q.size()] - q[i]).norm();
  return perimeter / 2.0;
}

}  // namespace collido
