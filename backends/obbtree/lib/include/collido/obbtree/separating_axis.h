#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace collido::obbtree {

/// Separating-axis test of two boxes, B given in A's box frame (Gottschalk, Lin & Manocha 1996;
/// Ericson, Real-Time Collision Detection, 4.4.1): `rotation` holds B's axes as columns in A's
/// box frame, `translation` B's centre there, `half_a`/`half_b` the half extents. Tests the 15
/// candidate axes (3 + 3 face normals, 9 edge cross products) and returns false only when one of
/// them separates the boxes with a margin larger than the rounding of the computation, so a box
/// pair that touches or nearly touches is reported as overlapping (conservative).
inline bool boxesOverlap(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
                         const Eigen::Vector3d& half_a, const Eigen::Vector3d& half_b) {
  // |R| plus a small term so that the cross-product axes of nearly parallel edges, whose
  // computed length is pure rounding, cannot produce a spurious separation.
  constexpr double kParallelGuard = 1e-12;
  // Relative margin on every comparison; well above the few ulps of rounding in these sums.
  constexpr double kMargin = 1e-12;
  const Eigen::Matrix3d& r = rotation;
  const Eigen::Vector3d& t = translation;
  const Eigen::Vector3d& a = half_a;
  const Eigen::Vector3d& b = half_b;
  const Eigen::Matrix3d abs_r = r.cwiseAbs().array() + kParallelGuard;
  const auto separated = [](double distance, double radius_sum) {
    return distance > radius_sum * (1.0 + kMargin) + kMargin * distance;
  };

  // A's face normals.
  for (int i = 0; i < 3; ++i) {
    if (separated(std::abs(t[i]), a[i] + abs_r.row(i).dot(b))) return false;
  }
  // B's face normals.
  for (int j = 0; j < 3; ++j) {
    if (separated(std::abs(t.dot(r.col(j))), abs_r.col(j).dot(a) + b[j])) return false;
  }
  // Edge cross products A_i x B_j.
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3;
    const int i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3;
      const int j2 = (j + 2) % 3;
      const double distance = std::abs(t[i2] * r(i1, j) - t[i1] * r(i2, j));
      const double radius =
          a[i1] * abs_r(i2, j) + a[i2] * abs_r(i1, j) + b[j1] * abs_r(i, j2) + b[j2] * abs_r(i, j1);
      if (separated(distance, radius)) return false;
    }
  }
  return true;
}

}  // namespace collido::obbtree
