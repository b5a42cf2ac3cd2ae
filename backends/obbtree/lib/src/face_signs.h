// Exact signs of a vertex against a planar face of the other object, kept for one query. Where
// two flat parts touch flush, every triangle pair of the two touching faces asks the exact side
// of the same vertices against the same plane, and an exact zero is the costliest sign there is
// (the filter cannot settle it). A triangle's side of a vertex is its face's, times the
// triangle's turn against the face's (ObbTree::faceOf), so each (face, vertex) is decided once a
// query and every later triangle pair of those faces reads it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <collido/obbtree/tree.h>
#include <collido/obbtree/triangle_intersection.h>

#include "stamped_table.h"
#include "static_orientation.h"
#include "tracked_world.h"

namespace collido::obbtree::detail {

/// A triangle pair as the exact stages of the collision query see it: the corners in A's model
/// frame with their error radii (A's triangle first), their world positions (placed on first
/// use; null where the world is not used), what names them (each triangle's tree and position
/// in its leaf order), and the sides of its corners against the other's plane that the
/// certified plane tests settled. Vertices and faces are looked up only by a sign the filter
/// cannot settle.
struct FaceSignPair {
  const UncertainPoint* corners[2] = {};   ///< A's triangle's three corners, then B's
  LazyWorldPoint* const* world = nullptr;  ///< six, A's first; null unless in the world
  const ObbTree* tree[2] = {};
  std::int32_t triangle[2] = {};
  /// A's corners against B's plane, as settleSides (prepared_triangle.h) left them.
  int sides_of_a[3] = {kUndecidedSign, kUndecidedSign, kUndecidedSign};
  int sides_of_b[3] = {kUndecidedSign, kUndecidedSign, kUndecidedSign};  ///< B's against A's
  bool proper[2] = {};  ///< each triangle's corners certainly not collinear

  /// Corner `slot` of the pair: 0 to 2 A's, 3 to 5 B's.
  const UncertainPoint& mapped(int slot) const { return corners[slot / 3][slot % 3]; }
};

/// The signs decided in one query, by (object of the face, face, vertex of the other object),
/// in a table stamped by the query (stamped_table.h).
class FaceSignCache {
 public:
  static constexpr int kNone = 2;

  /// Forgets the last query's signs.
  void begin() { table_.begin(); }
  /// The sign kept for the key, or kNone.
  int find(int object, std::int32_t face, std::int32_t vertex) const {
    const std::int32_t* sign = table_.find(keyOf(object, face, vertex));
    return sign != nullptr ? *sign : kNone;
  }
  void store(int object, std::int32_t face, std::int32_t vertex, int sign) {
    table_.store(keyOf(object, face, vertex), sign);
  }
  std::size_t bytes() const { return table_.bytes(); }

 private:
  static std::uint64_t keyOf(int object, std::int32_t face, std::int32_t vertex) {
    return (static_cast<std::uint64_t>(object) << 63) |
           (static_cast<std::uint64_t>(static_cast<std::uint32_t>(face)) << 32) |
           static_cast<std::uint32_t>(vertex);
  }

  StampedTable<std::int32_t> table_;
};

/// Where the exact signs are taken: on A's model coordinates, every corner exact there (A's as
/// stored, B's where the map is exact: identity, quarter turns, slides along an axis), or on
/// the world positions as tracked double-doubles (only for a pose of A with a positive
/// determinant, where orientations in A's frame and the world's agree). Within one query the
/// cache holds either kind of sign: they are the same whenever the world is used.
enum class ExactFrame { kModelOfA, kWorld };

/// The exact triangle test on the pair: every orientation of one triangle's plane against a
/// corner of the other first through the certified filter, then through `cache`, then decided
/// and kept. std::nullopt when a world sign was uncertain (the caller goes on to the
/// expansions); in kModelOfA every sign is decided.
std::optional<bool> trianglesIntersectWithFaceSigns(const FaceSignPair& pair, ExactFrame frame,
                                                    FaceSignCache& cache);

}  // namespace collido::obbtree::detail
