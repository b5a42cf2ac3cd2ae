#include <collido/runner/floor.h>

#include <algorithm>
#include <chrono>
#include <cstddef>

#include <collido/oracle/double_triangle_test.h>
#include <collido/runner/statistics.h>

namespace collido {
namespace {

std::array<Eigen::Vector3d, 3> worldTriangle(const TriangleMesh& mesh, const Pose& pose,
                                             std::int32_t t) {
  std::array<Eigen::Vector3d, 3> out;
  for (int k = 0; k < 3; ++k)
    out[static_cast<std::size_t>(k)] = pose * mesh.vertices.col(mesh.triangles(k, t));
  return out;
}

}  // namespace

void appendWorldPairs(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                      const Pose& pose_b, const std::vector<TrianglePair>& pairs,
                      std::vector<WorldTrianglePair>& out) {
  out.reserve(out.size() + pairs.size());
  for (const TrianglePair& pair : pairs)
    out.emplace_back(worldTriangle(a, pose_a, pair.a), worldTriangle(b, pose_b, pair.b));
}

double floorMicroseconds(const std::vector<WorldTrianglePair>& pairs, int repetitions) {
  if (pairs.empty()) return 0.0;  // nothing to test; a timing would measure only the clock
  using Clock = std::chrono::steady_clock;
  std::vector<double> times;
  // Counting the answers keeps the tests from being optimised away.
  volatile std::size_t intersecting = 0;
  for (int rep = 0; rep < std::max(repetitions, 1); ++rep) {
    std::size_t hits = 0;
    const Clock::time_point start = Clock::now();
    for (const auto& [s, t] : pairs)
      hits += exact::trianglesIntersect(s[0], s[1], s[2], t[0], t[1], t[2]) ? 1 : 0;
    const Clock::time_point stop = Clock::now();
    intersecting = intersecting + hits;
    times.push_back(std::chrono::duration<double, std::micro>(stop - start).count());
  }
  return quantile(times, 0.5);
}

}  // namespace collido
