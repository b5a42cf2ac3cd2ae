// ObbTree construction, refit and validation on procedural meshes and the bunny: the structure
// (flat depth-first array, children partition their parent's range, every triangle in exactly
// one leaf), the split rule's promises (leaf sizes, failed splits only where every axis fails),
// the depth of well-spread meshes, boxes that hold their triangles, refit, memory accounting.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/mesh/mesh_io.h>
#include <collido/mesh/procedural.h>
#include <collido/obbtree/tree.h>

namespace collido::obbtree {
namespace {

struct NamedMesh {
  std::string name;
  TriangleMesh mesh;
};

TriangleMesh unwrap(Result<TriangleMesh> result, const std::string& what) {
  EXPECT_TRUE(result.ok()) << what << ": " << (result.ok() ? "" : result.status().toString());
  return result.ok() ? std::move(result).value() : TriangleMesh{};
}

// Small resolutions: Debug builds are slow, and the structure is the same at any size.
TriangleMesh smallTorus() {
  TorusParams torus;
  torus.major_segments = 16;
  torus.minor_segments = 8;
  return unwrap(makeTorus(torus), "torus");
}

const TriangleMesh& bunny() {
  static const TriangleMesh mesh = unwrap(loadMesh("scenes/meshes/bunny.obj"), "bunny.obj");
  return mesh;
}

const std::vector<NamedMesh>& testMeshes() {
  static const std::vector<NamedMesh> meshes = [] {
    std::vector<NamedMesh> out;
    out.push_back({"torus", smallTorus()});
    SphereParams sphere;
    sphere.slices = 16;
    sphere.stacks = 8;
    out.push_back({"sphere", unwrap(makeSphere(sphere), "sphere")});
    GridSheetParams sheet;
    sheet.cells_x = 12;
    sheet.cells_y = 12;
    sheet.amplitude = 0.2;
    out.push_back({"waved sheet", unwrap(makeGridSheet(sheet), "sheet")});
    sheet.cells_x = 8;
    sheet.cells_y = 8;
    sheet.amplitude = 0.0;
    out.push_back({"flat sheet", unwrap(makeGridSheet(sheet), "flat sheet")});
    GearParams gear;
    gear.teeth = 8;
    gear.flank_samples = 3;
    gear.root_samples = 1;
    out.push_back({"gear", unwrap(makeGear(gear), "gear")});
    ChainParams chain;
    chain.links = 3;
    chain.link.major_segments = 12;
    chain.link.minor_segments = 6;
    chain.clearance = -0.05;
    out.push_back({"chain", unwrap(makeChain(chain), "chain")});
    return out;
  }();
  return meshes;
}

// Independent structural checks (not relying on validate()); adds failures naming `label`.
void checkStructure(const ObbTree& tree, const TriangleMesh& mesh, int max_leaf,
                    const std::string& label) {
  const auto n = static_cast<std::int32_t>(mesh.triangleCount());
  const std::vector<Node>& nodes = tree.nodes();
  ASSERT_EQ(tree.triangleCount(), mesh.triangleCount()) << label;
  ASSERT_FALSE(nodes.empty()) << label;
  ASSERT_LE(nodes.size(), static_cast<std::size_t>(2 * n - 1)) << label;
  EXPECT_EQ(nodes[0].first, 0) << label;
  EXPECT_EQ(nodes[0].count, n) << label;
  EXPECT_EQ(tree.vertices(), mesh.vertices) << label;

  // Walk the tree from the root: children partition the parent's range, the first child is the
  // next node, depth as reported, every node reached once.
  std::vector<int> visits(nodes.size(), 0);
  std::vector<int> leaf_of(static_cast<std::size_t>(n), -1);  // position -> leaf
  int max_depth = 0;
  std::vector<std::pair<std::int32_t, int>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [index, depth] = stack.back();
    stack.pop_back();
    ASSERT_GE(index, 0) << label;
    ASSERT_LT(static_cast<std::size_t>(index), nodes.size()) << label;
    ++visits[static_cast<std::size_t>(index)];
    max_depth = std::max(max_depth, depth);
    const Node& node = nodes[static_cast<std::size_t>(index)];
    ASSERT_GT(node.count, 0) << label << " node " << index;
    const Eigen::Matrix3d& axes = node.box.axes;
    EXPECT_LT((axes.transpose() * axes - Eigen::Matrix3d::Identity()).norm(), 1e-12)
        << label << " node " << index;
    EXPECT_GT(axes.determinant(), 0.0) << label << " node " << index;
    EXPECT_TRUE((node.box.half_extents.array() >= 0.0).all()) << label << " node " << index;
    if (node.isLeaf()) {
      for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
        ASSERT_EQ(leaf_of[static_cast<std::size_t>(k)], -1)
            << label << ": position " << k << " in two leaves";
        leaf_of[static_cast<std::size_t>(k)] = index;
      }
      continue;
    }
    const Node& left = nodes[static_cast<std::size_t>(index) + 1];
    ASSERT_GT(node.second_child, index + 1) << label << " node " << index;
    ASSERT_LT(static_cast<std::size_t>(node.second_child), nodes.size()) << label;
    const Node& right = nodes[static_cast<std::size_t>(node.second_child)];
    EXPECT_EQ(left.first, node.first) << label << " node " << index;
    EXPECT_EQ(right.first, left.first + left.count) << label << " node " << index;
    EXPECT_EQ(left.count + right.count, node.count) << label << " node " << index;
    stack.push_back({node.second_child, depth + 1});
    stack.push_back({index + 1, depth + 1});
  }
  EXPECT_EQ(max_depth, tree.depth()) << label;
  for (std::size_t i = 0; i < visits.size(); ++i) {
    ASSERT_EQ(visits[i], 1) << label << ": node " << i << " reached " << visits[i] << " times";
  }

