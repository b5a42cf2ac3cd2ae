#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/oracle/distance_oracle.h>
#include <collido/oracle/first_contact_oracle.h>
#include <collido/query.h>

namespace collido {

/// How much of the answer the oracle computes.
enum class OracleMode {
  kAllPairs,   ///< every intersecting triangle pair
  kFirstPair,  ///< stop at the first one (a boolean answer with one witness)
};

/// The exact reference answer for two posed meshes.
struct OracleAnswer {
  bool intersecting = false;
  std::vector<TrianglePair> pairs;  ///< sorted by (a, b); one witness in kFirstPair mode
  std::size_t candidate_pairs = 0;  ///< pairs whose conservative boxes overlapped
  std::size_t exact_tests = 0;      ///< pairs decided by exact predicates
  /// The exact distance, where a distance query asks about the pair (exactMeshDistance).
  std::optional<MeshDistance> distance;
  /// The first contact over the step from this frame to the next, where a query over a step
  /// asks about the pair (exactFirstContact), and the bracket width it was computed to.
  std::optional<ExactFirstContact> first_contact;
  double first_contact_width = 0.0;
};

/// Every pair (triangle of A, triangle of B) whose closed triangles share at least one point,
/// with A's world vertices = pose_a * v and B's = pose_b * v evaluated *exactly* (rational
/// arithmetic on the double entries of the poses and vertices; the rotation is used as given,
/// not re-orthonormalised). Touching counts as intersecting. Degenerate triangles are decided as
/// the segment or point they are. Candidates come from a uniform grid over conservative
/// (interval) boxes, then CGAL's exact-constructions kernel decides each candidate exactly.
/// This is the ground truth every backend is measured against.
OracleAnswer exactIntersectingPairs(const TriangleMesh& a, const Pose& pose_a,
                                    const TriangleMesh& b, const Pose& pose_b,
                                    OracleMode mode = OracleMode::kAllPairs);

/// Whether two closed triangles given by double coordinates share a point, decided exactly.
/// Degenerate triangles count as their segment or point.
bool exactTrianglesIntersect(const std::array<Eigen::Vector3d, 3>& t1,
                             const std::array<Eigen::Vector3d, 3>& t2);

}  // namespace collido

namespace collido {

/// Whether triangle pair.a of A and pair.b of B (posed as in exactIntersectingPairs) intersect,
/// decided exactly; used to check a single reported pair, e.g. a boolean query's witness.
bool exactPairIntersects(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                         const Pose& pose_b, const TrianglePair& pair);

/// Where two posed triangles meet, computed exactly and each point rounded to double once: the
/// reference for contact geometry. Crossing triangles meet in a segment, touching ones in a
/// point or a segment, coplanar overlapping ones in a convex polygon (degenerate triangles as
/// their segment or point).
struct ExactIntersection {
  enum class Shape { kEmpty, kPoint, kSegment, kPolygon };
  Shape shape = Shape::kEmpty;
  /// World points: the point, the segment's two ends, or the polygon's corners in order.
  std::vector<Eigen::Vector3d> points;
};

/// The intersection of triangle pair.a of A and pair.b of B, posed as in exactIntersectingPairs.
ExactIntersection exactPairIntersection(const TriangleMesh& a, const Pose& pose_a,
                                        const TriangleMesh& b, const Pose& pose_b,
                                        const TrianglePair& pair);

/// The same for triangle `a` (model corners) posed by pose_a and `b` posed by pose_b.
ExactIntersection exactPosedIntersection(const std::array<Eigen::Vector3d, 3>& a,
                                         const Pose& pose_a,
                                         const std::array<Eigen::Vector3d, 3>& b,
                                         const Pose& pose_b);

}  // namespace collido
