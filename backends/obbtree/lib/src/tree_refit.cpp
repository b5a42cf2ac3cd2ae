#include <collido/assert.h>
#include <collido/obbtree/tree.h>

namespace collido::obbtree {
namespace {

// Marks the nodes whose triangles use a moved vertex: children come after their parent in
// depth-first order, so a reverse sweep sees both children before their parent.
template <typename NodeT>
std::vector<char> dirtyNodes(const std::vector<NodeT>& nodes, const TriangleList& triangles,
                             const std::vector<char>& moved) {
  std::vector<char> dirty(nodes.size(), 0);
  for (std::size_t i = nodes.size(); i-- > 0;) {
    const NodeT& node = nodes[i];
    if (node.isLeaf()) {
      const std::int32_t first = node.leafFirst();
      for (std::int32_t t = first; t < first + node.leafCount() && dirty[i] == 0; ++t) {
        dirty[i] = moved[static_cast<std::size_t>(triangles(0, t))] |
                   moved[static_cast<std::size_t>(triangles(1, t))] |
                   moved[static_cast<std::size_t>(triangles(2, t))];
      }
    } else {
      dirty[i] = dirty[i + 1] | dirty[static_cast<std::size_t>(node.secondChild())];
    }
  }
  return dirty;
}

}  // namespace

RefitReport ObbTree::refit(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices) {
  COLLIDO_ASSERT(vertices.cols() == vertices_.cols(), "refit needs the same vertex count");
  RefitReport report;
  std::vector<char> moved(static_cast<std::size_t>(vertices.cols()), 0);
  for (Eigen::Index v = 0; v < vertices.cols(); ++v) {
    if (vertices.col(v) != vertices_.col(v)) {
      moved[static_cast<std::size_t>(v)] = 1;
      ++report.moved_vertices;
    }
  }
  if (report.moved_vertices == 0) return report;
  vertices_ = vertices;
  // A moved vertex may take its triangles out of their plane.
  faces_.clear();
  faces_.shrink_to_fit();
  // Bottom-up over the nodes holding a moved vertex only. Each box keeps its axes and is
  // measured over its own triangles: exact extents, not a union of the children's boxes, which
  // would grow with every level.
  // With vertex spans (BuildOptions::deformable) each vertex is projected once per node, not
  // once per triangle corner (about six times fewer projections on a closed mesh), and the
  // boxes are widened by the tree's bound on their axes' defect (axisDefect(), computed at
  // build over every box and kept by a refit, which keeps the axes).
  const bool spans = !topology_->first_use.empty();
  // Compact nodes keep no inner ranges: one sweep finds them all.
  const std::vector<TriangleRange> compact_ranges =
      float_boxes_ ? triangleRanges() : std::vector<TriangleRange>();
  const auto rangeOf = [&](std::size_t i) {
    return float_boxes_ ? compact_ranges[i] : TriangleRange{nodes_[i].first, nodes_[i].count};
  };
  // A leaf with spans is refit from its corners too (the spans keep no leaf lists), with the
  // tree's defect bound.
  const double known_defect = spans ? axis_defect_ : -1.0;
  const auto refitDirty = [&](auto& nodes, auto&& over_triangles, auto&& over_span) {
    const std::vector<char> dirty = dirtyNodes(nodes, topology_->triangles, moved);
    for (std::size_t i = nodes.size(); i-- > 0;) {
      if (dirty[i] == 0) continue;
      const TriangleRange range = rangeOf(i);
      if (spans && !nodes[i].isLeaf()) {
        over_span(nodes[i].box, vertexSpan(i));
      } else {
        over_triangles(nodes[i].box, range);
      }
      ++report.nodes_refit;
    }
  };
  refitDirty(
      nodes_,
      [&](OrientedBox& box, TriangleRange range) {
        refitBoxExtents(box, vertices_, topology_->triangles, range, known_defect);
      },
      [&](OrientedBox& box, const VertexSpan& span) {
        refitBoxExtents(box, vertices_, span, axis_defect_);
      });
  refitDirty(
      compact_nodes_,
      [&](CompactBox& box, TriangleRange range) {
        refitCompactBox(box, vertices_, topology_->triangles, range, known_defect);
      },
      [&](CompactBox& box, const VertexSpan& span) {
        refitCompactBox(box, vertices_, span, axis_defect_);
      });
  if (options_.deformable && options_.rebuild_ratio > 0.0) rebuildGrownSubtrees(report);
  return report;
}

VertexSpan ObbTree::vertexSpan(std::size_t node) const {
  const TreeTopology& topology = *topology_;
  VertexSpan span;
  span.first = topology.refit_order.data() + topology.first_use[node];
  span.last = topology.refit_order.data() + topology.first_use[subtreeEnd(node)];
  span.extra_first = topology.refit_extra.data() + topology.extra_begin[node];
  span.extra_last = topology.refit_extra.data() + topology.extra_begin[node + 1];
  return span;
}

}  // namespace collido::obbtree
