#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <collido/obbtree/oriented_box.h>
#include <collido/obbtree/triangle_list.h>

namespace collido::obbtree {

/// How to build a tree.
struct BuildOptions {
  /// Split while a node holds more than this (1 to kMaxLeafTriangles).
  std::int32_t max_leaf_triangles = 1;
  /// Store compact boxes (CompactNode: 32 instead of 136 bytes a node), still containing every
  /// triangle they bound; the tree's shape is the same as with double boxes.
  bool float_boxes = false;
  /// The model will be refit (update() with moved vertices): keep, per inner node, the list of
  /// its distinct vertices (in a compact form: 6 to 15 bytes per triangle), so that a refit
  /// projects each vertex once per level instead of once per triangle corner.
  bool deformable = false;
  /// With `deformable`: after a refit, rebuild (split and fit anew over its current triangles)
  /// every subtree whose root box's volume grew past this many times its volume when last
  /// fitted fresh (each extent counted as at least 1% of the box's size, so flat boxes compare
  /// by area); 0 never rebuilds. Keeps boxes tight when a deformation turns the geometry
  /// away from the axes the boxes were fitted to.
  double rebuild_ratio = 0.0;
  /// Where to split a node (last, so that brace-initialised options keep their meaning): true, at
  /// the plane (of 16 per box axis) that a cost model of the tests below it prefers
  /// (tree_split.cpp); false, at the mean of the triangle centres along the longest box axis that
  /// separates them (the dissertation's rule).
  bool split_by_cost = true;
};

/// What a refit did.
struct RefitReport {
  std::size_t moved_vertices = 0;    ///< vertices whose position changed
  std::size_t nodes_refit = 0;       ///< boxes measured anew (those holding a moved vertex)
  std::size_t subtrees_rebuilt = 0;  ///< subtrees rebuilt (BuildOptions::rebuild_ratio)
  std::size_t nodes_rebuilt = 0;     ///< nodes in them, after the rebuild
};

/// One node of the flat tree. Depth-first order: the first child of node i is i + 1.
struct Node {
  OrientedBox box;
  std::int32_t second_child = -1;  ///< index of the second child; -1 for a leaf
  std::int32_t first = 0;          ///< first position in the tree's triangle order
  std::int32_t count = 0;          ///< triangles in this subtree: order[first .. first + count)

  bool isLeaf() const { return second_child < 0; }
  // The accessors a CompactNode has too, for code written for either kind of node.
  std::int32_t secondChild() const { return second_child; }
  std::int32_t leafFirst() const { return first; }
  std::int32_t leafCount() const { return count; }
};

/// A node with a compact box (BuildOptions::float_boxes): 32 bytes. An inner node keeps only
/// its second child's index and a leaf only its triangles; the tree computes an inner node's
/// triangle range when it needs it (ObbTree::triangleRange).
struct CompactNode {
  CompactBox box;
  std::uint16_t leaf_count = 0;  ///< triangles in a leaf (at most kMaxLeafTriangles); 0 inside
  std::int32_t link = 0;         ///< an inner node's second child; a leaf's first triangle position

  bool isLeaf() const { return leaf_count != 0; }
  std::int32_t secondChild() const { return link; }
  std::int32_t leafFirst() const { return link; }
  std::int32_t leafCount() const { return leaf_count; }
};

/// The most triangles a leaf holds, whatever BuildOptions::max_leaf_triangles says (a node whose
/// triangle centres all coincide, which no plane splits, is split in halves above it).
inline constexpr std::int32_t kMaxLeafTriangles = 65535;

/// What a tree's shape fixes whatever the vertex positions: the triangles in leaf order, their
/// input ids, and (BuildOptions::deformable) the refit's vertex spans. Trees of one object's
/// active states with the same triangle list share one (ObbTree::buildLike).
struct TreeTopology {
  TriangleList triangles;  ///< leaf order: triangle k is input triangle ids[k]
  std::vector<std::int32_t> ids;
  // The refit's vertex spans: every vertex in the order the leaf-ordered triangles first use
  // it. Per node (and one entry past the last): node i's triangles first use
  // refit_order[first_use[i] .. first_use[e]), e being the node after i's subtree; an inner
  // node also uses the earlier-seen vertices refit_extra[extra_begin[i] .. extra_begin[i + 1]).
  // A leaf keeps no list: its few triangles' corners are projected instead (leaf lists were
  // about a third of the spans' memory).
  std::vector<std::int32_t> refit_order;
  std::vector<std::int32_t> first_use;
  std::vector<std::int32_t> extra_begin;
  std::vector<std::int32_t> refit_extra;

  std::size_t memoryBytes() const;
};

/// The OBB tree of a triangle mesh: a flat array of nodes, a copy of the vertices and the
/// triangles stored in leaf order (so a leaf's triangles are contiguous).
class ObbTree {
 public:
  /// Builds the tree top-down: fit a box (fitBox); split along the longest box axis by the plane
  /// through the mean of the triangle centres, a triangle going to the side its centre lies on;
  /// if a side is empty try the next longest axis; if every axis fails, or the node holds at
  /// most max_leaf_triangles, it is a leaf. O(n log n) for well-spread meshes. Every index must
  /// name one of the vertices (COLLIDO_ASSERT: the scene loader reports bad meshes before this).
  static ObbTree build(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                       const Eigen::Ref<const Eigen::Matrix3Xi>& triangles,
                       const BuildOptions& options = {});