  // Every input triangle in exactly one leaf, stored with its own corners.
  std::vector<int> seen(static_cast<std::size_t>(n), 0);
  for (std::int32_t k = 0; k < n; ++k) {
    ASSERT_NE(leaf_of[static_cast<std::size_t>(k)], -1) << label << ": position " << k;
    const std::int32_t id = tree.triangleId(k);
    ASSERT_GE(id, 0) << label;
    ASSERT_LT(id, n) << label;
    ++seen[static_cast<std::size_t>(id)];
    EXPECT_EQ(tree.orderedTriangles().col(k), mesh.triangles.col(id)) << label << " id " << id;
  }
  for (std::int32_t id = 0; id < n; ++id) {
    ASSERT_EQ(seen[static_cast<std::size_t>(id)], 1) << label << ": triangle " << id;
  }

  // A leaf over the limit only where no box axis splits its centres (all on one side of the
  // mean plane, the build's rule).
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Node& node = nodes[i];
    if (!node.isLeaf() || node.count <= max_leaf) continue;
    for (int axis = 0; axis < 3; ++axis) {
      const Eigen::Vector3d direction = node.box.axes.col(axis);
      std::vector<double> projections;
      for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
        const auto t = tree.orderedTriangles().col(k);
        const Eigen::Vector3d centre =
            (mesh.vertices.col(t[0]) + mesh.vertices.col(t[1]) + mesh.vertices.col(t[2])) / 3.0;
        projections.push_back(direction.dot(centre));
      }
      double mean = 0.0;
      for (double p : projections)
        mean += p;
      mean /= static_cast<double>(projections.size());
      const auto below = std::count_if(projections.begin(), projections.end(),
                                       [mean](double p) { return p < mean; });
      EXPECT_TRUE(below == 0 || below == static_cast<std::ptrdiff_t>(projections.size()))
          << label << ": leaf " << i << " holds " << node.count << " > " << max_leaf
          << " triangles although axis " << axis << " splits them " << below << " / "
          << projections.size() - static_cast<std::size_t>(below);
    }
  }
}

// One mesh of a's triangles then b's.
TriangleMesh joined(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh mesh;
  mesh.vertices.resize(3, a.vertices.cols() + b.vertices.cols());
  mesh.vertices << a.vertices, b.vertices;
  mesh.triangles.resize(3, a.triangles.cols() + b.triangles.cols());
  mesh.triangles << a.triangles, (b.triangles.array() + static_cast<int>(a.vertices.cols()));
  return mesh;
}

