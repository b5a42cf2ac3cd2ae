// A double-double value with a certified radius: the exact value it stands for lies within
// `radius` of hi + lo, and a zero radius means it is exactly hi + lo. The middle stage of the
// exact fallback (exact_world.cpp): world coordinates and orientation determinants carried to
// about 106 bits, so a sign the first filter could not certify at 2^-53 is certified here unless
// the determinant is within about 2^-100 of its permanent; and a sign that is exactly zero is
// certified when every step that led to it was exact (a face of a mesh placed by the identity
// or a quarter turn). Branch-free and of fixed length: no zero elimination, no merges.
//
// Sums follow AccurateDWPlusDW and products DWTimesDW3 (with a fused multiply-add) of Joldes,
// Muller and Popescu (ACM TOMS 2017), with TwoSum wherever they use FastTwoSum. The radii do not
// rest on that paper's bounds: each algorithm is a few error-free transformations (TwoSum,
// TwoProduct) and a few rounded operations, and the radius adds what the rounded ones can lose.
//  - A sum: the errors of its two rounded additions, recovered exactly by TwoSum.
//  - A product: u |r| for each rounded result r (u = 2^-53), plus 2^-1070 for subnormal results
//    and for a TwoProduct whose error term could underflow.
//  - Input radii: |X Y - x y| <= |x| r_y + |y| r_x + r_x r_y, and radii add under sums.
// The radius itself is summed in double, positive terms only, and widened by (1 + 16u) for its
// own rounding. Callers keep inputs in inExpansionRange(), far from overflow.
#pragma once

#include <cmath>

#include "expansion.h"

namespace collido::obbtree::detail {

struct TrackedDoubleDouble {
  double hi = 0.0;
  double lo = 0.0;
  double radius = 0.0;

  /// A double, exactly.
  static TrackedDoubleDouble exactly(double x) { return {x, 0.0, 0.0}; }

  /// a * b, exactly (inputs in inExpansionRange(): the error term cannot underflow).
  static TrackedDoubleDouble product(double a, double b) {
    const double p = a * b;
    return {p, std::fma(a, b, -p), 0.0};
  }

  static constexpr int kUnsure = 2;

  /// -1, 0 or +1 when every value within the radius has that sign (0 only for an exact zero);
  /// kUnsure otherwise.
  int certainSign() const {
    if (hi > radius) return 1;
    if (hi < -radius) return -1;
    if (radius == 0.0) return 0;  // exact, and hi == 0 means hi + lo == 0
    return kUnsure;
  }
};

namespace tracked_detail {
constexpr double kU = 0x1p-53;
constexpr double kWiden = 1.0 + 16.0 * kU;
// What subnormal results and the bound's own underflows can lose, all together.
constexpr double kFloor = 0x1p-1070;
// Below this, the error term of a TwoProduct may be subnormal and rounded.
constexpr double kProductSafe = 0x1p-960;

// `rounding` and the propagated radii, or exactly 0 when both are.
inline double radiusOf(double propagated, double rounding, bool exact) {
  return exact ? 0.0 : (propagated + rounding + kFloor) * kWiden;
}
}  // namespace tracked_detail

inline TrackedDoubleDouble operator+(const TrackedDoubleDouble& x, const TrackedDoubleDouble& y) {
  using namespace tracked_detail;
  double sl = 0.0;
  const double sh = twoSum(x.hi, y.hi, sl);
  double tl = 0.0;
  const double th = twoSum(x.lo, y.lo, tl);
  double c_error = 0.0;
  const double c = twoSum(sl, th, c_error);
  double vl = 0.0;
  const double vh = twoSum(sh, c, vl);
  double w_error = 0.0;
  const double w = twoSum(tl, vl, w_error);
  TrackedDoubleDouble z;
  z.hi = twoSum(vh, w, z.lo);
  // z.hi + z.lo = x + y - c_error - w_error exactly.
  const bool exact = x.radius == 0.0 && y.radius == 0.0 && c_error == 0.0 && w_error == 0.0;
  z.radius = radiusOf(x.radius + y.radius, std::abs(c_error) + std::abs(w_error), exact);
  return z;
}

inline TrackedDoubleDouble operator-(const TrackedDoubleDouble& x) {
  return {-x.hi, -x.lo, x.radius};
}

inline TrackedDoubleDouble operator-(const TrackedDoubleDouble& x, const TrackedDoubleDouble& y) {
  return x + (-y);
}

inline TrackedDoubleDouble operator*(const TrackedDoubleDouble& x, const TrackedDoubleDouble& y) {
  using namespace tracked_detail;
  const double ch = x.hi * y.hi;
  const double cl1 = std::fma(x.hi, y.hi, -ch);  // exact unless |ch| < kProductSafe
  const double tl0 = x.lo * y.lo;
  const double tl1 = std::fma(x.hi, y.lo, tl0);
  const double cl2 = std::fma(x.lo, y.hi, tl1);
  double cl3_error = 0.0;
  const double cl3 = twoSum(cl1, cl2, cl3_error);
  TrackedDoubleDouble z;
  z.hi = twoSum(ch, cl3, z.lo);
  // Exact when a factor is zero, or when both are doubles and TwoProduct was exact.
  const bool zero_factor = x.hi == 0.0 || y.hi == 0.0;
  const bool doubles = x.lo == 0.0 && y.lo == 0.0 && std::abs(ch) >= kProductSafe;
  const bool exact = x.radius == 0.0 && y.radius == 0.0 && (zero_factor || doubles);
  // X Y - x y = x (Y - y) + y (X - x) + (X - x)(Y - y), with |x| <= (1 + u) |x.hi|.
  const double propagated = std::abs(x.hi) * (1.0 + kU) * y.radius +
                            std::abs(y.hi) * (1.0 + kU) * x.radius + x.radius * y.radius;
  const double rounding = kU * (std::abs(tl0) + std::abs(tl1) + std::abs(cl2)) +
                          std::abs(cl3_error) + (std::abs(ch) < kProductSafe ? kFloor : 0.0);
  z.radius = radiusOf(propagated, rounding, exact);
  return z;
}

/// A point of world coordinates, each a tracked double-double.
struct TrackedPoint {
  TrackedDoubleDouble x[3];
};

}  // namespace collido::obbtree::detail
