// The three exact deciders behind posedTrianglesIntersect, apart for the tests that hold each to
// the other and to the oracle.
#pragma once

#include <array>
#include <optional>

#include <collido/obbtree/triangle_intersection.h>

#include "expansion.h"

namespace collido::obbtree::detail {

/// Whether every entry of the pose's 3x4 matrix is in inExpansionRange(): checked once per query.
bool poseInExpansionRange(const Eigen::Isometry3d& pose);

/// Whether the point's coordinates are all in inExpansionRange().
bool pointInExpansionRange(const Eigen::Vector3d& point);

/// Whether the three corners' coordinates are all in inExpansionRange().
bool cornersInExpansionRange(const Eigen::Vector3d* corners);

/// Whether a posed triangle's corners and its pose are all in inExpansionRange().
bool posedCornersInExpansionRange(const Eigen::Vector3d* corners, const Eigen::Isometry3d& pose);

/// posedTrianglesIntersect on floating-point expansions (expansion.h); std::nullopt when an
/// input is outside the expansions' safe range or an expansion outgrew its capacity.
std::optional<bool> posedTrianglesIntersectByExpansions(const Eigen::Vector3d* a,
                                                        const Eigen::Isometry3d& pose_a,
                                                        const Eigen::Vector3d* b,
                                                        const Eigen::Isometry3d& pose_b);

/// posedTrianglesIntersect on CGAL's lazy exact rationals: the last resort, any finite input.
bool posedTrianglesIntersectByRationals(const Eigen::Vector3d* a, const Eigen::Isometry3d& pose_a,
                                        const Eigen::Vector3d* b, const Eigen::Isometry3d& pose_b);

/// The expansions, and where they step aside the rationals: what follows a double-double stage
/// that was unsure.
bool posedTrianglesIntersectByExpansionsOrRationals(const Eigen::Vector3d* a,
                                                    const Eigen::Isometry3d& pose_a,
                                                    const Eigen::Vector3d* b,
                                                    const Eigen::Isometry3d& pose_b);

/// A world coordinate on expansions, r . v + t exactly: three products and a translation, at
/// most 7 components.
using ExactCoordinate = Expansion<8>;

/// A model point and the pose that places it: its world position is R v + t, exactly. Its exact
/// world coordinates are computed on the first sign that needs them and kept: a contact pair's
/// corners meet in several signs, and placing a point costs about as much as a sign's products.
class PosedModelPoint {
 public:
  PosedModelPoint() = default;
  PosedModelPoint(const Eigen::Vector3d& model, const Eigen::Isometry3d& pose)
      : model_(model), pose_(&pose) {}

  /// The exact world coordinates, or nullptr when the point or its pose lies outside
  /// inExpansionRange().
  const std::array<ExactCoordinate, 3>* placed() const;

 private:
  enum class Placement : unsigned char { kNotYet, kPlaced, kOutOfRange };
  Eigen::Vector3d model_ = Eigen::Vector3d::Zero();
  const Eigen::Isometry3d* pose_ = nullptr;
  mutable Placement placement_ = Placement::kNotYet;
  mutable std::array<ExactCoordinate, 3> world_;
};

/// Signs on the exact world positions of posed model points, on expansions: orient2d after
/// dropping coordinate `drop`, and the comparison of coordinate k. std::nullopt outside the
/// expansions' safe range or on overflow.
std::optional<int> posedOrient2dByExpansions(const PosedModelPoint& a, const PosedModelPoint& b,
                                             const PosedModelPoint& c, int drop);
std::optional<int> posedCompareByExpansions(const PosedModelPoint& a, const PosedModelPoint& b,
                                            int k);

/// The values, to within a few units in the last place, of an orientation determinant
/// ((b - a) x (c - a)) . (d - a) and of a 2D cross product (p1 - p0) x (q1 - q0) after dropping
/// coordinate `drop`, on the exact world positions: what a crossing point needs where the
/// doubles' own determinants are too ill conditioned. std::nullopt as above.
std::optional<double> posedOrient3dValueByExpansions(const PosedModelPoint& a,
                                                     const PosedModelPoint& b,
                                                     const PosedModelPoint& c,
                                                     const PosedModelPoint& d);
std::optional<double> posedCross2ValueByExpansions(const PosedModelPoint& p0,
                                                   const PosedModelPoint& p1,
                                                   const PosedModelPoint& q0,
                                                   const PosedModelPoint& q1, int drop);

}  // namespace collido::obbtree::detail