// Builds and checks one tree; the depth bound holds for these well-spread meshes.
void checkBuild(const TriangleMesh& mesh, int max_leaf, const std::string& label,
                bool split_by_cost = true) {
  BuildOptions options;
  options.max_leaf_triangles = max_leaf;
  options.split_by_cost = split_by_cost;
  const ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, options);
  EXPECT_EQ(tree.validate(), "") << label;
  checkStructure(tree, mesh, max_leaf, label);
  const double n = static_cast<double>(mesh.triangleCount());
  EXPECT_LE(tree.depth(), 4.0 * std::log2(n) + 8.0) << label;
  EXPECT_GE(tree.depth(), std::log2(n / max_leaf) - 1.0) << label;  // it did split
  // Leaves do split down to the limit on these meshes: few leaves are over it.
  std::size_t oversized = 0;
  for (const Node& node : tree.nodes())
    oversized += node.isLeaf() && node.count > max_leaf ? 1 : 0;
  EXPECT_LE(oversized, tree.nodes().size() / 100) << label;
}

TEST(ObbTreeBuild, ProceduralMeshesAtSeveralLeafSizes) {
  for (const NamedMesh& m : testMeshes()) {
    ASSERT_GE(m.mesh.triangleCount(), 100u) << m.name;
    for (int max_leaf : {1, 2, 4, 16}) {
      for (const bool by_cost : {true, false}) {
        checkBuild(m.mesh, max_leaf,
                   m.name + ", max_leaf " + std::to_string(max_leaf) +
                       (by_cost ? ", split by cost" : ", mean split"),
                   by_cost);
        if (HasFatalFailure()) return;
      }
    }
  }
}

TEST(ObbTreeBuild, BunnyAtTheExtremeLeafSizes) {
  ASSERT_EQ(bunny().triangleCount(), 3674u);
  for (int max_leaf : {1, 16})
    checkBuild(bunny(), max_leaf, "bunny, max_leaf " + std::to_string(max_leaf));
}

// A shaft standing clear above a wide plate (a flange and its shaft, a robot link's two ends):
// the cost model gives each part a child of its own, where the mean split cuts the plate in two
// and leaves one half with the shaft, a child whose box spans the empty space between them.
TEST(ObbTreeBuild, CostSplitGivesAShaftAndItsPlateAChildEach) {
  GridSheetParams sheet;
  sheet.width = 10.0;
  sheet.depth = 10.0;
  sheet.cells_x = 8;
  sheet.cells_y = 8;
  const TriangleMesh plate = unwrap(makeGridSheet(sheet), "plate");
  CylinderParams rod;
  rod.radius = 0.1;
  rod.height = 10.0;
  rod.segments = 16;
  TriangleMesh shaft = unwrap(makeCylinder(rod), "shaft");
  shaft.vertices.row(2).array() += 6.5;  // z from 1.5 to 11.5, above the plate at z = 0
  const TriangleMesh mesh = joined(plate, shaft);
  const auto plate_triangles = static_cast<std::int32_t>(plate.triangles.cols());

  // How many of the root's children hold triangles of one part only.
  const auto pure_children = [&](bool split_by_cost) {
    BuildOptions options;
    options.split_by_cost = split_by_cost;
    const ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, options);
    EXPECT_EQ(tree.validate(), "");
    checkStructure(tree, mesh, 1, split_by_cost ? "split by cost" : "mean split");
    int pure = 0;
    for (const std::size_t child :
         {std::size_t{1}, static_cast<std::size_t>(tree.nodes()[0].second_child)}) {
      const Node& node = tree.nodes()[child];
      int from_plate = 0;
      for (std::int32_t k = node.first; k < node.first + node.count; ++k)
        from_plate += tree.triangleId(k) < plate_triangles ? 1 : 0;
      pure += from_plate == 0 || from_plate == node.count ? 1 : 0;
    }
    return pure;
  };
  EXPECT_EQ(pure_children(true), 2);
  EXPECT_LT(pure_children(false), 2);
}

