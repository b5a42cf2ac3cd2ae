#include <string>
#include <vector>

#include <collido/obbtree/tree.h>

namespace collido::obbtree {
namespace {

std::string nodeText(std::size_t index) {
  return "node " + std::to_string(index);
}

}  // namespace

std::string ObbTree::validate() const {
  const auto n = static_cast<std::int32_t>(ids_.size());
  if (nodes_.empty()) return n == 0 ? "" : "no nodes for " + std::to_string(n) + " triangles";
  if (nodes_[0].first != 0 || nodes_[0].count != n) return "the root does not hold every triangle";

  // Structure: each internal node's children are contiguous halves of its range; each triangle
  // id appears exactly once.
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (std::int32_t id : ids_) {
    if (id < 0 || id >= n || seen[static_cast<std::size_t>(id)])
      return "triangle ids are not a permutation";
    seen[static_cast<std::size_t>(id)] = 1;
  }
  std::vector<std::int32_t> parent(nodes_.size(), -1);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const Node& node = nodes_[i];
    if (node.count <= 0) return nodeText(i) + " is empty";
    if (node.isLeaf()) continue;
    const std::size_t first_child = i + 1;
    const auto second_child = static_cast<std::size_t>(node.second_child);
    if (second_child <= first_child || second_child >= nodes_.size()) {
      return nodeText(i) + " has a second child out of order";
    }
    const Node& left = nodes_[first_child];
    const Node& right = nodes_[second_child];
    if (left.first != node.first || right.first != left.first + left.count ||
        left.count + right.count != node.count) {
      return nodeText(i) + ": children do not partition its triangles";
    }
    parent[first_child] = static_cast<std::int32_t>(i);
    parent[second_child] = static_cast<std::int32_t>(i);
  }
  for (std::size_t i = 1; i < nodes_.size(); ++i) {
    if (parent[i] < 0) return nodeText(i) + " is not reachable from the root";
  }

  // Geometry: every corner of every triangle lies in its leaf's box and in every ancestor's.
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (!nodes_[i].isLeaf()) continue;
    for (auto ancestor = static_cast<std::int32_t>(i); ancestor >= 0;
         ancestor = parent[static_cast<std::size_t>(ancestor)]) {
      const OrientedBox& box = nodes_[static_cast<std::size_t>(ancestor)].box;
      for (std::int32_t k = nodes_[i].first; k < nodes_[i].first + nodes_[i].count; ++k) {
        for (int c = 0; c < 3; ++c) {
          if (!boxContains(box, vertices_.col(triangles_(c, k)))) {
            return "triangle " + std::to_string(ids_[static_cast<std::size_t>(k)]) +
                   " is outside the box of " + nodeText(static_cast<std::size_t>(ancestor));
          }
        }
      }
    }
  }
  return "";
}

}  // namespace collido::obbtree
