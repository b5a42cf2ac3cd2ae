// A double-double value with a certified radius: the exact value it stands for lies within
// `radius` of hi + lo, and a zero radius means it is exactly hi + lo. The middle stage of the
// exact fallback (exact_world.cpp): world coordinates and orientation determinants carried to
// about 106 bits, so a sign the first filter could not certify at 2^-53 is certified here unless
// the determinant is within about 2^-100 of its permanent; and a sign that is exactly zero is
// certified when every step that led to it was exact (a face of a mesh placed by the identity
// or a quarter turn). Branch-free and of fixed length: no zero elimination, no merges.
//
// Sums follow AccurateDWPlusDW of Joldes, Muller and Popescu (ACM TOMS 2017), with TwoSum
// wherever it uses FastTwoSum; products sum the four partial products of the two parts, each
// exactly by TwoProduct, by TwoSums. Every rounding error is either kept or recovered exactly,
// so the radius adds exactly what the result leaves out:
//  - a sum: the errors of its two rounded additions (about u^2 |x + y|, u = 2^-53);
//  - a product: the terms of about u^3 |x y| left out, plus 2^-1070 where a TwoProduct's error
//    term could underflow;
//  - input radii: |X Y - x y| <= |x| r_y + |y| r_x + r_x r_y, and radii add under sums.
// So a result is exact (radius 0) whenever it fits in a double-double and its inputs were exact.
// The radius itself is summed in double, positive terms only, and widened by (1 + 16u) for its
// own rounding. Callers keep inputs in inExpansionRange(), far from overflow.
#pragma once

#include <cmath>
#include <optional>

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
    TrackedDoubleDouble z;
    z.hi = twoProduct(a, b, z.lo);
    return z;
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

// Whether the TwoProduct p of a and b might have lost its error term to underflow.
inline bool mayUnderflow(double p, double a, double b) {
  return std::abs(p) < kProductSafe && a != 0.0 && b != 0.0;
}

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
  // The four partial products, each exactly as a TwoProduct (p + e) unless it could underflow.
  double e1 = 0.0;
  double e2 = 0.0;
  double e3 = 0.0;
  double e4 = 0.0;
  const double p1 = twoProduct(x.hi, y.hi, e1);  // ~ |x y|
  const double p2 = twoProduct(x.hi, y.lo, e2);  // ~ u |x y|
  const double p3 = twoProduct(x.lo, y.hi, e3);
  const double p4 = twoProduct(x.lo, y.lo, e4);  // ~ u^2 |x y|
  const bool underflow = mayUnderflow(p1, x.hi, y.hi) || mayUnderflow(p2, x.hi, y.lo) ||
                         mayUnderflow(p3, x.lo, y.hi) || mayUnderflow(p4, x.lo, y.lo);
  // The u-sized terms, then the u^2-sized ones, each sum by TwoSum; what is left out of the
  // result (d3 .. d6, e4 and dm, all u^3-sized) is summed into the radius.
  double d1 = 0.0;
  double d2 = 0.0;
  double d3 = 0.0;
  double d4 = 0.0;
  double d5 = 0.0;
  double d6 = 0.0;
  double dm = 0.0;
  const double s1 = twoSum(p2, p3, d1);
  const double middle = twoSum(s1, e1, d2);
  const double s3 = twoSum(d1, d2, d3);
  const double s4 = twoSum(s3, e2, d4);
  const double s5 = twoSum(s4, e3, d5);
  const double lower = twoSum(s5, p4, d6);
  const double m = twoSum(middle, lower, dm);
  TrackedDoubleDouble z;
  z.hi = twoSum(p1, m, z.lo);
  const double dropped = std::abs(d3) + std::abs(d4) + std::abs(d5) + std::abs(d6) + std::abs(e4) +
                         std::abs(dm) + (underflow ? kFloor : 0.0);
  // X Y - x y = x (Y - y) + y (X - x) + (X - x)(Y - y), with |x| <= (1 + u) |x.hi|.
  const double propagated = std::abs(x.hi) * (1.0 + kU) * y.radius +
                            std::abs(y.hi) * (1.0 + kU) * x.radius + x.radius * y.radius;
  const bool exact = x.radius == 0.0 && y.radius == 0.0 && dropped == 0.0;
  z.radius = radiusOf(propagated, dropped, exact);
  return z;
}

/// certainSign() as an optional: std::nullopt where it is kUnsure.
inline std::optional<int> certainSignOf(const TrackedDoubleDouble& value) {
  const int sign = value.certainSign();
  if (sign == TrackedDoubleDouble::kUnsure) return std::nullopt;
  return sign;
}

/// A point of world coordinates, each a tracked double-double.
struct TrackedPoint {
  TrackedDoubleDouble x[3];
};

}  // namespace collido::obbtree::detail