// Triangles (c + u, c + v, c - u - v) with small integer u, v: every centre is exactly c, so no
// axis can split them and the root stays a leaf whatever the leaf size.
TriangleMesh coincidentCentres(const Eigen::Vector3d& c, int count) {
  TriangleMesh mesh;
  mesh.vertices.resize(3, 3 * count);
  mesh.triangles.resize(3, count);
  std::mt19937_64 rng(4);
  std::uniform_int_distribution<int> q(-8, 8);
  for (int t = 0; t < count; ++t) {
    const Eigen::Vector3d u(q(rng), q(rng), q(rng));
    const Eigen::Vector3d v(q(rng), q(rng), q(rng));
    mesh.vertices.col(3 * t) = c + u;
    mesh.vertices.col(3 * t + 1) = c + v;
    mesh.vertices.col(3 * t + 2) = c - u - v;
    mesh.triangles.col(t) << 3 * t, 3 * t + 1, 3 * t + 2;
  }
  return mesh;
}

TEST(ObbTreeBuild, CoincidentCentresMakeASingleLeaf) {
  const TriangleMesh mesh = coincidentCentres(Eigen::Vector3d(1, 2, 3), 50);
  for (int max_leaf : {1, 4, 16}) {
    const ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, {max_leaf});
    ASSERT_EQ(tree.nodes().size(), 1u) << "max_leaf " << max_leaf;
    EXPECT_TRUE(tree.nodes()[0].isLeaf());
    EXPECT_EQ(tree.nodes()[0].count, 50);
    EXPECT_EQ(tree.depth(), 0);
    EXPECT_EQ(tree.validate(), "");
    checkStructure(tree, mesh, max_leaf, "coincident centres");
  }
}

// A compact node counts a leaf's triangles in 16 bits: more coincident centres than that are
// split in halves, in both kinds of tree, and a larger max_leaf_triangles is capped.
TEST(ObbTreeBuild, CoincidentCentresBeyondTheLeafLimitAreSplitInHalves) {
  const TriangleMesh mesh = coincidentCentres(Eigen::Vector3d(1, 2, 3), kMaxLeafTriangles + 5);
  for (const bool float_boxes : {false, true}) {
    const ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, {1 << 20, float_boxes});
    ASSERT_EQ(tree.nodeCount(), 3u);
    EXPECT_EQ(tree.validate(), "");
    EXPECT_EQ(tree.triangleRange(1).count, (kMaxLeafTriangles + 5) / 2);
    EXPECT_EQ(tree.triangleRange(2).count, kMaxLeafTriangles + 5 - (kMaxLeafTriangles + 5) / 2);
  }
}

TEST(ObbTreeBuild, TwoClustersOfCoincidentCentresMakeTwoLeaves) {
  const TriangleMesh mesh = joined(coincidentCentres(Eigen::Vector3d(1, 2, 3), 20),
                                   coincidentCentres(Eigen::Vector3d(101, 2, 3), 30));
  const ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, {1});
  ASSERT_EQ(tree.nodes().size(), 3u);
  EXPECT_EQ(tree.depth(), 1);
  EXPECT_EQ(tree.validate(), "");
  checkStructure(tree, mesh, 1, "two clusters");
  EXPECT_EQ(std::min(tree.nodes()[1].count, tree.nodes()[2].count), 20);
}

TEST(ObbTreeBuild, SmallAndEmptyInputs) {
  TriangleMesh one;
  one.vertices.resize(3, 3);
  one.vertices << 0, 1, 0,  //
      0, 0, 1,              //
      0, 0, 0;
  one.triangles.resize(3, 1);
  one.triangles.col(0) << 0, 1, 2;
  const ObbTree single = ObbTree::build(one.vertices, one.triangles);
  ASSERT_EQ(single.nodes().size(), 1u);
  EXPECT_EQ(single.validate(), "");
  EXPECT_EQ(single.depth(), 0);

  const ObbTree empty = ObbTree::build(Eigen::Matrix3Xd(3, 0), Eigen::Matrix3Xi(3, 0));
  EXPECT_TRUE(empty.nodes().empty());
  EXPECT_EQ(empty.triangleCount(), 0u);
  EXPECT_EQ(empty.validate(), "");

  // max_leaf_triangles below 1 means 1.
  const TriangleMesh torus = smallTorus();
  const ObbTree zero = ObbTree::build(torus.vertices, torus.triangles, {0});
  const ObbTree unit = ObbTree::build(torus.vertices, torus.triangles, {1});
  EXPECT_EQ(zero.nodes().size(), unit.nodes().size());
  EXPECT_EQ(zero.validate(), "");
}

