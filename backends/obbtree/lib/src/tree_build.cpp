// Top-down construction of the OBB tree (the dissertation's method; Gottschalk et al. 1996).
//
// Per node: fit the box (then keep a tighter one where a frame of its triangles gives it,
// BoxFitter::tighten); if the node holds more than
// max_leaf_triangles, split: by default where a cost model prefers (tree_split.cpp), its planes
// along the fitted or the tighter frame; with split_by_cost off, or where no candidate of the
// cost model separates the triangles, by the dissertation's rule: the split plane is orthogonal
// to the longest axis of the fitted box and passes through the mean of the triangle centres; a
// triangle goes to the side its centre lies on. If one side is empty, the next longest axis is
// tried; if all three fail (e.g. all centres coincide), the node becomes a leaf that keeps all its
// triangles. Nodes are emitted in depth-first order, so the first child is always the next node
// and only the second child's index is stored. An explicit stack keeps adversarial inputs (very
// unbalanced splits) from exhausting the call stack.
#include <algorithm>
#include <numeric>

#include <collido/assert.h>
#include <collido/obbtree/tree.h>

#include "tree_split.h"

namespace collido::obbtree {
namespace {

struct Task {
  std::int32_t first;
  std::int32_t count;
  std::int32_t parent;  // node whose second_child this task fills; -1 for the root/first child
  int depth;
};

// Partitions order[first, first + count) by the centre plane along `axis`; returns the size of
// the lower part (0 or count when the split fails on this axis).
std::int32_t partition(std::int32_t* order, std::int32_t count, const Eigen::Vector3d& axis,
                       const Eigen::Matrix3Xd& centroids) {
  double mean = 0.0;
  for (std::int32_t i = 0; i < count; ++i)
    mean += axis.dot(centroids.col(order[i]));
  mean /= static_cast<double>(count);
  std::int32_t* middle = std::partition(
      order, order + count, [&](std::int32_t t) { return axis.dot(centroids.col(t)) < mean; });
  return static_cast<std::int32_t>(middle - order);
}

}  // namespace

ObbTree ObbTree::build(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                       const Eigen::Ref<const Eigen::Matrix3Xi>& triangles,
                       const BuildOptions& options) {
  // An index out of range would be read out of bounds here, and stored truncated to 16 bits.
  COLLIDO_ASSERT(triangles.size() == 0 ||
                     (triangles.minCoeff() >= 0 && triangles.maxCoeff() < vertices.cols()),
                 "a triangle's vertex index names no vertex");
  ObbTree tree;
  tree.vertices_ = vertices;
  const auto n = static_cast<std::int32_t>(triangles.cols());
  const std::int32_t max_leaf =
      std::clamp<std::int32_t>(options.max_leaf_triangles, 1, kMaxLeafTriangles);
  std::vector<std::int32_t> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);

  Eigen::Matrix3Xd centroids(3, n);
  for (std::int32_t t = 0; t < n; ++t) {
    centroids.col(t) = (vertices.col(triangles(0, t)) + vertices.col(triangles(1, t)) +
                        vertices.col(triangles(2, t))) /
                       3.0;
  }

  // A binary tree with at most n leaves has at most 2n - 1 nodes.
  tree.nodes_.reserve(n > 0 ? static_cast<std::size_t>(2 * (n / max_leaf + 1)) : 0);
  BoxFitter fitter(static_cast<std::size_t>(vertices.cols()));
  std::vector<Task> stack;
  detail::SplitScratch split_scratch;
  if (n > 0) stack.push_back(Task{0, n, -1, 0});
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    const auto index = static_cast<std::int32_t>(tree.nodes_.size());
    if (task.parent >= 0) tree.nodes_[static_cast<std::size_t>(task.parent)].second_child = index;
    Node node;
    std::int32_t* range = order.data() + task.first;
    // A node keeps a tighter box where a frame of its triangles gives one (BoxFitter::tighten),
    // and the cost model may take its planes along that frame too.
    const OrientedBox fitted = fitter.fit(vertices, triangles, range, task.count);
    const OrientedBox tighter = fitter.tighten(fitted, vertices, triangles, range, task.count);
    node.box = tighter;
    node.first = task.first;
    node.count = task.count;
    tree.depth_ = std::max(tree.depth_, task.depth);
    tree.nodes_.push_back(node);
    if (task.count <= max_leaf) continue;

