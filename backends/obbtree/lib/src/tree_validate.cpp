#include <string>
#include <vector>

#include <collido/obbtree/tree.h>

namespace collido::obbtree {
namespace {

std::string nodeText(std::size_t index) {
  return "node " + std::to_string(index);
}

// The checks of ObbTree::validate on either kind of node; `box_of(node)` gives the box the
// queries use, `range_of(i)` node i's triangles (computed through second children, so the
// child order is checked first).
template <typename NodeT, typename BoxOf, typename RangeOf>
std::string validateNodes(const std::vector<NodeT>& nodes, const std::vector<std::int32_t>& ids,
                          const Eigen::Matrix3Xd& vertices, const TriangleList& triangles,
                          BoxOf&& box_of, RangeOf&& range_of) {
  const auto n = static_cast<std::int32_t>(ids.size());
  if (nodes.empty()) return n == 0 ? "" : "no nodes for " + std::to_string(n) + " triangles";
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].isLeaf()) continue;
    const auto second_child = static_cast<std::size_t>(nodes[i].secondChild());
    if (second_child <= i + 1 || second_child >= nodes.size())
      return nodeText(i) + " has a second child out of order";
  }
  const TriangleRange root = range_of(0);
  if (root.first != 0 || root.count != n) return "the root does not hold every triangle";

  // Structure: each internal node's children are contiguous halves of its range; each triangle
  // id appears exactly once.
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (std::int32_t id : ids) {
    if (id < 0 || id >= n || seen[static_cast<std::size_t>(id)])
      return "triangle ids are not a permutation";
    seen[static_cast<std::size_t>(id)] = 1;
  }
  std::vector<std::int32_t> parent(nodes.size(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const TriangleRange range = range_of(i);
    if (range.count <= 0) return nodeText(i) + " is empty";
    if (nodes[i].isLeaf()) continue;
    const std::size_t first_child = i + 1;
    const auto second_child = static_cast<std::size_t>(nodes[i].secondChild());
    const TriangleRange left = range_of(first_child);
    const TriangleRange right = range_of(second_child);
    if (left.first != range.first || right.first != left.first + left.count ||
        left.count + right.count != range.count) {
      return nodeText(i) + ": children do not partition its triangles";
    }
    parent[first_child] = static_cast<std::int32_t>(i);
    parent[second_child] = static_cast<std::int32_t>(i);
  }
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    if (parent[i] < 0) return nodeText(i) + " is not reachable from the root";
  }

  // Geometry: every corner of every triangle lies in its leaf's box and in every ancestor's.
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!nodes[i].isLeaf()) continue;
    for (auto ancestor = static_cast<std::int32_t>(i); ancestor >= 0;
         ancestor = parent[static_cast<std::size_t>(ancestor)]) {
      const OrientedBox box = box_of(nodes[static_cast<std::size_t>(ancestor)]);
      const TriangleRange leaf = range_of(i);
      for (std::int32_t k = leaf.first; k < leaf.first + leaf.count; ++k) {
        for (int c = 0; c < 3; ++c) {
          if (!boxContains(box, vertices.col(triangles(c, k)))) {
            return "triangle " + std::to_string(ids[static_cast<std::size_t>(k)]) +
                   " is outside the box of " + nodeText(static_cast<std::size_t>(ancestor));
          }
        }
      }
    }
  }
  return "";
}

}  // namespace

std::string ObbTree::validate() const {
  if (float_boxes_) {
    if (!nodes_.empty()) return "a float-box tree holds double boxes too";
    return validateNodes(
        compact_nodes_, topology_->ids, vertices_, topology_->triangles,
        [](const CompactNode& node) { return expandBox(node.box); },
        [this](std::size_t i) { return triangleRange(i); });
  }
  if (!compact_nodes_.empty()) return "a double-box tree holds float boxes too";
  return validateNodes(
      nodes_, topology_->ids, vertices_, topology_->triangles,
      [](const Node& node) { return node.box; },
      [this](std::size_t i) { return triangleRange(i); });
}

}  // namespace collido::obbtree