// A degenerate mesh: zero-area triangles, duplicated triangles, a flat sheet (zero thickness).
// Indices are stored in 16 bits up to 65,536 vertices and in 32 above: a torus whose vertices
// sit after unused padding, its last index just inside and just past the narrow range.
TEST(ObbTreeBuild, VertexIndicesNarrowUpToSixteenBits) {
  const TriangleMesh torus = smallTorus();
  for (const Eigen::Index last_index : {Eigen::Index{65535}, Eigen::Index{65536}}) {
    const Eigen::Index padding = last_index + 1 - torus.vertices.cols();
    Eigen::Matrix3Xd vertices = Eigen::Matrix3Xd::Zero(3, last_index + 1);
    vertices.rightCols(torus.vertices.cols()) = torus.vertices;
    const Eigen::Matrix3Xi triangles = torus.triangles.array() + static_cast<int>(padding);
    const ObbTree tree = ObbTree::build(vertices, triangles, {4});
    const std::string label = "last index " + std::to_string(last_index);
    EXPECT_EQ(tree.orderedTriangles().narrow(), last_index <= 65535) << label;
    EXPECT_EQ(tree.validate(), "") << label;
    for (std::int32_t k = 0; k < static_cast<std::int32_t>(tree.triangleCount()); ++k) {
      ASSERT_EQ(tree.orderedTriangles().col(k), triangles.col(tree.triangleId(k)))
          << label << ", position " << k;
    }
  }
}

TEST(ObbTreeBuildDeathTest, AnIndexNamingNoVertexIsRefused) {
  const TriangleMesh torus = smallTorus();
  Eigen::Matrix3Xi triangles = torus.triangles;
  triangles(1, 3) = static_cast<int>(torus.vertices.cols());
  EXPECT_DEATH(ObbTree::build(torus.vertices, triangles), "names no vertex");
  triangles(1, 3) = -1;
  EXPECT_DEATH(ObbTree::build(torus.vertices, triangles), "names no vertex");
}

TEST(ObbTreeBuild, DegenerateTrianglesAreStillContained) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  TriangleMesh mesh;
  const int n = 300;
  mesh.vertices.resize(3, 3 * n);
  mesh.triangles.resize(3, n);
  for (int t = 0; t < n; ++t) {
    const Eigen::Vector3d a(u(rng), u(rng), u(rng));
    const Eigen::Vector3d b(u(rng), u(rng), u(rng));
    switch (t % 3) {
      case 0:  // a point
        mesh.vertices.col(3 * t) = a;
        mesh.vertices.col(3 * t + 1) = a;
        mesh.vertices.col(3 * t + 2) = a;
        break;
      case 1:  // a segment
        mesh.vertices.col(3 * t) = a;
        mesh.vertices.col(3 * t + 1) = b;
        mesh.vertices.col(3 * t + 2) = 0.5 * (a + b);
        break;
      default:  // a proper triangle, repeated by the next index when it exists
        mesh.vertices.col(3 * t) = a;
        mesh.vertices.col(3 * t + 1) = b;
        mesh.vertices.col(3 * t + 2) = Eigen::Vector3d(u(rng), u(rng), u(rng));
        break;
    }
    mesh.triangles.col(t) << 3 * t, 3 * t + 1, 3 * t + 2;
  }
  mesh.triangles.col(n - 1) = mesh.triangles.col(n - 2);  // a duplicated triangle
  for (int max_leaf : {1, 4}) {
    const ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, {max_leaf});
    EXPECT_EQ(tree.validate(), "") << "max_leaf " << max_leaf;
    checkStructure(tree, mesh, max_leaf, "degenerate soup, max_leaf " + std::to_string(max_leaf));
  }
}

