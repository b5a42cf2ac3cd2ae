// Trees of one object's active states built with ObbTree::buildLike: they share the sibling's
// leaf order (one copy, counted once), fit every box fresh at the state's positions, answer
// exactly, and a rebuild after a refit takes a private copy without touching the sibling.
#include <cmath>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/mesh/procedural.h>
#include <collido/obbtree/tree.h>

#include "collide_check.h"

namespace collido::obbtree {
namespace {

// Two interlocked links; state "folded" of link A bends it half over about the y axis, so its
// state differs from the rest shape by much more than a refit's kept axes would suit.
struct Links {
  TriangleMesh a;
  TriangleMesh folded_a;
  TriangleMesh b;
};

TriangleMesh link(const TriangleMesh& chain, int i) {
  const Eigen::Index v = chain.vertices.cols() / 2;
  const Eigen::Index t = chain.triangles.cols() / 2;
  TriangleMesh out;
  out.vertices = chain.vertices.middleCols(i * v, v);
  out.triangles = chain.triangles.middleCols(i * t, t).array() - static_cast<int>(i * v);
  return out;
}

Links links() {
  ChainParams params;
  params.links = 2;
  params.link.major_segments = 32;
  params.link.minor_segments = 12;
  const TriangleMesh chain = unwrap(makeChain(params), "chain");
  Links out{link(chain, 0), link(chain, 0), link(chain, 1)};
  for (Eigen::Index v = 0; v < out.folded_a.vertices.cols(); ++v) {
    const Eigen::Vector3d p = out.a.vertices.col(v);
    if (p.x() <= 0.0) continue;  // the half with x > 0 turns a quarter about y
    out.folded_a.vertices.col(v) =
        Eigen::AngleAxisd(0.5 * M_PI * p.x(), Eigen::Vector3d::UnitY()) * p;
  }
  return out;
}

BuildOptions options(bool float_boxes, bool deformable) {
  BuildOptions o;
  o.max_leaf_triangles = 4;
  o.float_boxes = float_boxes;
  o.deformable = deformable;
  return o;
}

TEST(ObbTreeStates, ShareTheLeafOrderAndAnswerExactly) {
  const Links l = links();
  for (const bool float_boxes : {false, true}) {
    for (const bool deformable : {false, true}) {
      const std::string label = std::string(float_boxes ? "float" : "double") + " boxes" +
                                (deformable ? ", deformable" : "");
      const BuildOptions o = options(float_boxes, deformable);
      const ObbTree rest = ObbTree::build(l.a.vertices, l.a.triangles, o);
      const ObbTree own = ObbTree::build(l.folded_a.vertices, l.folded_a.triangles, o);
      const std::size_t rest_alone = rest.memoryBytes();
      const ObbTree folded = ObbTree::buildLike(rest, l.folded_a.vertices, o);
      EXPECT_TRUE(rest.sharesTopology()) << label;
      EXPECT_TRUE(folded.sharesTopology()) << label;
      EXPECT_EQ(folded.orderedTriangles().data(), rest.orderedTriangles().data()) << label;
      EXPECT_EQ(folded.nodeCount(), rest.nodeCount()) << label;
      EXPECT_EQ(folded.floatBoxes(), float_boxes) << label;
      EXPECT_EQ(folded.validate(), "") << label;
      EXPECT_EQ(rest.validate(), "") << label;
      // The shared part is counted in the tree that built it only: the state tree (same node
      // count) is smaller by at least the ordered triangles and ids.
      EXPECT_EQ(rest.memoryBytes(), rest_alone) << label;
      EXPECT_LE(folded.memoryBytes() + rest.orderedTriangles().memoryBytes() +
                    folded.triangleCount() * sizeof(std::int32_t),
                rest_alone)
          << label;
      EXPECT_LT(folded.memoryBytes(), own.memoryBytes()) << label;
      // Boxes fitted fresh: the folded half's boxes have other axes than the rest shape's.
      if (!float_boxes) {
        std::size_t new_axes = 0;
        for (std::size_t i = 0; i < folded.nodeCount(); ++i)
          new_axes += folded.nodes()[i].box.axes != rest.nodes()[i].box.axes ? 1 : 0;
        EXPECT_GT(new_axes, folded.nodeCount() / 4) << label;
      }
      // Exact answers against the other link, folded and at rest, at a few poses.
      const ObbTree tree_b = ObbTree::build(l.b.vertices, l.b.triangles, o);
      std::mt19937_64 rng(7);
      for (int k = 0; k < 4; ++k) {
        const Pose pose_b =
            k == 0 ? Pose::Identity()
                   : makePose(randomRotation(rng), Eigen::Vector3d(0.1 * k, -0.05 * k, 0.02 * k));
        const std::string at = label + ", pose " + std::to_string(k);
        checkQuery(l.folded_a, folded, Pose::Identity(), l.b, tree_b, pose_b, at + ", folded");
        checkQuery(l.a, rest, Pose::Identity(), l.b, tree_b, pose_b, at + ", rest");
        if (HasFailure()) return;
      }
    }
  }
}

// A rebuild inside a refit (rebuild_ratio) reorders the leaves: the state tree takes a copy
// first, so its sibling keeps its order and stays valid.
TEST(ObbTreeStates, RebuildAfterRefitCopiesTheSharedOrder) {
  const Links l = links();
  BuildOptions o = options(false, true);
  o.rebuild_ratio = 1.5;
  const ObbTree rest = ObbTree::build(l.a.vertices, l.a.triangles, o);
  ObbTree state = ObbTree::buildLike(rest, l.a.vertices, o);
  const Eigen::Matrix3Xi order = rest.orderedTriangles().matrix();
  // Stretch along z threefold: many boxes grow past 1.5 times their fresh volume.
  Eigen::Matrix3Xd stretched = l.a.vertices;
  stretched.row(2) *= 3.0;
  stretched.row(0) += 0.4 * l.a.vertices.row(1);
  const RefitReport report = state.refit(stretched);
  ASSERT_GT(report.subtrees_rebuilt, 0u);
  EXPECT_FALSE(state.sharesTopology());
  EXPECT_FALSE(rest.sharesTopology());
  EXPECT_EQ(rest.orderedTriangles().matrix(), order);
  EXPECT_EQ(rest.validate(), "");
  EXPECT_EQ(state.validate(), "");
  TriangleMesh moved = l.a;
  moved.vertices = stretched;
  const ObbTree tree_b = ObbTree::build(l.b.vertices, l.b.triangles, o);
  checkQuery(moved, state, Pose::Identity(), l.b, tree_b, Pose::Identity(), "stretched state");
}

// Once the sibling is gone the state tree is the topology's only holder and counts it.
TEST(ObbTreeStates, TheLastHolderCountsTheSharedOrder) {
  const Links l = links();
  const BuildOptions o = options(false, false);
  std::size_t shared_bytes = 0;
  std::size_t borrowed_bytes = 0;
  std::optional<ObbTree> state;
  {
    const ObbTree rest = ObbTree::build(l.a.vertices, l.a.triangles, o);
    state = ObbTree::buildLike(rest, l.folded_a.vertices, o);
    borrowed_bytes = state->memoryBytes();
    shared_bytes =
        rest.orderedTriangles().memoryBytes() + rest.triangleCount() * sizeof(std::int32_t);
  }
  EXPECT_FALSE(state->sharesTopology());
  EXPECT_GE(state->memoryBytes(), borrowed_bytes + shared_bytes);
  EXPECT_EQ(state->validate(), "");
}

}  // namespace
}  // namespace collido::obbtree
