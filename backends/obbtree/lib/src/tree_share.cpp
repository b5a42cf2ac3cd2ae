// Trees of one object's active states that share a triangle list: one topology (leaf order,
// ids, vertex spans), boxes per state.
#include <numeric>

#include <collido/assert.h>
#include <collido/obbtree/tree.h>

namespace collido::obbtree {

ObbTree ObbTree::buildLike(const ObbTree& sibling,
                           const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                           const BuildOptions& options) {
  COLLIDO_ASSERT(vertices.cols() == sibling.vertices_.cols(),
                 "a state tree needs its sibling's vertex count");
  ObbTree tree;
  tree.vertices_ = vertices;
  tree.topology_ = sibling.topology_;
  tree.topology_borrowed_ = true;
  tree.options_ = options;
  tree.depth_ = sibling.depth_;
  // The sibling's shape, every box fitted fresh: new axes suit the state's geometry, where a
  // refit of the sibling's boxes would keep axes fitted to another shape.
  const Eigen::Matrix3Xi triangles = tree.topology_->triangles.matrix();  // for the fitter
  std::vector<std::int32_t> identity(static_cast<std::size_t>(triangles.cols()));
  std::iota(identity.begin(), identity.end(), 0);
  BoxFitter fitter(static_cast<std::size_t>(vertices.cols()));
  const std::size_t node_count = sibling.nodeCount();
  tree.nodes_.resize(node_count);
  const std::vector<TriangleRange> ranges = sibling.triangleRanges();
  for (std::size_t i = 0; i < node_count; ++i) {
    Node& node = tree.nodes_[i];
    const TriangleRange range = ranges[i];
    node.first = range.first;
    node.count = range.count;
    if (sibling.float_boxes_) {
      const CompactNode& from = sibling.compact_nodes_[i];
      node.second_child = from.isLeaf() ? -1 : from.secondChild();
    } else {
      node.second_child = sibling.nodes_[i].second_child;
    }
    const std::int32_t* order = identity.data() + node.first;
    node.box = fitter.fit(vertices, triangles, order, node.count);
    node.box = fitter.tighten(node.box, vertices, triangles, order, node.count);
  }
  if (options.float_boxes) tree.storeFloatBoxes();
  if (options.deformable) {
    // A rigid sibling has no vertex spans: make them on a private copy, not on its topology.
    if (tree.topology_->first_use.empty()) tree.buildVertexSpans();
    tree.recordFreshVolumes();
  }
  tree.measureAxisDefect();
  tree.findPlanarFaces();
  return tree;
}

TreeTopology& ObbTree::ownTopology() {
  if (topology_.use_count() > 1) topology_ = std::make_shared<TreeTopology>(*topology_);
  topology_borrowed_ = false;
  return *topology_;
}

}  // namespace collido::obbtree