    const int tighter_frames = tighter.axes == fitted.axes ? 0 : 1;
    std::int32_t lower =
        options.split_by_cost
            ? detail::splitByCost(range, task.count, fitted, &tighter.axes, tighter_frames,
                                  vertices, triangles, centroids, split_scratch)
            : 0;
    // The mean split: the rule itself, or where no cost candidate separates the centres (then
    // no plane does). The axes are sorted longest first.
    for (int axis = 0; axis < 3 && (lower == 0 || lower == task.count); ++axis) {
      lower = partition(range, task.count, fitted.axes.col(axis), centroids);
      if (lower > 0 && lower < task.count) break;
    }
    if (lower == 0 || lower == task.count) {
      // No plane splits the centres: a leaf, unless it would hold more than a leaf may.
      if (task.count <= kMaxLeafTriangles) continue;
      lower = task.count / 2;
    }
    // LIFO: the first child is popped next, so it lands at index + 1.
    stack.push_back(Task{task.first + lower, task.count - lower, index, task.depth + 1});
    stack.push_back(Task{task.first, lower, -1, task.depth + 1});
  }
  tree.topology_->triangles = TriangleList(triangles, order, vertices.cols());
  tree.topology_->ids = order;
  tree.nodes_.shrink_to_fit();
  if (options.float_boxes) tree.storeFloatBoxes();
  tree.options_ = options;
  if (options.deformable) {
    tree.buildVertexSpans();
    tree.recordFreshVolumes();
  }
  tree.measureAxisDefect();
  tree.findPlanarFaces();
  return tree;
}

// The layout BuildOptions::float_boxes promises (checked here, where the nodes are made).
static_assert(sizeof(CompactBox) == 26 && sizeof(CompactNode) == 32);

void ObbTree::storeFloatBoxes() {
  // Built in double, then stored in float: each box measured anew around its own triangles.
  float_boxes_ = true;
  compact_nodes_.reserve(nodes_.size());
  for (const Node& node : nodes_) {
    CompactNode compact;
    compact.box = compactBox(node.box, vertices_, topology_->triangles,
                             TriangleRange{node.first, node.count});
    compact.leaf_count = static_cast<std::uint16_t>(node.isLeaf() ? node.count : 0);
    compact.link = node.isLeaf() ? node.first : node.second_child;
    compact_nodes_.push_back(compact);
  }
  std::vector<Node>().swap(nodes_);
}

TriangleRange ObbTree::triangleRange(std::size_t node) const {
  if (!float_boxes_) return TriangleRange{nodes_[node].first, nodes_[node].count};
  // A subtree's triangles start where its first leaf's do and end where its last leaf's do;
  // the first leaf is reached by following first children down, the last by second children.
  std::size_t first_leaf = node;
  while (!compact_nodes_[first_leaf].isLeaf())
    ++first_leaf;
  std::size_t last_leaf = node;
  while (!compact_nodes_[last_leaf].isLeaf())
    last_leaf = static_cast<std::size_t>(compact_nodes_[last_leaf].secondChild());
  const std::int32_t first = compact_nodes_[first_leaf].leafFirst();
  const CompactNode& last = compact_nodes_[last_leaf];
  return TriangleRange{first, last.leafFirst() + last.leafCount() - first};
}

std::vector<TriangleRange> ObbTree::triangleRanges() const {
  std::vector<TriangleRange> ranges(nodeCount());
  if (!float_boxes_) {
    for (std::size_t i = 0; i < ranges.size(); ++i)
      ranges[i] = TriangleRange{nodes_[i].first, nodes_[i].count};
    return ranges;
  }
  // Children come after their parent: a reverse sweep has both children's ranges at hand.
  for (std::size_t i = ranges.size(); i-- > 0;) {
    const CompactNode& node = compact_nodes_[i];
    if (node.isLeaf()) {
      ranges[i] = TriangleRange{node.leafFirst(), node.leafCount()};
    } else {
      const TriangleRange& second = ranges[static_cast<std::size_t>(node.secondChild())];
      ranges[i] = TriangleRange{ranges[i + 1].first, ranges[i + 1].count + second.count};
    }
  }
  return ranges;
}

