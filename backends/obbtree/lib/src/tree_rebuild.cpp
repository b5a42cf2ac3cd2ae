// Rebuilding the subtrees a deformation has turned away from their boxes' axes: a refit keeps
// each box's axes, so a part that bends, twists or stretches far ends up in boxes much larger
// than freshly fitted ones would be. A subtree whose root box grew past rebuild_ratio times its
// volume when last fitted fresh is built again over its current triangles, in place.
#include <algorithm>
#include <numeric>

#include <collido/obbtree/tree.h>

namespace collido::obbtree {
namespace {

// A subtree's nodes with their triangle positions and child indices moved to where the
// subtree now sits: triangle positions from `first`, node indices from `root`.
std::vector<Node> placed(const std::vector<Node>& nodes, std::int32_t first, std::size_t root) {
  std::vector<Node> out = nodes;
  for (Node& node : out) {
    node.first += first;
    if (!node.isLeaf()) node.second_child += static_cast<std::int32_t>(root);
  }
  return out;
}
std::vector<CompactNode> placed(const std::vector<CompactNode>& nodes, std::int32_t first,
                                std::size_t root) {
  std::vector<CompactNode> out = nodes;
  for (CompactNode& node : out)
    node.link += node.isLeaf() ? first : static_cast<std::int32_t>(root);
  return out;
}

void shiftSecondChild(Node& node, std::int64_t delta) {
  node.second_child = static_cast<std::int32_t>(node.second_child + delta);
}
void shiftSecondChild(CompactNode& node, std::int64_t delta) {
  node.link = static_cast<std::int32_t>(node.link + delta);
}

// Replaces nodes [root, end) by `replacement`; the indices of later nodes shift by the change in
// size, and so do the second_child indices that point past the subtree.
template <typename NodeT>
void splice(std::vector<NodeT>& nodes, std::size_t root, std::size_t end,
            const std::vector<NodeT>& replacement) {
  const auto delta =
      static_cast<std::int64_t>(replacement.size()) - static_cast<std::int64_t>(end - root);
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    if (j >= root && j < end) continue;
    if (!nodes[j].isLeaf() && nodes[j].secondChild() >= static_cast<std::int32_t>(end))
      shiftSecondChild(nodes[j], delta);
  }
  const auto at = [&nodes](std::size_t k) {
    return nodes.begin() + static_cast<std::ptrdiff_t>(k);
  };
  nodes.erase(at(root), at(end));
  nodes.insert(at(root), replacement.begin(), replacement.end());
}

}  // namespace

double ObbTree::boxVolume(std::size_t node) const {
  Eigen::Vector3d h = float_boxes_ ? Eigen::Vector3d::Zero() : nodes_[node].box.half_extents;
  for (int k = 0; k < 3 && float_boxes_; ++k)
    h[k] = halfExtent(compact_nodes_[node].box, k);
  // Each extent at least 1% of the box's size, so that a flat box (a planar patch) compares by
  // its area instead of by a volume of rounding errors.
  return 8.0 * (h.array() + 0.01 * h.sum()).prod();
}

void ObbTree::recordFreshVolumes() {
  fresh_volume_.resize(nodeCount());
  for (std::size_t i = 0; i < nodeCount(); ++i)
    fresh_volume_[i] = static_cast<float>(boxVolume(i));
}

std::size_t ObbTree::subtreeEnd(std::size_t node) const {
  // The last node of a subtree is its rightmost leaf: follow second children down.
  for (;;) {
    const bool leaf = isLeafNode(node);
    if (leaf) return node + 1;
    const std::int32_t second =
        float_boxes_ ? compact_nodes_[node].secondChild() : nodes_[node].secondChild();
    node = static_cast<std::size_t>(second);
  }
}

std::size_t ObbTree::rebuildSubtree(std::size_t node) {
  TreeTopology& topology = ownTopology();
  const auto [first, count] = triangleRange(node);
  const std::size_t end = subtreeEnd(node);
  const Eigen::Matrix3Xi triangles = topology.triangles.middleCols(first, count);
  BuildOptions options = options_;
  options.deformable = false;
  options.rebuild_ratio = 0.0;
  const ObbTree part = ObbTree::build(vertices_, triangles, options);
  // The subtree's triangles in the part's leaf order.
  const std::vector<std::int32_t> ids(topology.ids.begin() + first,
                                      topology.ids.begin() + first + count);
  for (std::int32_t k = 0; k < count; ++k) {
    topology.triangles.set(first + k,
                           triangles.col(part.topology_->ids[static_cast<std::size_t>(k)]));
    topology.ids[static_cast<std::size_t>(first) + static_cast<std::size_t>(k)] =
        ids[static_cast<std::size_t>(part.topology_->ids[static_cast<std::size_t>(k)])];
  }
  if (float_boxes_) {
    splice(compact_nodes_, node, end, placed(part.compact_nodes_, first, node));
  } else {
    splice(nodes_, node, end, placed(part.nodes_, first, node));
  }
  // Fresh volumes: the part's boxes are fresh; the others keep theirs.
  std::vector<float> volumes(part.nodeCount());
  for (std::size_t k = 0; k < volumes.size(); ++k)
    volumes[k] = static_cast<float>(part.boxVolume(k));
  const auto at = [this](std::size_t k) {
    return fresh_volume_.begin() + static_cast<std::ptrdiff_t>(k);
  };
  fresh_volume_.erase(at(node), at(end));
  fresh_volume_.insert(at(node), volumes.begin(), volumes.end());
  // New axes: the query's bound on their defect must cover them too.
  axis_defect_ = std::max(axis_defect_, part.axis_defect_);
  return part.nodeCount();
}

void ObbTree::rebuildGrownSubtrees(RefitReport& report) {
  // Top-down (depth-first order), so a grown subtree is rebuilt whole and its nodes are not
  // looked at again.
  std::size_t i = 0;
  while (i < nodeCount()) {
    if (boxVolume(i) > options_.rebuild_ratio * static_cast<double>(fresh_volume_[i])) {
      const std::size_t size = rebuildSubtree(i);
      ++report.subtrees_rebuilt;
      report.nodes_rebuilt += size;
      i += size;
    } else {
      ++i;
    }
  }
  if (report.subtrees_rebuilt == 0) return;
  // The tree's depth and the refit's vertex spans follow the new shape.
  depth_ = 0;
  std::vector<std::pair<std::size_t, int>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    depth_ = std::max(depth_, depth);
    const bool leaf = isLeafNode(node);
    if (leaf) continue;
    const std::int32_t second =
        float_boxes_ ? compact_nodes_[node].secondChild() : nodes_[node].secondChild();
    stack.emplace_back(node + 1, depth + 1);
    stack.emplace_back(static_cast<std::size_t>(second), depth + 1);
  }
  buildVertexSpans();
}

}  // namespace collido::obbtree
