// The exact reference distance: a swept search for candidate pairs in double precision, the
// winner decided in exact arithmetic.
#include <collido/oracle/distance_oracle.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <collido/oracle/exact_oracle.h>
#include <collido/oracle/triangle_distance.h>

#include "box_sweep.h"

namespace collido {
namespace {

struct PosedTriangle {
  std::array<Eigen::Vector3d, 3> corners;
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;
};

std::vector<PosedTriangle> posed(const TriangleMesh& mesh, const Pose& pose, double& magnitude) {
  const Eigen::Matrix3Xd world = pose * mesh.vertices;
  magnitude = std::max(magnitude, world.cwiseAbs().maxCoeff());
  std::vector<PosedTriangle> out(mesh.triangleCount());
  for (std::size_t t = 0; t < out.size(); ++t) {
    PosedTriangle& p = out[t];
    for (int k = 0; k < 3; ++k)
      p.corners[static_cast<std::size_t>(k)] =
          world.col(mesh.triangles(k, static_cast<Eigen::Index>(t)));
    p.lo = p.corners[0].cwiseMin(p.corners[1]).cwiseMin(p.corners[2]);
    p.hi = p.corners[0].cwiseMax(p.corners[1]).cwiseMax(p.corners[2]);
  }
  return out;
}

double boxGap(const PosedTriangle& x, const PosedTriangle& y) {
  const Eigen::Vector3d gap = (x.lo - y.hi).cwiseMax(y.lo - x.hi).cwiseMax(Eigen::Vector3d::Zero());
  return gap.norm();
}

struct Candidate {
  double distance;
  std::int32_t a;
  std::int32_t b;
};

// Every pair whose boxes come within `radius`, with its double distance, skipping pairs whose
// box gap already exceeds the best distance found plus `slack`; swept along `axis`, where the
// meshes spread most.
std::vector<Candidate> sweep(const std::vector<PosedTriangle>& xs,
                             const std::vector<PosedTriangle>& ys, int axis, double radius,
                             double slack, double& best, std::size_t& computed) {
  std::vector<Candidate> out;
  detail::sweepPairs(
      xs.size(), [&](std::size_t i) { return xs[i].lo[axis]; },
      [&](std::size_t i) { return xs[i].hi[axis]; }, ys.size(),
      [&](std::size_t j) { return ys[j].lo[axis]; }, [&](std::size_t j) { return ys[j].hi[axis]; },
      radius,
      [&](std::size_t i, std::size_t j) {
        const double gap = boxGap(xs[i], ys[j]);
        if (gap > radius || gap > best + slack) return true;
        ++computed;
        const double d = closestPointsOfTriangles(xs[i].corners, ys[j].corners).distance;
        best = std::min(best, d);
        out.push_back({d, static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
        return true;
      });
  return out;
}

}  // namespace

MeshDistance exactMeshDistance(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                               const Pose& pose_b) {
  MeshDistance answer;
  double magnitude = 0.0;
  const std::vector<PosedTriangle> xs = posed(a, pose_a, magnitude);
  const std::vector<PosedTriangle> ys = posed(b, pose_b, magnitude);
  const auto finish = [&](const TrianglePair& pair, double distance) {
    answer.pair = pair;
    answer.distance = distance;
    const TriangleClosestPoints points = closestPointsOfTriangles(
        xs[static_cast<std::size_t>(pair.a)].corners, ys[static_cast<std::size_t>(pair.b)].corners);
    answer.point_a = points.point_a;
    answer.point_b = points.point_b;
    if (distance == 0.0) answer.point_b = answer.point_a;  // one shared point, as computed
  };
  if (xs.empty() || ys.empty()) return answer;

  const OracleAnswer touching =
      exactIntersectingPairs(a, pose_a, b, pose_b, OracleMode::kFirstPair);
  answer.exact_tests = touching.exact_tests;
  if (touching.intersecting) {
    finish(touching.pairs.front(), 0.0);
    return answer;
  }

  // Double distances of posed doubles differ from the exact ones by a few roundings of the
  // coordinates' magnitude; this bounds it generously.
  const double slack = 256.0 * std::numeric_limits<double>::epsilon() * std::max(magnitude, 1e-300);
  Eigen::Vector3d lo_a = xs.front().lo, hi_a = xs.front().hi;
  Eigen::Vector3d lo_b = ys.front().lo, hi_b = ys.front().hi;
  for (const PosedTriangle& x : xs) {
    lo_a = lo_a.cwiseMin(x.lo);
    hi_a = hi_a.cwiseMax(x.hi);
  }
  for (const PosedTriangle& y : ys) {
    lo_b = lo_b.cwiseMin(y.lo);
    hi_b = hi_b.cwiseMax(y.hi);
  }
  const double size = std::max((hi_a - lo_a).norm(), (hi_b - lo_b).norm());
  const double bounds_gap =
      (lo_a - hi_b).cwiseMax(lo_b - hi_a).cwiseMax(Eigen::Vector3d::Zero()).norm();
  const Eigen::Vector3d spread = hi_a.cwiseMax(hi_b) - lo_a.cwiseMin(lo_b);
  int axis = 0;
  spread.maxCoeff(&axis);
  double radius = std::max(bounds_gap, 1e-3 * size) + slack;
  std::vector<Candidate> candidates;
  double best = std::numeric_limits<double>::infinity();
  for (;;) {
    candidates = sweep(xs, ys, axis, radius, slack, best, answer.candidate_pairs);
    // Every pair closer than `radius` (less the rounding) was a candidate: done when the best
    // lies within it; else search again out to the best found (or further, if none).
    if (best <= radius - slack) break;
    radius = std::isfinite(best) ? best + 2.0 * slack : 4.0 * radius + size;
  }
  // The exact winner among the pairs within rounding of the best, nearest first (ties by pair).
  // Parallel faces put many pairs at one distance: past kExactTies of them the rest, all within
  // rounding of the best, are left undecided (see the header).
  constexpr std::size_t kExactTies = 64;
  candidates.erase(
      std::remove_if(candidates.begin(), candidates.end(),
                     [&](const Candidate& c) { return c.distance > best + 2.0 * slack; }),
      candidates.end());
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& l, const Candidate& r) {
    return l.distance < r.distance ||
           (l.distance == r.distance && (l.a < r.a || (l.a == r.a && l.b < r.b)));
  });
  if (candidates.size() > kExactTies) candidates.resize(kExactTies);
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& l, const Candidate& r) {
    return l.a < r.a || (l.a == r.a && l.b < r.b);
  });
  double best_exact = std::numeric_limits<double>::infinity();
  TrianglePair winner;
  for (const Candidate& c : candidates) {
    ++answer.exact_tests;
    const TrianglePair pair{c.a, c.b};
    const double d2 = exactPairSquaredDistance(a, pose_a, b, pose_b, pair);
    if (d2 < best_exact) {
      best_exact = d2;
      winner = pair;
    }
  }
  finish(winner, std::sqrt(best_exact));
  return answer;
}

}  // namespace collido
