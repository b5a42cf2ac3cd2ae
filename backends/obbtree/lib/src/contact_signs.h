// Exact signs for contact sets on posed triangle corners: the certified filter on the world
// doubles first (filtered_predicates.h), then the world positions as tracked double-doubles
// (tracked_world.h), and expansions on the exact world positions (R v + t, as the oracle places
// them) for the signs neither can settle (exact_world.h). Corners exactly on the
// other triangle's plane, and exactly coplanar faces, are what CAD contacts are made of: each
// such sign costs a double-double determinant, or where that is unsure one expansion
// determinant, instead of a rational construction.
#pragma once

#include <array>
#include <optional>

#include <Eigen/Geometry>

#include <collido/obbtree/triangle_intersection.h>

#include "exact_world.h"
#include "face_signs.h"
#include "plane_relations.h"
#include "stamped_table.h"
#include "tracked_world.h"

namespace collido::obbtree::detail {

/// A triangle corner: its world position in double with the radius of that rounding, the same
/// to about 106 bits (placed on first use), and the model point and pose that place it exactly.
struct PosedCorner {
  UncertainPoint world;
  mutable LazyWorldPoint tracked;
  PosedModelPoint exact;
};

/// The corner `model` placed by `pose` (which must outlive the corner); `pose_in_range`: the
/// pose's poseInExpansionRange().
PosedCorner posedCorner(const Eigen::Vector3d& model, const Eigen::Isometry3d& pose,
                        bool pose_in_range);

/// A triangle's three posed corners, each kept by whoever placed it (a query's corner cache).
using PosedTriangle = std::array<const PosedCorner*, 3>;

/// orient2d and compare on posed corners, exact. A sign neither the filter, the double-doubles
/// nor the expansions could give (a coordinate outside the expansions' safe range, an overflow) is
/// returned as 0 and marks the kernel failed: the caller then computes the set on rationals.
class ContactSignKernel {
 public:
  using Point = const PosedCorner*;

  bool failed() const { return failed_; }
  int orient2d(const Point& a, const Point& b, const Point& c, int drop);
  int compare(const Point& a, const Point& b, int k);

 private:
  int settle(const std::optional<int>& sign);
  bool failed_ = false;
};

/// The tracked planes of triangles and the tracked determinants of vertices against them, kept
/// for one query (stamped_table.h): near-coplanar faces meet in many triangle pairs, and each
/// pair asks its neighbours' planes about the same vertices, for a sign and for the value a
/// shallow crossing needs.
class TrackedDeterminants {
 public:
  /// Forgets the last query's.
  void begin() {
    planes_.begin();
    determinants_.begin();
  }
  /// The plane of triangle `position` of `object` (0: A, 1: B), if kept.
  const TrackedPlane* plane(int object, std::int32_t position) const {
    return planes_.find(planeKey(object, position));
  }
  void keepPlane(int object, std::int32_t position, const TrackedPlane& plane) {
    planes_.store(planeKey(object, position), plane);
  }
  /// The determinant of the other object's `vertex` against that plane, if kept.
  const TrackedDoubleDouble* determinant(int object, std::int32_t position,
                                         std::int32_t vertex) const {
    return determinants_.find(determinantKey(object, position, vertex));
  }
  void keepDeterminant(int object, std::int32_t position, std::int32_t vertex,
                       const TrackedDoubleDouble& value) {
    determinants_.store(determinantKey(object, position, vertex), value);
  }

 private:
  static std::uint64_t planeKey(int object, std::int32_t position) {
    return (static_cast<std::uint64_t>(object) << 63) | static_cast<std::uint32_t>(position);
  }
  static std::uint64_t determinantKey(int object, std::int32_t position, std::int32_t vertex) {
    return (static_cast<std::uint64_t>(object) << 63) |
           (static_cast<std::uint64_t>(static_cast<std::uint32_t>(position)) << 32) |
           static_cast<std::uint32_t>(vertex);
  }

  StampedTable<TrackedPlane> planes_;
  StampedTable<TrackedDoubleDouble> determinants_;
};

/// The sides of each of two triangles' corners of the other's plane, exact, and on request the
/// signed distances behind them (orientation determinants, n . (x - corner 0) with n by the
/// plane's winding, to within a few units in the last place). A corner the filter places costs
/// nothing; one it cannot is asked of the double-doubles, whose determinant also gives the value
/// a crossing point needs when its radius is below an ulp of it; the rest share one expansion
/// determinant, computed once: near-coplanar CAD faces ask both of most corners.
class PlaneSides {
 public:
  /// The corners must outlive this.
  PlaneSides(const PosedTriangle& a, const PosedTriangle& b) : a_(a), b_(b) {}

  /// What names the pair's corners and planes for the query's tables: each triangle's position
  /// in its tree's leaf order, its face and turn against it (ObbTree::faceOf, faceTurn), and its
  /// corners' vertices; [0] A's.
  struct FaceNames {
    std::int32_t triangle[2] = {};
    std::int32_t face[2] = {};
    int turn[2] = {1, 1};
    std::int32_t vertices[2][3] = {};
  };
  /// Reads the signs the filter cannot settle from `cache`, and keeps them there, by face and
  /// vertex (face_signs.h); `cache` and `names` must outlive this.
  void keepSignsIn(FaceSignCache& cache, const FaceNames& names) {
    cache_ = &cache;
    names_ = &names;
  }
  /// Reads the planes and determinants from `known`, and keeps those computed there, by the
  /// names given to keepSignsIn; `known` must outlive this.
  void keepDeterminantsIn(TrackedDeterminants& known) { known_ = &known; }

  /// [0]: B's corners against A's plane, [1]: A's against B's (as PlaneSigns); nullopt
  /// when a sign was out of the expansions' reach (the caller then decides on rationals).
  std::optional<PlaneSigns> signs();
  /// The signed distance of corner k of B from A's plane (side 0), or of A's corner k from B's
  /// plane (side 1); nullopt out of the expansions' reach.
  std::optional<double> value(std::size_t side, std::size_t k);

 private:
  struct Memo {
    bool computed = false;
    std::optional<double> value;
  };
  // The tracked determinant of corner k against side's plane; nullopt out of range.
  std::optional<TrackedDoubleDouble> tracked(std::size_t side, std::size_t k);

  PosedTriangle a_;
  PosedTriangle b_;
  FaceSignCache* cache_ = nullptr;
  const FaceNames* names_ = nullptr;
  TrackedDeterminants* known_ = nullptr;
  std::array<std::array<Memo, 3>, 2> values_{};
  std::array<std::optional<TrackedPlane>, 2> planes_{};
  std::array<std::array<std::optional<TrackedDoubleDouble>, 3>, 2> determinants_{};
};

}  // namespace collido::obbtree::detail
