#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include <collido/geometry.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/query.h>

namespace collido {

/// Which face a contact's normal is: A's (n_A) or B's reversed (-n_B).
enum class NormalOwner { kNone, kA, kB };

/// The normal and depth of a contact between two posed triangles (docs/DESIGN.md, "Contact
/// geometry"): each face normal with the depth along it, and the one chosen (the smaller depth,
/// A's on a tie). Computed in double from the posed corners; a degenerate triangle (zero
/// normal) gives no candidate.
struct ContactFrame {
  std::optional<Eigen::Vector3d> normal_a;  ///< n_A, unit
  std::optional<Eigen::Vector3d> normal_b;  ///< -n_B, unit (already reversed)
  double depth_a = 0.0;                     ///< how far B's corners reach behind A's plane
  double depth_b = 0.0;                     ///< how far A's corners reach behind B's plane
  NormalOwner owner = NormalOwner::kNone;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< the chosen one (UnitZ when kNone)
  double depth = 0.0;                                 ///< the depth along it
};

/// The contact frame of world triangles `a` (of A) and `b` (of B).
ContactFrame contactFrame(const std::array<Eigen::Vector3d, 3>& a,
                          const std::array<Eigen::Vector3d, 3>& b);

/// The reference contact of one intersecting triangle pair: the exact intersection set, its
/// mean point, and the contact frame.
struct PairContact {
  ExactIntersection set;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  ContactFrame frame;
};

/// The reference contact of triangle pair.a of A and pair.b of B, posed as in
/// exactIntersectingPairs; `set` is empty (and the point meaningless) when they do not meet.
PairContact exactPairContact(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                             const Pose& pose_b, const TrianglePair& pair);

/// The mean of an intersection set's points (zero for an empty set).
Eigen::Vector3d intersectionMean(const ExactIntersection& set);

/// The distance from `p` to an intersection set (a point, a segment or a planar convex
/// polygon), in double; infinity for an empty set.
double distanceToIntersection(const ExactIntersection& set, const Eigen::Vector3d& p);

/// Triangle t of `mesh` placed by `pose`, in double.
std::array<Eigen::Vector3d, 3> posedTriangle(const TriangleMesh& mesh, const Pose& pose,
                                             std::int32_t t);

/// The distance from `p` to a closed triangle, degenerate ones as the segment or point they are.
double distanceToTriangle(const Eigen::Vector3d& p, const std::array<Eigen::Vector3d, 3>& t);

/// How much of the intersection curve a set stands for: a segment's length, half a polygon's
/// perimeter (its extent along the contact region), 0 for a point.
double intersectionLength(const ExactIntersection& set);

}  // namespace collido
