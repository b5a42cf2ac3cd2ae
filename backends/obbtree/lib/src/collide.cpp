// Simultaneous descent of two OBB trees, exact on the exact world coordinates.
//
// Everything happens in A's model frame: B's boxes and triangles are mapped there by the
// relative pose pose_a^-1 * pose_b, so A's data is used as stored and the numbers stay near A's
// own coordinates however far both objects are from the world origin. The map is computed in
// double (rotation = R_a^T R_b, translation = R_a^T (t_b - t_a)), so a mapped point differs from
// the exact one (R_a^-1 (R_b v + t_b - t_a), the rotations as given, not orthonormalised) by at
// most QueryBounds::linear |v|_1 + QueryBounds::constant; see backends/obbtree/README.md.
// Per node pair (a, b) on the stack:
//   1. test the boxes with the 15-axis separating-axis test, B's box enlarged by its mapping
//      error and the comparisons by the bound on their rounding: separated -> drop the pair;
//   2. both leaves -> test every triangle pair with the certified filter on the mapped corners
//      (each with its error radius); when the filter cannot be sure, decide exactly on the
//      world coordinates; record hits;
//   3. otherwise split the node that is not a leaf, or of two inner nodes the larger one (by the
//      sum of its half extents), and push both child pairs.
#include <collido/obbtree/collide.h>

#include <collido/obbtree/separating_axis.h>
#include <collido/obbtree/triangle_intersection.h>

#include <cmath>
#include <limits>
#include <optional>

namespace collido::obbtree {
namespace {

struct PairTask {
  std::int32_t a;
  std::int32_t b;
};

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The error of the computed relative map and what the box test must allow for.
struct QueryBounds {
  double linear = 0.0;  // mapped point error <= linear |v|_1 + constant
  double constant = 0.0;
  double axis_error = 0.0;  // SeparationTolerance::axis_error for every box pair

