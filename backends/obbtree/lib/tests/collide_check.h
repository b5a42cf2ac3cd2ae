// Shared checks of tree-tree queries against the exact oracle.
#pragma once

#include <array>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/obbtree/collide.h>
#include <collido/query.h>
#include <collido/status.h>

namespace collido::obbtree {

using Pairs = std::vector<collido::TrianglePair>;

/// The value, or an empty mesh and a test failure naming `what`.
TriangleMesh unwrap(Result<TriangleMesh> result, const std::string& what);

/// The tree's pairs as oracle pairs, sorted.
Pairs sorted(const std::vector<obbtree::TrianglePair>& pairs);

/// Up to `limit` pairs as " (a, b)", with the total when there are more.
std::string listPairs(const Pairs& pairs, std::size_t limit = 8);

/// "" when equal, else the pairs each side lacks (a few of each) and duplicates.
std::string differences(const Pairs& tree, const Pairs& truth);

/// Both answers of checkQuery.
struct Outcome {
  Pairs truth;
  Pairs tree;
};

/// Runs the tree query (all pairs and first hit) and the oracle; checks equality, the boolean
/// answer and its witness, and the swapped query B-A (gtest failures name `label`).
Outcome checkQuery(const TriangleMesh& mesh_a, const ObbTree& tree_a, const Pose& pose_a,
                   const TriangleMesh& mesh_b, const ObbTree& tree_b, const Pose& pose_b,
                   const std::string& label);

Eigen::Matrix3d randomRotation(std::mt19937_64& rng);

/// Link i of a chain of `links` built by makeChain, as a mesh of its own (V vertices and 2 V
/// triangles per link, in order).
TriangleMesh chainLink(const TriangleMesh& chain, int links, int i);
Pose makePose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation);

/// The exact oracle's answer for triangle a placed by pose_a against triangle b placed by pose_b.
bool oracleTrianglesIntersect(const std::array<Eigen::Vector3d, 3>& a, const Pose& pose_a,
                              const std::array<Eigen::Vector3d, 3>& b, const Pose& pose_b);

}  // namespace collido::obbtree