void ObbTree::measureAxisDefect() {
  // Refit keeps the axes, so this bound holds for the tree's whole life.
  for (const Node& node : nodes_)
    axis_defect_ = std::max(axis_defect_, obbtree::axisDefect(node.box.axes));
  for (const CompactNode& node : compact_nodes_)
    axis_defect_ = std::max(axis_defect_, obbtree::axisDefect(expandBox(node.box).axes));
}

void ObbTree::buildVertexSpans() {
  TreeTopology& topology = ownTopology();
  const auto n = static_cast<std::int32_t>(topology.triangles.cols());
  std::vector<std::int32_t> first_triangle(static_cast<std::size_t>(vertices_.cols()), -1);
  // Where each triangle position's first-used vertices start in refit_order; kept per node.
  std::vector<std::int32_t> position_first_use(static_cast<std::size_t>(n), 0);
  topology.refit_order.clear();
  for (std::int32_t k = 0; k < n; ++k) {
    position_first_use[static_cast<std::size_t>(k)] =
        static_cast<std::int32_t>(topology.refit_order.size());
    for (int c = 0; c < 3; ++c) {
      const std::int32_t v = topology.triangles(c, k);
      if (first_triangle[static_cast<std::size_t>(v)] >= 0) continue;
      first_triangle[static_cast<std::size_t>(v)] = k;
      topology.refit_order.push_back(v);
    }
  }
  const std::size_t node_count = nodeCount();
  const std::vector<TriangleRange> ranges = triangleRanges();
  topology.first_use.assign(node_count + 1, 0);
  topology.first_use[node_count] = static_cast<std::int32_t>(topology.refit_order.size());
  // An inner node's vertices first used before its triangles: found once per node with a stamp.
  topology.extra_begin.assign(node_count + 1, 0);
  topology.refit_extra.clear();
  std::vector<std::size_t> stamp(static_cast<std::size_t>(vertices_.cols()), 0);
  for (std::size_t i = 0; i < node_count; ++i) {
    const TriangleRange range = ranges[i];
    const std::int32_t first = range.first;
    topology.first_use[i] = position_first_use[static_cast<std::size_t>(first)];
    topology.extra_begin[i] = static_cast<std::int32_t>(topology.refit_extra.size());
    if (isLeafNode(i)) continue;
    for (std::int32_t k = first; k < first + range.count; ++k) {
      for (int c = 0; c < 3; ++c) {
        const auto v = static_cast<std::size_t>(topology.triangles(c, k));
        if (first_triangle[v] >= first || stamp[v] == i + 1) continue;
        stamp[v] = i + 1;
        topology.refit_extra.push_back(static_cast<std::int32_t>(v));
      }
    }
  }
  topology.extra_begin[node_count] = static_cast<std::int32_t>(topology.refit_extra.size());
  topology.refit_order.shrink_to_fit();
  topology.refit_extra.shrink_to_fit();
}

std::size_t TreeTopology::memoryBytes() const {
  return triangles.memoryBytes() + (ids.capacity() + refit_order.capacity() + first_use.capacity() +
                                    extra_begin.capacity() + refit_extra.capacity()) *
                                       sizeof(std::int32_t);
}

std::size_t ObbTree::memoryBytes() const {
  return nodes_.capacity() * sizeof(Node) + compact_nodes_.capacity() * sizeof(CompactNode) +
         static_cast<std::size_t>(vertices_.size()) * sizeof(double) +
         (topology_borrowed_ && topology_.use_count() > 1 ? 0 : topology_->memoryBytes()) +
         fresh_volume_.capacity() * sizeof(float) + faces_.capacity() * sizeof(std::int32_t);
}

}  // namespace collido::obbtree