  double pointError(const Eigen::Vector3d& v) const { return linear * v.lpNorm<1>() + constant; }
};

// Derivation (2-norms are bounded by 1-norms throughout): with E = R_a^T R_a - I and
// d_a = axisDefect(R_a) >= |E|_2, R_a^-1 = (I + E)^-1 R_a^T, so |R_a^-1 - R_a^T|_2 <=
// k = d_a / (1 - d_a) (1 + d_a). The exact map's linear part R_a^-1 R_b then differs from
// R_a^T R_b by k (1 + d_b); rounding R_a^T R_b, t_b - t_a, R_a^T (t_b - t_a) and M v + s adds
// fewer than 12 ulps of |v|_1 and of |t_b - t_a|_1 (64 allowed). The box test's axis error adds
// both trees' axis defects and the deviation of the mapped axes from orthonormality (below
// 2 (d_a + d_b) + 2 linear). Poses far from rigid (defect >= 1e-3; the scene loader rejects them)
// get infinite bounds: nothing is culled and every triangle pair is decided exactly.
QueryBounds queryBounds(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
                        const Eigen::Isometry3d& pose_b) {
  QueryBounds bounds;
  const double defect_a = axisDefect(pose_a.linear());
  const double defect_b = axisDefect(pose_b.linear());
  const double shift = (pose_b.translation() - pose_a.translation()).lpNorm<1>();
  if (!(defect_a < 1e-3 && defect_b < 1e-3) || !std::isfinite(shift)) {
    const double infinite = std::numeric_limits<double>::infinity();
    return QueryBounds{infinite, infinite, infinite};
  }
  const double inverse_error = defect_a / (1.0 - defect_a) * (1.0 + defect_a);
  bounds.linear = inverse_error * (1.0 + defect_b) + 64.0 * kEps;
  bounds.constant = (inverse_error + 64.0 * kEps) * shift * (1.0 + kEps);
  bounds.axis_error = a.axisDefect() + b.axisDefect() + 2.0 * (defect_a + defect_b) +
                      2.0 * bounds.linear + 32.0 * kEps;
  return bounds;
}

// The box a query uses: a double box as stored, a float box decoded (expandBox).
const OrientedBox& boxOf(const Node& node) {
  return node.box;
}
OrientedBox boxOf(const CompactNode& node) {
  return expandBox(node.box);
}

double boxSize(const Node& node) {
  return node.box.half_extents.sum();
}
double boxSize(const CompactNode& node) {
  return static_cast<double>(node.box.half_extents[0]) + node.box.half_extents[1] +
         node.box.half_extents[2];
}

// The poses and the computed map from B's model frame into A's.
struct Placement {
  const Eigen::Isometry3d& pose_a;
  const Eigen::Isometry3d& pose_b;
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation;
  QueryBounds bounds;
};

template <typename NodeA, typename NodeB>
void descend(const ObbTree& a, const std::vector<NodeA>& nodes_a, const ObbTree& b,
             const std::vector<NodeB>& nodes_b, const Placement& placement,
             const CollideRequest& request, CollideResult& result) {
  const Eigen::Matrix3d& rotation = placement.rotation;
  const Eigen::Vector3d& translation = placement.translation;
  const QueryBounds& bounds = placement.bounds;
  const Eigen::Matrix3Xd& vertices_a = a.vertices();
  const Eigen::Matrix3Xd& vertices_b = b.vertices();
  const Eigen::Matrix3Xi& triangles_a = a.orderedTriangles();
  const Eigen::Matrix3Xi& triangles_b = b.orderedTriangles();

  std::vector<PairTask> stack;
  stack.reserve(64);
  stack.push_back(PairTask{0, 0});
  while (!stack.empty()) {
    const PairTask task = stack.back();
    stack.pop_back();
    const NodeA& node_a = nodes_a[static_cast<std::size_t>(task.a)];
    const NodeB& node_b = nodes_b[static_cast<std::size_t>(task.b)];
    const auto& box_a = boxOf(node_a);
    const auto& box_b = boxOf(node_b);

    // B's box in A's box frame.
    const Eigen::Matrix3d axes_b = rotation * box_b.axes;
    const Eigen::Vector3d center_b = rotation * box_b.center + translation;
    const Eigen::Matrix3d relative = box_a.axes.transpose() * axes_b;
    const Eigen::Vector3d offset = box_a.axes.transpose() * (center_b - box_a.center);
    ++result.box_tests;
    const SeparationTolerance tolerance{
        bounds.axis_error,
        bounds.pointError(box_b.center) + bounds.axis_error * box_b.half_extents.sum()};
    if (!boxesOverlap(relative, offset, box_a.half_extents, box_b.half_extents, tolerance)) {
      continue;
    }

    if (node_a.isLeaf() && node_b.isLeaf()) {
      for (std::int32_t j = node_b.first; j < node_b.first + node_b.count; ++j) {
        UncertainPoint q[3];
        for (int k = 0; k < 3; ++k) {
          const auto v = vertices_b.col(triangles_b(k, j));
          q[k].p = rotation * v + translation;
          q[k].error = bounds.pointError(v);
        }
        for (std::int32_t i = node_a.first; i < node_a.first + node_a.count; ++i) {
          ++result.triangle_tests;
          const UncertainPoint p[3] = {{vertices_a.col(triangles_a(0, i)), 0.0},
                                       {vertices_a.col(triangles_a(1, i)), 0.0},
                                       {vertices_a.col(triangles_a(2, i)), 0.0}};
          std::optional<bool> hit = trianglesIntersectCertified(p[0], p[1], p[2], q[0], q[1], q[2]);
          if (!hit) {
            ++result.exact_fallbacks;
            const Eigen::Vector3d corners_a[3] = {p[0].p, p[1].p, p[2].p};
            const Eigen::Vector3d corners_b[3] = {vertices_b.col(triangles_b(0, j)),
                                                  vertices_b.col(triangles_b(1, j)),
                                                  vertices_b.col(triangles_b(2, j))};
            hit = posedTrianglesIntersect(corners_a, placement.pose_a, corners_b, placement.pose_b);
          }
          if (!*hit) continue;
          // Truncated means a pair beyond the limit exists, not merely that the limit was met.
          if (request.max_pairs != 0 && result.pairs.size() >= request.max_pairs) {
            result.truncated = true;
            return;
          }
          result.pairs.push_back(TrianglePair{a.triangleId(i), b.triangleId(j)});
          if (request.mode == CollideMode::kFirstHit) return;
        }
      }
      continue;
    }

    const bool split_a =
        node_b.isLeaf() || (!node_a.isLeaf() && boxSize(node_a) >= boxSize(node_b));
    if (split_a) {
      stack.push_back(PairTask{node_a.second_child, task.b});
      stack.push_back(PairTask{task.a + 1, task.b});
    } else {
      stack.push_back(PairTask{task.a, node_b.second_child});
      stack.push_back(PairTask{task.a, task.b + 1});
    }
  }
}

}  // namespace

void collide(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
             const Eigen::Isometry3d& pose_b, const CollideRequest& request,
             CollideResult& result) {
  result.pairs.clear();
  result.truncated = false;
  result.box_tests = 0;
  result.triangle_tests = 0;
  result.exact_fallbacks = 0;
  if (a.nodeCount() == 0 || b.nodeCount() == 0) return;

  // B's model frame to A's model frame, with the transpose standing for the inverse; the
  // bounds account for the rotations not being exactly orthonormal.
  const Placement placement{
      pose_a, pose_b, pose_a.linear().transpose() * pose_b.linear(),
      pose_a.linear().transpose() * (pose_b.translation() - pose_a.translation()),
      queryBounds(a, pose_a, b, pose_b)};
  if (a.floatBoxes() && b.floatBoxes()) {
    descend(a, a.compactNodes(), b, b.compactNodes(), placement, request, result);
  } else if (a.floatBoxes()) {
    descend(a, a.compactNodes(), b, b.nodes(), placement, request, result);
  } else if (b.floatBoxes()) {
    descend(a, a.nodes(), b, b.compactNodes(), placement, request, result);
  } else {
    descend(a, a.nodes(), b, b.nodes(), placement, request, result);
  }
}

}  // namespace collido::obbtree
