#include "collide_check.h"

#include <algorithm>
#include <iterator>
#include <sstream>
#include <utility>

#include <gtest/gtest.h>

#include <collido/oracle/exact_oracle.h>

namespace collido::obbtree {

std::string listPairs(const Pairs& pairs, std::size_t limit) {
  std::ostringstream out;
  for (std::size_t i = 0; i < pairs.size() && i < limit; ++i) {
    out << " (" << pairs[i].a << ", " << pairs[i].b << ")";
  }
  if (pairs.size() > limit) out << " ... (" << pairs.size() << " in all)";
  return out.str();
}

TriangleMesh unwrap(Result<TriangleMesh> result, const std::string& what) {
  EXPECT_TRUE(result.ok()) << what << ": " << (result.ok() ? "" : result.status().toString());
  return result.ok() ? std::move(result).value() : TriangleMesh{};
}

Pairs sorted(const std::vector<obbtree::TrianglePair>& pairs) {
  Pairs out;
  out.reserve(pairs.size());
  for (const auto& p : pairs)
    out.push_back(collido::TrianglePair{p.a, p.b});
  std::sort(out.begin(), out.end());
  return out;
}

std::string differences(const Pairs& tree, const Pairs& truth) {
  Pairs missing;
  Pairs extra;
  std::set_difference(truth.begin(), truth.end(), tree.begin(), tree.end(),
                      std::back_inserter(missing));
  std::set_difference(tree.begin(), tree.end(), truth.begin(), truth.end(),
                      std::back_inserter(extra));
  const bool duplicates = std::adjacent_find(tree.begin(), tree.end()) != tree.end();
  if (missing.empty() && extra.empty() && !duplicates) return "";
  std::ostringstream out;
  out << "tree " << tree.size() << " pairs, exact " << truth.size() << ";";
  if (!missing.empty()) out << " missing" << listPairs(missing) << ";";
  if (!extra.empty()) out << " extra" << listPairs(extra) << ";";
  if (duplicates) out << " duplicate pairs reported;";
  return out.str();
}

Outcome checkQuery(const TriangleMesh& mesh_a, const ObbTree& tree_a, const Pose& pose_a,
                   const TriangleMesh& mesh_b, const ObbTree& tree_b, const Pose& pose_b,
                   const std::string& label) {
  Outcome out;
  const OracleAnswer answer = exactIntersectingPairs(mesh_a, pose_a, mesh_b, pose_b);
  out.truth = answer.pairs;
  CollideResult result;
  collide(tree_a, pose_a, tree_b, pose_b, CollideRequest{CollideMode::kAllPairs, 0}, result);
  out.tree = sorted(result.pairs);
  EXPECT_FALSE(result.truncated) << label;
  EXPECT_EQ(differences(out.tree, out.truth), "") << label;
  EXPECT_GE(result.triangle_tests, out.tree.size()) << label;
  EXPECT_GT(result.box_tests, 0u) << label;

  CollideResult first;
  collide(tree_a, pose_a, tree_b, pose_b, CollideRequest{CollideMode::kFirstHit, 0}, first);
  EXPECT_EQ(!first.pairs.empty(), answer.intersecting) << label << ": boolean answer";
  EXPECT_LE(first.pairs.size(), 1u) << label;
  if (!first.pairs.empty()) {
    const collido::TrianglePair witness{first.pairs[0].a, first.pairs[0].b};
    EXPECT_TRUE(std::binary_search(out.truth.begin(), out.truth.end(), witness))
        << label << ": witness (" << witness.a << ", " << witness.b << ") is not an exact pair";
    EXPECT_LE(first.triangle_tests, result.triangle_tests) << label << ": first hit stops early";
  }

  CollideResult swapped;
  collide(tree_b, pose_b, tree_a, pose_a, CollideRequest{}, swapped);
  Pairs mirrored;
  for (const auto& p : swapped.pairs)
    mirrored.push_back(collido::TrianglePair{p.b, p.a});
  std::sort(mirrored.begin(), mirrored.end());
  EXPECT_EQ(differences(mirrored, out.truth), "") << label << ": B-A query";
  return out;
}

Eigen::Matrix3d randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

Pose makePose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) {
  Pose pose = Pose::Identity();
  pose.linear() = rotation;
  pose.translation() = translation;
  return pose;
}

TriangleMesh chainLink(const TriangleMesh& chain, int links, int i) {
  const Eigen::Index v = chain.vertices.cols() / links;
  const Eigen::Index t = chain.triangles.cols() / links;
  TriangleMesh link;
  link.vertices = chain.vertices.middleCols(i * v, v);
  link.triangles = chain.triangles.middleCols(i * t, t).array() - static_cast<int>(i * v);
  return link;
}

bool oracleTrianglesIntersect(const std::array<Eigen::Vector3d, 3>& a, const Pose& pose_a,
                              const std::array<Eigen::Vector3d, 3>& b, const Pose& pose_b) {
  TriangleMesh mesh_a;
  mesh_a.vertices.resize(3, 3);
  mesh_a.triangles.resize(3, 1);
  mesh_a.triangles << 0, 1, 2;
  TriangleMesh mesh_b = mesh_a;
  for (int k = 0; k < 3; ++k) {
    mesh_a.vertices.col(k) = a[static_cast<std::size_t>(k)];
    mesh_b.vertices.col(k) = b[static_cast<std::size_t>(k)];
  }
  return exactPairIntersects(mesh_a, pose_a, mesh_b, pose_b, {0, 0});
}

}  // namespace collido::obbtree
