#include <collido/assert.h>
#include <collido/obbtree/tree.h>

namespace collido::obbtree {

void ObbTree::refit(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices) {
  COLLIDO_ASSERT(vertices.cols() == vertices_.cols(), "refit needs the same vertex count");
  vertices_ = vertices;
  // Children come after their parent in depth-first order, so a reverse sweep is bottom-up. Each
  // box keeps its axes and is measured over its own triangles: exact extents, not a union of
  // the children's boxes, which would grow with every level.
  for (auto node = nodes_.rbegin(); node != nodes_.rend(); ++node) {
    refitBoxExtents(node->box, vertices_, triangles_.middleCols(node->first, node->count));
  }
  for (auto node = compact_nodes_.rbegin(); node != compact_nodes_.rend(); ++node) {
    refitCompactBox(node->box, vertices_, triangles_.middleCols(node->first, node->count));
  }
}

}  // namespace collido::obbtree
