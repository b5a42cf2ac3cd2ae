// Builds an OBB tree over a tetrahedron and asks whether two posed copies touch.
#include <cstdio>

#include <collido/obbtree/collide.h>

int main() {
  Eigen::Matrix3Xd vertices(3, 4);
  vertices << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;  // rows: x, y, z of the four corners
  Eigen::Matrix3Xi triangles(3, 4);
  triangles << 0, 0, 0, 1, 2, 1, 3, 2, 1, 3, 2, 3;  // columns: the four faces
  const auto tree = collido::obbtree::ObbTree::build(vertices, triangles);

  for (const double shift : {0.2, 2.0}) {
    const Eigen::Isometry3d pose_b(Eigen::Translation3d(shift, shift, shift));
    collido::obbtree::CollideResult result;
    collido::obbtree::collide(tree, Eigen::Isometry3d::Identity(), tree, pose_b, {}, result);
    std::printf("shifted by %.1f: %zu intersecting triangle pairs\n", shift, result.pairs.size());
  }
}
