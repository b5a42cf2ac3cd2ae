#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include <collido/nurbs/nurbs_surface.h>

namespace collido::nurbs {

/// What bounds the distance between two sub-patches from below.
enum class PatchBound {
  kConvexHull,  ///< GJK between the control nets: the support function of the points is that of
                ///< their hull, which holds the patch (the seed method)
  kBox,         ///< the gap between the nets' axis-aligned boxes (the seed's baseline)
};

/// How the search runs and when it stops.
struct SurfaceDistanceOptions {
  /// Stop when upper - lower <= tolerance (absolute, in model units).
  double tolerance = 1e-6;
  PatchBound bound = PatchBound::kConvexHull;
  /// Refine the upper bound by a damped Gauss-Newton descent on the squared distance between
  /// surface points, from the closest child pair of the first pair opened at each level
  /// (besides the patch corners, which are free: a clamped patch passes through its corner
  /// control points). Off, the search is the seed method as published.
  bool refine = true;
  int max_depth = 40;                 ///< subdivision levels; a pair this deep is not split
  std::size_t max_pairs = 5'000'000;  ///< patch pairs bounded before the search gives up
};

/// Work at one subdivision level (the roots are level 0).
struct LevelWork {
  std::size_t pairs_bounded = 0;  ///< patch pairs whose lower bound was computed
  std::size_t pairs_opened = 0;   ///< pairs split into their 16 child pairs
  double seconds = 0.0;           ///< time spent bounding and splitting at this level
};

/// A certified minimum distance between two surfaces.
struct SurfaceDistance {
  /// The true minimum distance lies in [lower, upper] (both allow for the rounding of the
  /// subdivision and the evaluations: a relative 1e-14 of the model's size per level).
  double lower = 0.0;
  double upper = std::numeric_limits<double>::infinity();
  /// The closest pair found: parameters and points on A and B, |point_b - point_a| ~ upper.
  Eigen::Vector2d params_a = Eigen::Vector2d::Zero();
  Eigen::Vector2d params_b = Eigen::Vector2d::Zero();
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
  bool converged = false;  ///< upper - lower <= tolerance (else a limit stopped the search)
  std::size_t pairs_bounded = 0;
  std::size_t pairs_opened = 0;
  std::size_t surface_evaluations = 0;  ///< by the refinement
  std::vector<LevelWork> levels;
};

/// The seed method: the minimum distance between two NURBS surfaces by subdivision. The upper
/// bound starts at the closest pair of patch corners; sub-patch pairs are visited best-first by
/// their lower bound (PatchBound); a visited pair is split into 4 x 4 sub-patches by knot
/// insertion at its parameter midpoints (splitInFour), each child pair bounded, its corners
/// (and, with `refine`, a local descent) improving the upper bound; a pair whose lower bound
/// reaches the upper bound less the tolerance is dropped. Stops when upper - lower <= tolerance
/// (lower: the smallest bound still waiting). Both surfaces must pass validate().
SurfaceDistance minimumDistance(const NurbsSurface& a, const NurbsSurface& b,
                                const SurfaceDistanceOptions& options = {});

}  // namespace collido::nurbs
