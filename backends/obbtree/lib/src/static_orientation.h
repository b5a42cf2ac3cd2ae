// Orientation signs of exact double points by a static filter: the determinant evaluated in
// double and compared with a bound on every rounding in it, a multiple of the permanent (the
// determinant's expansion with every sign positive). Where the flush faces of CAD parts meet,
// every corner of a triangle pair is exact in one frame and most signs are asked of such points;
// the certified filter (filtered_predicates.h) carries error radii through every difference,
// which exact points do not need, and this bound costs a fraction of it.
//
// The bound, for differences U = (b - a, c - a, d - a) computed in double: each computed
// difference is within eps |U| of the exact one (a subtraction never underflows inexactly), so
// the exact determinant is within ((1 + eps)^3 - 1) perm(|U|) < 3.01 eps perm(|U|) of det(U);
// rounding det(U) adds at most 2.5 eps perm(|U|) and rounding the permanent less than 3 eps of
// it. 12 eps perm covers all of them. Products of three factors each at least 1e-100 stay normal,
// so the bound is relative; a smaller non-zero factor leaves the sign undecided (the exact
// predicate decides), as does an overflow (comparisons with NaN or infinity fail). A permanent
// exactly zero with no such factor makes every term of the determinant zero: the sign is zero.
// The 2D sign is the same with two columns.
#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Core>

#include <collido/oracle/orientation.h>

namespace collido::obbtree::detail {

/// The sign a static filter cannot settle.
inline constexpr int kUndecidedSign = 2;

namespace static_orientation {
inline constexpr double kBound = 12.0 * std::numeric_limits<double>::epsilon();
inline constexpr double kTiny = 1e-290;

inline bool tinyFactor(double x, double smallest) {
  const double magnitude = std::abs(x);
  return magnitude > 0.0 && magnitude < smallest;
}

inline int signWithin(double det, double permanent, bool tiny_factor) {
  if (tiny_factor) return kUndecidedSign;
  const double bound = kBound * permanent + kTiny;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  if (permanent == 0.0) return 0;
  return kUndecidedSign;
}
}  // namespace static_orientation

/// Sign of the orientation of exact points (a, b, c, d) in exact::orient3d's convention, or
/// kUndecidedSign.
inline int staticOrient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& c, const Eigen::Vector3d& d) {
  const Eigen::Vector3d u = b - a;
  const Eigen::Vector3d v = c - a;
  const Eigen::Vector3d w = d - a;
  const double det = u.x() * (v.y() * w.z() - v.z() * w.y()) -
                     u.y() * (v.x() * w.z() - v.z() * w.x()) +
                     u.z() * (v.x() * w.y() - v.y() * w.x());
  const Eigen::Vector3d au = u.cwiseAbs();
  const Eigen::Vector3d av = v.cwiseAbs();
  const Eigen::Vector3d aw = w.cwiseAbs();
  const double permanent = au.x() * (av.y() * aw.z() + av.z() * aw.y()) +
                           au.y() * (av.x() * aw.z() + av.z() * aw.x()) +
                           au.z() * (av.x() * aw.y() + av.y() * aw.x());
  bool tiny = false;
  for (int k = 0; k < 3; ++k) {
    tiny = tiny || static_orientation::tinyFactor(u[k], 1e-100) ||
           static_orientation::tinyFactor(v[k], 1e-100) ||
           static_orientation::tinyFactor(w[k], 1e-100);
  }
  return static_orientation::signWithin(det, permanent, tiny);
}

/// Sign of the 2D orientation of exact points (a, b, c) with coordinate `drop` dropped, in
/// exact::orient2d's convention and projection, or kUndecidedSign.
inline int staticOrient2d(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& c, int drop) {
  const int i = exact::keptFirst(drop);
  const int j = exact::keptSecond(drop);
  const double ui = b[i] - a[i];
  const double uj = b[j] - a[j];
  const double vi = c[i] - a[i];
  const double vj = c[j] - a[j];
  const double left = ui * vj;
  const double right = uj * vi;
  const bool tiny =
      static_orientation::tinyFactor(ui, 1e-150) || static_orientation::tinyFactor(uj, 1e-150) ||
      static_orientation::tinyFactor(vi, 1e-150) || static_orientation::tinyFactor(vj, 1e-150);
  return static_orientation::signWithin(left - right, std::abs(left) + std::abs(right), tiny);
}

}  // namespace collido::obbtree::detail