// The same mesh far from the origin (1e6) and scaled down (1e-6): boxes still hold every vertex.
TEST(ObbTreeBuild, FarFromTheOriginAndTiny) {
  TriangleMesh mesh = smallTorus();
  mesh.vertices.colwise() += Eigen::Vector3d(1e6, -2e6, 3e5);
  ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, {2});
  EXPECT_EQ(tree.validate(), "");
  checkStructure(tree, mesh, 2, "far torus");
  TriangleMesh tiny = smallTorus();
  tiny.vertices *= 1e-6;
  tree = ObbTree::build(tiny.vertices, tiny.triangles, {2});
  EXPECT_EQ(tree.validate(), "");
  checkStructure(tree, tiny, 2, "tiny torus");
}

// Refit keeps the shape and axes, measures every box anew (so a moved mesh moves its boxes) and
// keeps validate() clean under a smooth deformation and under random vertex noise.
// Centres a few subnormals apart: the cost split's bins span less than 16 / DBL_MAX, where a
// bin computed as (centre - least) * (16 / spread) multiplies by infinity (found by
// tree_query_fuzz under UBSan).
TEST(ObbTreeBuild, CentresASubnormalApartBuild) {
  constexpr double step = 1e-310;
  constexpr double size = 1e-309;
  TriangleMesh mesh;
  mesh.vertices.resize(3, 12);
  mesh.triangles.resize(3, 4);
  for (int t = 0; t < 4; ++t) {
    const double x = t * step;
    mesh.vertices.col(3 * t) << x, 0.0, 0.0;
    mesh.vertices.col(3 * t + 1) << x + size, 0.0, 0.0;
    mesh.vertices.col(3 * t + 2) << x, size, 0.0;
    mesh.triangles.col(t) << 3 * t, 3 * t + 1, 3 * t + 2;
  }
  for (const bool split_by_cost : {true, false}) {
    BuildOptions options;
    options.split_by_cost = split_by_cost;
    const ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, options);
    EXPECT_EQ(tree.validate(), "") << split_by_cost;
    std::int32_t triangles = 0;
    for (const Node& node : tree.nodes())
      triangles += node.isLeaf() ? node.count : 0;
    EXPECT_EQ(triangles, 4) << split_by_cost;
  }
}

TEST(ObbTreeRefit, KeepsShapeAndAxesAndContainsMovedTriangles) {
  std::mt19937_64 rng(21);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::vector<std::pair<NamedMesh, int>> cases;
  for (const NamedMesh& m : testMeshes()) {
    for (int max_leaf : {1, 4})
      cases.push_back({m, max_leaf});
  }
  cases.push_back({NamedMesh{"bunny", bunny()}, 16});
  for (const auto& [m, max_leaf] : cases) {
    // Refit over triangle corners, and over the vertex spans a deformable tree keeps.
    for (const bool deformable : {false, true}) {
      const std::string label =
          m.name + ", max_leaf " + std::to_string(max_leaf) + (deformable ? ", deformable" : "");
      ObbTree tree =
          ObbTree::build(m.mesh.vertices, m.mesh.triangles, {max_leaf, false, deformable});
      const std::vector<Node> before = tree.nodes();
      const int depth = tree.depth();

      // Twist about z, stretch, move and jitter.
      Eigen::Matrix3Xd moved = m.mesh.vertices;
      for (Eigen::Index v = 0; v < moved.cols(); ++v) {
        const Eigen::Vector3d p = moved.col(v);
        const Eigen::Matrix3d twist =
            Eigen::AngleAxisd(0.3 * p.z(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
        moved.col(v) = twist * Eigen::Vector3d(1.5 * p.x(), p.y(), 0.7 * p.z()) +
                       Eigen::Vector3d(10.0, -4.0, 2.5) +
                       Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      }
      tree.refit(moved);
      EXPECT_EQ(tree.validate(), "") << label;
      EXPECT_EQ(tree.vertices(), moved) << label;
      EXPECT_EQ(tree.depth(), depth) << label;
      ASSERT_EQ(tree.nodes().size(), before.size()) << label;
      for (std::size_t i = 0; i < before.size(); ++i) {
        const Node& now = tree.nodes()[i];
        ASSERT_EQ(now.box.axes, before[i].box.axes) << label << " node " << i;
        ASSERT_EQ(now.second_child, before[i].second_child) << label << " node " << i;
        ASSERT_EQ(now.first, before[i].first) << label << " node " << i;
        ASSERT_EQ(now.count, before[i].count) << label << " node " << i;
      }
      // The root box moved with the mesh: its centre is near the moved vertices' mean, not the
      // old one (the offset is (10, -4, 2.5)).
      const Eigen::Vector3d mean = moved.rowwise().mean();
      EXPECT_LT((tree.nodes()[0].box.center - mean).norm(), (before[0].box.center - mean).norm())
          << label;
      // Tight: each box's extents are the extremes of its own vertices (not a union of its
      // children's boxes), within the rounding allowance.
      for (std::size_t i = 0; i < tree.nodes().size(); i += 7) {
        const Node& node = tree.nodes()[i];
        Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300);
        Eigen::Vector3d hi = -lo;
        for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
          for (int c = 0; c < 3; ++c) {
            const Eigen::Vector3d u =
                node.box.axes.transpose() * moved.col(tree.orderedTriangles()(c, k));
            lo = lo.cwiseMin(u);
            hi = hi.cwiseMax(u);
          }
        }
        const Eigen::Vector3d half = 0.5 * (hi - lo);
        EXPECT_LT((node.box.half_extents - half).cwiseAbs().maxCoeff(), 1e-9)
            << label << " node " << i;
      }
      if (HasFatalFailure()) return;
    }
  }
}

