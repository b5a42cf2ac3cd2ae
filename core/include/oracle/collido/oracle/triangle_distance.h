#pragma once

#include <array>

#include <Eigen/Core>

namespace collido {

/// The closest points of two triangles, computed in double precision.
struct TriangleClosestPoints {
  double distance = 0.0;                              ///< |point_b - point_a|
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();  ///< on the first triangle
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();  ///< on the second triangle
};

/// The closest points of two closed triangles (corners in any order; degenerate triangles count
/// as the segment or point they are). Disjoint triangles are closest at a vertex–triangle or an
/// edge–edge pair, so the six vertices' closest points on the other triangle and the nine edge
/// pairs are tried; triangles that cross (an edge piercing the other's interior) are at distance
/// 0 at the piercing point. Accurate to a few roundings of the coordinates' magnitude: a caller
/// that needs the exact verdict for touching triangles decides it with the exact predicates
/// (exactTrianglesIntersect) and uses these points as a witness.
TriangleClosestPoints closestPointsOfTriangles(const std::array<Eigen::Vector3d, 3>& a,
                                               const std::array<Eigen::Vector3d, 3>& b);

/// The closest point of a closed triangle to `p` (Voronoi regions of vertices, edges, face).
Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p,
                                       const std::array<Eigen::Vector3d, 3>& t);

/// The closest points of segments [p0, p1] and [q0, q1] (either may be a point); writes them to
/// `on_p` and `on_q` and returns the squared distance.
double closestPointsOfSegments(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                               const Eigen::Vector3d& q0, const Eigen::Vector3d& q1,
                               Eigen::Vector3d& on_p, Eigen::Vector3d& on_q);

}  // namespace collido
