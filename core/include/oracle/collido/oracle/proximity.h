#pragma once

#include <cstddef>
#include <limits>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>

namespace collido {

/// Whether two posed meshes come within a distance of each other.
struct ProximityAnswer {
  bool within = false;
  /// The smallest distance found between candidate triangle pairs (those whose boxes come
  /// within the distance), leaving out pairs that the plane of one triangle proves farther than
  /// the distance; infinity when there was none. With `within`, the search stopped at the first
  /// pair within the distance, so this is that pair's distance.
  double closest = std::numeric_limits<double>::infinity();
  std::size_t candidate_pairs = 0;
};

/// Whether some triangle of A (world = pose_a * v) and some triangle of B come within
/// `distance` (>= 0): a possible contact when each pose may be off by up to that much.
/// Distances are CGAL's triangle distances on the posed doubles (filtered predicates, inexact
/// constructions: accurate to rounding, not exact; the margin is an estimate anyway);
/// degenerate triangles count as the segment or point they are. With distance 0 the answer is
/// the exact oracle's (exactIntersectingPairs).
ProximityAnswer meshesWithinDistance(const TriangleMesh& a, const Pose& pose_a,
                                     const TriangleMesh& b, const Pose& pose_b, double distance);

}  // namespace collido