// Only the boxes holding a moved vertex are measured anew; the others stay as they were, and a
// refit to the same positions does nothing.
TEST(ObbTreeRefit, OnlyBoxesWithMovedVerticesAreRefit) {
  const TriangleMesh& mesh = bunny();
  for (const bool float_boxes : {false, true}) {
    ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, {4, float_boxes, true});
    EXPECT_EQ(tree.refit(mesh.vertices).moved_vertices, 0u);
    Eigen::Matrix3Xd moved = mesh.vertices;
    moved.col(0) += Eigen::Vector3d(0.01, 0.02, -0.01);  // one vertex of a few triangles
    const std::vector<CompactNode> compact_before = tree.compactNodes();
    const std::vector<Node> before = tree.nodes();
    const RefitReport report = tree.refit(moved);
    EXPECT_EQ(report.moved_vertices, 1u);
    EXPECT_GT(report.nodes_refit, 0u);
    EXPECT_LT(report.nodes_refit, 4u * static_cast<std::size_t>(tree.depth() + 1));
    EXPECT_EQ(tree.validate(), "");
    std::size_t changed = 0;
    for (std::size_t i = 0; i < tree.nodeCount(); ++i) {
      if (float_boxes) {
        const CompactBox& now = tree.compactNodes()[i].box;
        const CompactBox& then = compact_before[i].box;
        bool same = true;
        for (int k = 0; k < 3; ++k)
          same =
              same && now.center[k] == then.center[k] && halfExtent(now, k) == halfExtent(then, k);
        changed += same ? 0 : 1;
      } else {
        changed += tree.nodes()[i].box.half_extents != before[i].box.half_extents ||
                           tree.nodes()[i].box.center != before[i].box.center
                       ? 1
                       : 0;
      }
    }
    EXPECT_LE(changed, report.nodes_refit);
  }
}

// Refit back to the build's vertices gives boxes that hold them again (a round trip).
TEST(ObbTreeRefit, RoundTripToTheOriginalVertices) {
  const TriangleMesh mesh = testMeshes()[1].mesh;  // sphere
  ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, {2});
  const std::vector<Node> built = tree.nodes();
  tree.refit(mesh.vertices * 3.0);
  EXPECT_EQ(tree.validate(), "");
  tree.refit(mesh.vertices);
  EXPECT_EQ(tree.validate(), "");
  checkStructure(tree, mesh, 2, "sphere refit round trip");
  // Back where it was built: the same boxes (measured over the same vertices with the same
  // axes), up to the rounding of the reference point they are measured from.
  for (std::size_t i = 0; i < built.size(); ++i) {
    EXPECT_LT((tree.nodes()[i].box.center - built[i].box.center).norm(), 1e-12) << i;
    EXPECT_LT((tree.nodes()[i].box.half_extents - built[i].box.half_extents).norm(), 1e-12) << i;
  }
}

