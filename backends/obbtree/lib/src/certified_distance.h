// The distance between two triangles in A's frame with a certified interval, computed in double
// precision: the caller decides what the interval cannot (contact, or a relative width too wide
// for the answer's guarantee) in exact arithmetic.
#pragma once

#include <array>

#include <Eigen/Core>

namespace collido::obbtree::detail {

/// A triangle pair's distance: the true distance lies in [lower, upper]; `value` is the computed
/// distance clamped into it, attained between point_a and point_b (as computed).
struct CertifiedDistance {
  double lower = 0.0;
  double upper = 0.0;
  double value = 0.0;
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
};

/// The distance between triangle `a` (exact corners) and the triangle whose exact corners lie
/// within `b_error` (Euclidean) of `b`'s. Candidates are the closest points of the nine edge
/// pairs and of each corner against the other triangle's face where its projection falls inside
/// (the minimum over them is the distance of triangles that do not meet); every candidate point
/// is a convex combination of its triangle's corners with coefficients checked in [0, 1], so its
/// rounding is bounded by the corners' magnitude. The upper bound is the best candidate's
/// length plus those roundings and b_error; the lower bound is the gap between the triangles'
/// projections on the best candidate's direction, with the rounding of each projection bounded
/// term by term, less b_error: at the true closest pair that gap is the distance, so the interval
/// is narrow unless the triangles nearly touch (lower = 0: contact cannot be ruled out) or the
/// direction is ill-determined (slivers, near-parallel edges).
CertifiedDistance certifiedTriangleDistance(const std::array<Eigen::Vector3d, 3>& a,
                                            const std::array<Eigen::Vector3d, 3>& b,
                                            double b_error);

/// A certified lower bound on the distance between triangle `a` (exact corners) and the triangle
/// whose exact corners lie within `b_error` of `b`'s: the gap between their projections on the
/// direction `n` (either way round, any length; n as given, not an exact one), with each
/// projection's rounding bounded term by term, less b_error; 0 when the projections overlap.
/// Projections are taken relative to `origin`, which should lie near both triangles (it keeps
/// the rounding small); any point gives a valid bound.
double separationAlong(const Eigen::Vector3d& n, const std::array<Eigen::Vector3d, 3>& a,
                       const std::array<Eigen::Vector3d, 3>& b, double b_error,
                       const Eigen::Vector3d& origin);

}  // namespace collido::obbtree::detail
