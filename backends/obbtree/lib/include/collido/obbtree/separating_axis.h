#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace collido::obbtree {

/// What the separating-axis test must allow for when its inputs are computed, not exact.
struct SeparationTolerance {
  /// Bound on the error of every entry of `rotation` and, relative to its size, of
  /// `translation`, against the exact relative frame of two exactly orthonormal boxes (the
  /// frames' own deviation from orthonormality included). The default covers a few roundings of
  /// products of orthonormal matrices.
  double axis_error = 16.0 * std::numeric_limits<double>::epsilon();
  /// B's box is taken as enlarged by a ball of this radius (e.g. the error of mapping it).
  double inflation = 0.0;
};

/// One candidate axis of the separating-axis test, B given in A's box frame (see boxesOverlap):
/// the distance of the centres along it and the sum of the boxes' radii, both scaled by the axis's
/// length (1 for a face normal, the sine of the edges' angle for an edge cross product). The
/// boxes are apart along it by distance - radius_sum, divided by that length.
struct AxisProjection {
  double distance;
  double radius_sum;
};

/// A's face normal i. `abs_r`: the rotation's entries' magnitudes.
inline AxisProjection faceAxisOfA(const Eigen::Matrix3d& abs_r, const Eigen::Vector3d& t,
                                  const Eigen::Vector3d& a, const Eigen::Vector3d& b, int i) {
  return {std::abs(t[i]), a[i] + abs_r.row(i).dot(b)};
}

/// B's face normal j.
inline AxisProjection faceAxisOfB(const Eigen::Matrix3d& r, const Eigen::Matrix3d& abs_r,
                                  const Eigen::Vector3d& t, const Eigen::Vector3d& a,
                                  const Eigen::Vector3d& b, int j) {
  return {std::abs(t.dot(r.col(j))), abs_r.col(j).dot(a) + b[j]};
}

/// The cross product of A's edge direction i and B's edge direction j, unnormalised: its length
/// is sqrt(r(i1, j)^2 + r(i2, j)^2).
inline AxisProjection edgeAxis(const Eigen::Matrix3d& r, const Eigen::Matrix3d& abs_r,
                               const Eigen::Vector3d& t, const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b, int i, int j) {
  const int i1 = (i + 1) % 3;
  const int i2 = (i + 2) % 3;
  const int j1 = (j + 1) % 3;
  const int j2 = (j + 2) % 3;
  return {
      std::abs(t[i2] * r(i1, j) - t[i1] * r(i2, j)),
      a[i1] * abs_r(i2, j) + a[i2] * abs_r(i1, j) + b[j1] * abs_r(i, j2) + b[j2] * abs_r(i, j1)};
}

/// Separating-axis test of two boxes, B given in A's box frame (Gottschalk, Lin & Manocha 1996;
/// Ericson, Real-Time Collision Detection, 4.4.1): `rotation` holds B's axes as columns in A's
/// box frame, `translation` B's centre there, `half_a`/`half_b` the half extents. Tests the 15
/// candidate axes (3 + 3 face normals, 9 edge cross products) and returns false only when one of
/// them separates the boxes by more than the bound on the error of the computation:
///
///   slack = 5 axis_error (|t|_1 + |a|_1 + |b|_1) + inflation.
///
/// Why this bounds it: every projected distance and radius below is a sum of at most four
/// products of one entry of the rotation (error <= axis_error) with one of t, a or b (error <=
/// axis_error |t|); so each computed (distance - radius) is within 4 axis_error of the sum of
/// the magnitudes involved, and the rounding of these few sums is far below the fifth.
/// Inflation enlarges B along every axis by at most `inflation` (an edge cross-product axis has
/// length sin(angle) <= 1, and the unnormalised formulas scale B's radius by that length, so
/// adding the full inflation is conservative). For nearly parallel edges the cross-product axis
/// degenerates: distance and radii both go to zero, and the slack keeps the pair overlapping.
/// Touching boxes are therefore reported as overlapping.
/// With `face_axes_only`, only the 6 face normals are tried: a weaker test (it may call
/// separated boxes overlapping, never the reverse) that skips the 9 edge axes, which rarely
/// separate what the face normals do not; the descent uses it for inner node pairs, whose
/// children are tested anyway.
inline bool boxesOverlap(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
                         const Eigen::Vector3d& half_a, const Eigen::Vector3d& half_b,
                         const SeparationTolerance& tolerance = {}, bool face_axes_only = false) {
  const Eigen::Matrix3d& r = rotation;
  const Eigen::Vector3d& t = translation;
  const Eigen::Vector3d& a = half_a;
  const Eigen::Vector3d& b = half_b;
  const Eigen::Matrix3d abs_r = r.cwiseAbs();
  // 1e-290: relative bounds fail where products are subnormal.
  const double slack = 5.0 * tolerance.axis_error * (t.cwiseAbs().sum() + a.sum() + b.sum()) +
                       tolerance.inflation + 1e-290;
  const auto separated = [slack](const AxisProjection& axis) {
    return axis.distance > axis.radius_sum + slack;
  };

  for (int i = 0; i < 3; ++i) {
    if (separated(faceAxisOfA(abs_r, t, a, b, i))) return false;
  }
  for (int j = 0; j < 3; ++j) {
    if (separated(faceAxisOfB(r, abs_r, t, a, b, j))) return false;
  }
  if (face_axes_only) return true;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (separated(edgeAxis(r, abs_r, t, a, b, i, j))) return false;
    }
  }
  return true;
}

}  // namespace collido::obbtree
