#pragma once

#include <array>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/query.h>

namespace collido {

/// Two triangles in world coordinates (pose * v, rounded to doubles).
using WorldTrianglePair = std::pair<std::array<Eigen::Vector3d, 3>, std::array<Eigen::Vector3d, 3>>;

/// Appends the world triangles of each pair (a triangle of `a`, a triangle of `b`), placed by
/// their poses.
void appendWorldPairs(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                      const Pose& pose_b, const std::vector<TrianglePair>& pairs,
                      std::vector<WorldTrianglePair>& out);

/// The floor of an all-pairs query: the median over `repetitions` runs (at least one) of the
/// time, in microseconds, to decide every pair of `pairs` with one exact triangle-triangle test
/// (exact::trianglesIntersect, the fastest exact test we have). No all-pairs answer can cost
/// less than testing each pair it reports once; a backend's floor ratio is its query time over
/// this time, measured in the same process. 0 without pairs.
double floorMicroseconds(const std::vector<WorldTrianglePair>& pairs, int repetitions);

}  // namespace collido