  /// A tree of another active state of `sibling`'s object (the same vertex count and triangle
  /// list, new positions): the same shape and leaf order, shared with `sibling` (memoryBytes()
  /// counts it once, in the tree that built it), every box fitted fresh (new axes) around its
  /// triangles at the new positions. Cheaper to build and smaller than build(); its boxes are
  /// as tight as the old grouping allows, which suits states that move parts of the mesh
  /// (a folding panel, an arm's configurations) more than ones that shuffle it.
  static ObbTree buildLike(const ObbTree& sibling,
                           const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                           const BuildOptions& options = {});
  /// Whether this tree shares its topology with another (buildLike, either side).
  bool sharesTopology() const { return topology_.use_count() > 1; }

  /// The nodes with double boxes; empty when the tree stores float boxes (compactNodes()).
  const std::vector<Node>& nodes() const { return nodes_; }
  /// The nodes with float boxes; empty unless built with BuildOptions::float_boxes.
  const std::vector<CompactNode>& compactNodes() const { return compact_nodes_; }
  bool floatBoxes() const { return float_boxes_; }
  std::size_t nodeCount() const { return float_boxes_ ? compact_nodes_.size() : nodes_.size(); }
  const Eigen::Matrix3Xd& vertices() const { return vertices_; }
  /// Triangles in leaf order: triangle k is the input triangle triangleId(k).
  const TriangleList& orderedTriangles() const { return topology_->triangles; }
  /// The input index of the triangle at position k of the leaf order.
  std::int32_t triangleId(std::int32_t k) const {
    return topology_->ids[static_cast<std::size_t>(k)];
  }
  std::size_t triangleCount() const { return topology_->ids.size(); }
  /// The planar face of the triangle at position k of the leaf order: triangles that share an
  /// edge (by vertex position) and lie exactly in one plane of the model share a face, named by
  /// its first triangle's position; a triangle alone in its plane, or degenerate, is face k.
  /// Found at build and for buildLike's positions; a refit that moves a vertex forgets them.
  std::int32_t faceOf(std::int32_t k) const {
    return faces_.empty() ? k : faces_[static_cast<std::size_t>(k)] >> 1;
  }
  /// +1 when the triangle at position k turns (its corners' order about the face's normal) as
  /// its face's first triangle does, -1 when the other way.
  int faceTurn(std::int32_t k) const {
    return faces_.empty() || (faces_[static_cast<std::size_t>(k)] & 1) == 0 ? 1 : -1;
  }
  /// The triangles under node i (inner nodes of a compact tree: found through its last leaf).
  TriangleRange triangleRange(std::size_t node) const;
  /// Every node's triangles, in one sweep (for passes over all nodes; triangleRange walks).
  std::vector<TriangleRange> triangleRanges() const;
  /// Deepest level (the root is at depth 0).
  int depth() const { return depth_; }
  /// The largest axisDefect of any box as the query decodes it (the separating-axis bound's
  /// allowance for the boxes' axes not being exactly orthonormal).
  double axisDefect() const { return axis_defect_; }

  /// Replaces the vertex positions (same count and order as at build) and refits, bottom-up,
  /// every box holding a triangle with a moved vertex, keeping its axes; the other boxes are
  /// untouched. The tree's shape is unchanged.
  RefitReport refit(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices);

  /// Checks the invariants: the structure (children partition their parent's range, every
  /// triangle in exactly one leaf) and that every triangle lies inside every ancestor box.
  /// Returns an empty string when valid, else the first violation found.
  std::string validate() const;

  /// Bytes held: nodes, vertices, and the topology (ordered triangles, ids, vertex spans) unless
  /// it was shared from a sibling (buildLike); capacities, not sizes.
  std::size_t memoryBytes() const;

 private:
  std::vector<Node> nodes_;
  std::vector<CompactNode> compact_nodes_;
  bool float_boxes_ = false;

  /// Replaces the double boxes by float boxes, each measured anew around its triangles.
  void storeFloatBoxes();
  /// Sets axis_defect_ from every box (after a build; a refit keeps the axes).
  void measureAxisDefect();
  void buildVertexSpans();
  /// Sets faces_ from the current vertices (tree_faces.cpp).
  void findPlanarFaces();
  void recordFreshVolumes();
  double boxVolume(std::size_t node) const;
  std::size_t subtreeEnd(std::size_t node) const;
  /// Rebuilds the subtree rooted at `node` over its current triangles (in place: later nodes
  /// shift); returns its new node count.
  std::size_t rebuildSubtree(std::size_t node);
  void rebuildGrownSubtrees(RefitReport& report);
  /// The vertices of inner node `node`'s triangles (BuildOptions::deformable).
  VertexSpan vertexSpan(std::size_t node) const;
  bool isLeafNode(std::size_t node) const {
    return float_boxes_ ? compact_nodes_[node].isLeaf() : nodes_[node].isLeaf();
  }
  /// The topology to change: a private copy first when it is shared with a sibling.
  TreeTopology& ownTopology();
  Eigen::Matrix3Xd vertices_;
  std::shared_ptr<TreeTopology> topology_ = std::make_shared<TreeTopology>();
  // Built by buildLike: memoryBytes counts the topology only once no sibling holds it.
  bool topology_borrowed_ = false;
  // With BuildOptions::deformable: each box's volume when it was last fitted fresh (at build or
  // rebuild), the reference of rebuild_ratio.
  std::vector<float> fresh_volume_;
  // Per leaf position: face << 1 | (1 when the triangle turns against its face). Kept only
  // where faces save work (at least a quarter of the triangles share one); empty otherwise, each
  // triangle then its own face.
  std::vector<std::int32_t> faces_;
  BuildOptions options_;
  int depth_ = 0;
  double axis_defect_ = 0.0;
};

}  // namespace collido::obbtree