TEST(ObbTreeMemory, PositiveAndGrowsWithTheTriangleCount) {
  std::size_t previous = 0;
  for (int segments : {4, 8, 12, 16}) {
    TorusParams params;
    params.major_segments = 2 * segments;
    params.minor_segments = segments;
    const TriangleMesh torus = unwrap(makeTorus(params), "torus");
    const ObbTree tree = ObbTree::build(torus.vertices, torus.triangles, {1});
    const std::size_t bytes = tree.memoryBytes();
    // At least what it must hold: nodes, vertices, triangles and ids.
    const std::size_t floor =
        tree.nodes().size() * sizeof(Node) + torus.vertexCount() * 3 * sizeof(double) +
        torus.triangleCount() * (3 * sizeof(std::uint16_t) + sizeof(std::int32_t));
    EXPECT_GE(bytes, floor) << segments;
    EXPECT_LE(bytes, 2 * floor) << segments;  // no hidden slack
    EXPECT_GT(bytes, previous) << segments;
    previous = bytes;
  }
}

}  // namespace
}  // namespace collido::obbtree

namespace collido::obbtree {
namespace {

// Float boxes: the same tree shape as double boxes, every triangle still inside every box the
// query decodes (validate), a third of the node memory, and refit keeps that true.
TEST(ObbTreeFloatBoxes, SameShapeContainedAndSmaller) {
  const Result<TriangleMesh> bunny = loadMesh("scenes/meshes/bunny.obj");
  ASSERT_TRUE(bunny.ok());
  TriangleMesh far = smallTorus();
  far.vertices.colwise() += Eigen::Vector3d(1e6, -2e6, 3e5);
  TriangleMesh tiny = smallTorus();
  tiny.vertices *= 1e-6;
  for (const auto& [label, mesh] :
       {std::pair<const char*, const TriangleMesh*>{"bunny", &bunny.value()},
        {"far torus", &far},
        {"tiny torus", &tiny}}) {
    for (std::int32_t leaf : {1, 4}) {
      SCOPED_TRACE(std::string(label) + " leaf " + std::to_string(leaf));
      const ObbTree doubles = ObbTree::build(mesh->vertices, mesh->triangles, {leaf, false});
      const ObbTree floats = ObbTree::build(mesh->vertices, mesh->triangles, {leaf, true});
      EXPECT_TRUE(floats.floatBoxes());
      EXPECT_TRUE(floats.nodes().empty());
      EXPECT_EQ(floats.validate(), "");
      ASSERT_EQ(floats.nodeCount(), doubles.nodeCount());
      for (std::size_t i = 0; i < floats.nodeCount(); ++i) {
        const CompactNode& compact = floats.compactNodes()[i];
        const Node& node = doubles.nodes()[i];
        ASSERT_EQ(compact.isLeaf(), node.isLeaf());
        if (node.isLeaf()) {
          EXPECT_EQ(compact.leafCount(), node.count);
        } else {
          EXPECT_EQ(compact.secondChild(), node.second_child);
        }
        EXPECT_EQ(floats.triangleRange(i).first, node.first);
        EXPECT_EQ(floats.triangleRange(i).count, node.count);
      }
      EXPECT_LT(floats.memoryBytes(), doubles.memoryBytes());
    }
  }
}

TEST(ObbTreeFloatBoxes, RefitKeepsEveryTriangleInside) {
  TriangleMesh mesh = smallTorus();
  ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles, {1, true});
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    mesh.vertices.col(v) += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  }
  tree.refit(mesh.vertices);
  EXPECT_TRUE(tree.floatBoxes());
  EXPECT_EQ(tree.validate(), "");
}

}  // namespace
}  // namespace collido::obbtree
