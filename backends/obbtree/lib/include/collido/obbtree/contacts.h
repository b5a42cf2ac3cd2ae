#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include <collido/obbtree/collide.h>
#include <collido/obbtree/tree.h>

namespace collido::obbtree {

/// How a contacts answer is merged and capped (docs/DESIGN.md, "Contact geometry").
struct ContactOptions {
  /// Contacts closer than this are merged into the deepest of them; 0 merges only coincident
  /// points.
  double merge_radius = 0.0;
  /// Most contacts returned; 0 = no limit. Past it the deepest is kept, then repeatedly the
  /// one farthest from those kept, so the manifold still spans the contact region.
  std::uint64_t max_contacts = 0;
};

/// One contact: where an intersecting triangle pair meets, in the world frame.
struct TriangleContact {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< the mean of the intersection set
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   ///< unit, from A towards B
  double depth = 0.0;                                  ///< along `normal`, >= 0
  std::int32_t triangle_a = -1;                        ///< input triangle index in A
  std::int32_t triangle_b = -1;                        ///< input triangle index in B
};

/// The contacts answer and the work it took.
struct ContactAnswer {
  std::vector<TriangleContact> contacts;
  bool truncated = false;        ///< max_contacts dropped some
  std::uint64_t exact_sets = 0;  ///< intersection sets computed in exact arithmetic
  std::uint64_t merged = 0;      ///< contacts merged into a deeper one nearby
};

/// The positions of input triangle ids in a tree's leaf order (the inverse of triangleId), kept
/// by a model that answers contacts so a pair's corners are found in constant time.
std::vector<std::int32_t> leafPositionsOfIds(const ObbTree& tree);

/// The contacts of intersecting triangle pairs (as collide() finds them) of two posed trees, as
/// docs/DESIGN.md defines them. Per pair, the intersection set in three stages:
/// - crossing triangles (every corner clearly off the other's plane, the planes and each
///   crossing edge at least 2^-10 in sine from parallel): the segment where each meets the
///   other's plane, overlapped, in double precision (a point moves by at most about 2^-42 of
///   the coordinates' magnitude);
/// - corners on or near the other's plane (touching CAD faces, coplanar faces): each corner's
///   side decided exactly (certified filter, then expansions on the world positions R v + t),
///   then the same construction, or for coplanar triangles their overlap polygon, its corners
///   and edge crossings found exactly and placed in double;
/// - what is left (near-parallel crossings, degenerate triangles, coordinates outside the
///   expansions' range): core's exact oracle, in rationals.
/// Then the contact point (the set's mean), normal and depth, merging and the cap. `answer` is
/// overwritten.
void contactsOfPairs(const ObbTree& a, const std::vector<std::int32_t>& positions_a,
                     const Eigen::Isometry3d& pose_a, const ObbTree& b,
                     const std::vector<std::int32_t>& positions_b, const Eigen::Isometry3d& pose_b,
                     const std::vector<TrianglePair>& pairs, const ContactOptions& options,
                     ContactAnswer& answer);

}  // namespace collido::obbtree
