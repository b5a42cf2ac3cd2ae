#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <collido/frep/solid.h>

namespace collido::frep {

/// How the octree search runs.
struct CollisionOptions {
  /// Cells are split until their longest side is at most this (model units): the seed's ε.
  double precision = 1e-3;
  /// Cells bounded before the search gives up (answer kUndecided with the work done).
  std::size_t max_cells = 20'000'000;
};

/// The answer of the guaranteed collision test.
enum class CollisionVerdict {
  kColliding,  ///< a witness point lies inside both solids (certified by interval bounds)
  kSeparated,  ///< every cell of the common bounds was proved outside one of the solids
  kTouching,   ///< no witness, but cells of side <= precision could not be proved outside:
               ///< the solids come within about the precision of each other (or touch)
  kUndecided,  ///< max_cells reached first
};

/// "colliding", "separated", "touching", "undecided".
const char* verdictName(CollisionVerdict verdict);

/// The verdict verdictName names, if any.
std::optional<CollisionVerdict> parseVerdict(const std::string& name);

/// Cells handled at one octree level (the common bounds are level 0).
struct CollisionLevel {
  std::size_t cells = 0;      ///< cells whose two ranges were computed
  std::size_t discarded = 0;  ///< proved outside one solid
  std::size_t split = 0;      ///< split into eight
};

/// The verdict with its evidence and the work it took.
struct CollisionResult {
  CollisionVerdict verdict = CollisionVerdict::kUndecided;
  /// For kColliding: a point with f1 >= 0 and f2 >= 0 proved by interval bounds at the point.
  Eigen::Vector3d witness = Eigen::Vector3d::Zero();
  /// For kTouching: the undecided cells of side <= precision (their union holds every point
  /// the solids may share), at most `kMaxKeptCells` of them kept; `undecided_cells` counts all.
  std::vector<Eigen::AlignedBox3d> touching_cells;
  std::size_t undecided_cells = 0;
  /// The common bounds searched (empty when the bounding boxes are disjoint).
  Eigen::AlignedBox3d domain;
  /// The deepest level the precision allows: the step count is at most 8^depth cells per level,
  /// whatever the solids' complexity.
  int max_depth = 0;
  std::size_t cells = 0;  ///< cells whose ranges were computed, all levels
  std::vector<CollisionLevel> levels;

  static constexpr std::size_t kMaxKeptCells = 64;
};

/// The seed method's collision of two FRep solids: the intersection of their bounding boxes is
/// subdivided as an octree, best cell first (largest upper bound of min(f1, f2)); a cell is
/// discarded when the interval of f1 or of f2 over it is negative, a cell whose centre has both
/// lower bounds >= 0 gives the witness, and cells stop splitting at the precision. An overlap
/// holding a ball of radius sqrt(3) * precision is never missed (some finest cell lies inside
/// it and its centre is a witness), unless max_cells ends the search first (kUndecided). Throws
/// std::invalid_argument when the common bounds are
/// unbounded or the precision is not positive.
CollisionResult collide(const Solid& a, const Solid& b, const CollisionOptions& options);

}  // namespace collido::frep
