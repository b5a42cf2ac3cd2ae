#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include <Eigen/Core>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/query.h>

namespace collido {

/// The exact reference distance between two posed meshes.
struct MeshDistance {
  /// The minimum distance between the closed triangle sets, 0 when they share a point (decided
  /// exactly): the exact squared distance of the closest pair (rational arithmetic on the double
  /// inputs, posed exactly as exactIntersectingPairs poses them), rounded to double, then its
  /// square root; within two units in the last place of the true distance. The pairs decided
  /// exactly are those whose double distance lies within rounding (256 units in the last place
  /// of the largest coordinate) of the smallest, nearest first, at most 64: where more tie
  /// (parallel faces), the answer is exact for the pairs decided and within that rounding of
  /// the true minimum.
  double distance = std::numeric_limits<double>::infinity();
  TrianglePair pair;  ///< a closest pair (the smallest (a, b) among exact ties)
  /// Closest points of that pair in the world frame, computed in double precision (the exact
  /// distance is the measure; the points show where).
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
  std::size_t candidate_pairs = 0;  ///< pairs whose double distance was computed
  std::size_t exact_tests = 0;      ///< pairs whose distance was computed exactly
};

/// The exact minimum distance between A (world = pose_a * v) and B. First the exact
/// intersection test (a shared point: distance 0); otherwise triangle pairs are swept along x,
/// boxes grown by a search radius that starts at the gap between the meshes' bounds and grows
/// until the closest pair found lies within it (so every pair that could be closer was a
/// candidate); double-precision distances choose the pairs within rounding of the best, and
/// those are decided exactly. Meshes must not be empty.
MeshDistance exactMeshDistance(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                               const Pose& pose_b);

/// The squared distance between triangle pair.a of A and pair.b of B (posed as above), computed
/// exactly (degenerate triangles as their segment or point) and rounded to double.
double exactPairSquaredDistance(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                                const Pose& pose_b, const TrianglePair& pair);

/// An interval of doubles holding an exact value, and the double nearest to it.
struct ExactInterval {
  double lower = 0.0;
  double nearest = 0.0;
  double upper = 0.0;
};

/// The closest points of two posed triangles, computed exactly and rounded once.
struct ExactClosestPoints {
  ExactInterval squared_distance;  ///< the tightest interval of doubles around it, and nearest
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();  ///< world, on a (each coordinate rounded)
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();  ///< world, on b
};

/// The closest points of triangle `a` posed by pose_a and `b` posed by pose_b (corners in model
/// coordinates, posed exactly as above; degenerate triangles as their segment or point), in
/// exact rational arithmetic: the closest points of every pair of edges and of every corner
/// projected into the other triangle where it falls inside, the nearest pair exactly. For
/// triangles that share a point the squared distance is 0 and the points are one shared point.
ExactClosestPoints exactPosedClosestPoints(const std::array<Eigen::Vector3d, 3>& a,
                                           const Pose& pose_a,
                                           const std::array<Eigen::Vector3d, 3>& b,
                                           const Pose& pose_b);

}  // namespace collido
