// Planar faces of a tree's mesh (ObbTree::faceOf): the exact signs of the collision query's last
// stages are kept per face and vertex (face_signs.h), so that flush contact between flat parts
// decides each vertex against each touching face once.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

#include <collido/obbtree/tree.h>
#include <collido/oracle/orientation.h>

namespace collido::obbtree {
namespace {

// One id per distinct vertex position (exact comparison), so that meshes stored with a copy of
// each vertex per triangle join along their edges too.
std::vector<std::int32_t> positionIds(const Eigen::Matrix3Xd& vertices) {
  const auto count = static_cast<std::size_t>(vertices.cols());
  std::vector<std::int32_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  const auto less = [&](std::int32_t i, std::int32_t j) {
    const auto a = vertices.col(i);
    const auto b = vertices.col(j);
    return std::make_tuple(a.x(), a.y(), a.z()) < std::make_tuple(b.x(), b.y(), b.z());
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<std::int32_t> ids(count);
  std::int32_t id = -1;
  for (std::size_t k = 0; k < count; ++k) {
    if (k == 0 || less(order[k - 1], order[k])) ++id;
    ids[static_cast<std::size_t>(order[k])] = id;
  }
  return ids;
}

struct EdgeUse {
  std::uint64_t key;      // the two position ids, smaller first
  std::int32_t triangle;  // leaf position
};

}  // namespace

void ObbTree::findPlanarFaces() {
  faces_.clear();
  const TriangleList& triangles = topology_->triangles;
  const auto count = static_cast<std::int32_t>(triangles.cols());
  if (count < 2) return;
  const std::vector<std::int32_t> ids = positionIds(vertices_);
  const auto idOf = [&](std::int32_t k, int corner) {
    return ids[static_cast<std::size_t>(triangles(corner, k))];
  };
  // Edge e of triangle k by its ends' position ids, the smaller first; 0 for a collapsed edge
  // (ids are distinct, so no real edge has the key 0).
  const auto edgeKey = [&](std::int32_t k, int e) -> std::uint64_t {
    const auto u = static_cast<std::uint32_t>(idOf(k, e));
    const auto v = static_cast<std::uint32_t>(idOf(k, (e + 1) % 3));
    return u == v ? 0 : (std::uint64_t{std::min(u, v)} << 32) | std::max(u, v);
  };
  std::vector<EdgeUse> uses;  // every edge of every triangle, sorted by key
  uses.reserve(3 * static_cast<std::size_t>(count));
  for (std::int32_t k = 0; k < count; ++k) {
    for (int e = 0; e < 3; ++e) {
      if (const std::uint64_t key = edgeKey(k, e)) uses.push_back(EdgeUse{key, k});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.key < y.key || (x.key == y.key && x.triangle < y.triangle);
  });
  const auto corner = [&](std::int32_t k, int c) -> Eigen::Vector3d {
    return vertices_.col(triangles(c, k));
  };
  std::vector<std::int32_t> faces(static_cast<std::size_t>(count), -1);
  std::vector<std::int32_t> queue;
  std::int32_t face_count = 0;
  for (std::int32_t seed = 0; seed < count; ++seed) {
    if (faces[static_cast<std::size_t>(seed)] >= 0) continue;
    ++face_count;
    faces[static_cast<std::size_t>(seed)] = seed << 1;
    const Eigen::Vector3d s[3] = {corner(seed, 0), corner(seed, 1), corner(seed, 2)};
    if (exact::collinear(s[0], s[1], s[2])) continue;  // no plane: a face of its own
    int drop = 0;  // a projection in which the seed, and so every triangle of its plane, is proper
    while (exact::orient2d(s[0], s[1], s[2], drop) == 0)
      ++drop;
    const int seed_turn = exact::orient2d(s[0], s[1], s[2], drop);
    queue.assign(1, seed);
    while (!queue.empty()) {
      const std::int32_t t = queue.back();
      queue.pop_back();
      for (int e = 0; e < 3; ++e) {
        const std::uint64_t key = edgeKey(t, e);
        const auto first =
            std::lower_bound(uses.begin(), uses.end(), key,
                             [](const EdgeUse& use, std::uint64_t k) { return use.key < k; });
        for (auto i = first; i != uses.end() && i->key == key; ++i) {
          const std::int32_t r = i->triangle;
          if (faces[static_cast<std::size_t>(r)] >= 0) continue;
          const Eigen::Vector3d p[3] = {corner(r, 0), corner(r, 1), corner(r, 2)};
          // r shares an edge with a triangle of the plane: the corners off that edge decide.
          bool in_plane = true;
          for (int c = 0; c < 3 && in_plane; ++c) {
            const auto id = static_cast<std::uint64_t>(idOf(r, c));
            if (id == (key >> 32) || id == (key & 0xffffffffu)) continue;
            in_plane = exact::orient3d(s[0], s[1], s[2], p[c]) == 0;
          }
          if (!in_plane) continue;
          const int turn = exact::orient2d(p[0], p[1], p[2], drop);
          if (turn == 0) continue;  // degenerate: left to a face of its own
          faces[static_cast<std::size_t>(r)] = (seed << 1) | (turn == seed_turn ? 0 : 1);
          queue.push_back(r);
        }
      }
    }
  }
  // Where few triangles share a face (curved meshes) the faces save nothing: each triangle is
  // its own, and nothing is stored.
  if (4 * static_cast<std::int64_t>(face_count) > 3 * static_cast<std::int64_t>(count)) return;
  faces_ = std::move(faces);
}

}  // namespace collido::obbtree
