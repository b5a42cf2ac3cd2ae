// Simultaneous descent of two OBB trees.
//
// Everything happens in A's model frame: B's boxes and triangles are mapped there by the
// relative pose pose_a^-1 * pose_b, so A's data is used as stored and the numbers stay near A's
// own coordinates however far both objects are from the world origin.
// Per node pair (a, b) on the stack:
//   1. test the boxes with the 15-axis separating-axis test; separated -> drop the pair;
//   2. both leaves -> test every triangle pair exactly, record hits;
//   3. otherwise split the node that is not a leaf, or of two inner nodes the larger one (by the
//      sum of its half extents), and push both child pairs.
#include <collido/obbtree/collide.h>

#include <collido/obbtree/separating_axis.h>
#include <collido/obbtree/triangle_intersection.h>

namespace collido::obbtree {
namespace {

struct PairTask {
  std::int32_t a;
  std::int32_t b;
};

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

template <typename NodeA, typename NodeB>
void descend(const ObbTree& a, const std::vector<NodeA>& nodes_a, const ObbTree& b,
             const std::vector<NodeB>& nodes_b, const Eigen::Matrix3d& rotation,
             const Eigen::Vector3d& translation, const CollideRequest& request,
             CollideResult& result) {
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
    if (!boxesOverlap(relative, offset, box_a.half_extents, box_b.half_extents)) {
      continue;
    }

    if (node_a.isLeaf() && node_b.isLeaf()) {
      for (std::int32_t j = node_b.first; j < node_b.first + node_b.count; ++j) {
        const Eigen::Vector3d q0 = rotation * vertices_b.col(triangles_b(0, j)) + translation;
        const Eigen::Vector3d q1 = rotation * vertices_b.col(triangles_b(1, j)) + translation;
        const Eigen::Vector3d q2 = rotation * vertices_b.col(triangles_b(2, j)) + translation;
        for (std::int32_t i = node_a.first; i < node_a.first + node_a.count; ++i) {
          ++result.triangle_tests;
          if (!trianglesIntersect(vertices_a.col(triangles_a(0, i)),
                                  vertices_a.col(triangles_a(1, i)),
                                  vertices_a.col(triangles_a(2, i)), q0, q1, q2)) {
            continue;
          }
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
  if (a.nodeCount() == 0 || b.nodeCount() == 0) return;

  // B's model frame to A's model frame. Poses are rigid, so the inverse is the transpose.
  const Eigen::Matrix3d rotation = pose_a.linear().transpose() * pose_b.linear();
  const Eigen::Vector3d translation =
      pose_a.linear().transpose() * (pose_b.translation() - pose_a.translation());
  if (a.floatBoxes() && b.floatBoxes()) {
    descend(a, a.compactNodes(), b, b.compactNodes(), rotation, translation, request, result);
  } else if (a.floatBoxes()) {
    descend(a, a.compactNodes(), b, b.nodes(), rotation, translation, request, result);
  } else if (b.floatBoxes()) {
    descend(a, a.nodes(), b, b.compactNodes(), rotation, translation, request, result);
  } else {
    descend(a, a.nodes(), b, b.nodes(), rotation, translation, request, result);
  }
}

}  // namespace collido::obbtree
