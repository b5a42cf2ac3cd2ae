// A double-double value with a running error bound: the cheap first try of the double-double
// stage (tracked_world.h). TrackedDoubleDouble keeps every rounding error of its sums and
// products, which certifies exact zeros but costs four exact products and eight TwoSums a
// product. Where an input is already inexact (a world coordinate R v + t of a rotation that is
// not a quarter turn), no zero can be certified anyway, and a sign far from zero at 2^-106 (a
// solver's "upright" pose 1e-18 off the axis) needs only a bound: this type computes each sum and
// product as the "sloppy" double-double algorithms do (one exact product or sum, the lower parts
// in double) and carries, in double, a bound on the distance to the exact value and on the
// magnitudes involved (a running error analysis).
//
// The bounds, with u = 2^-53 and both parts normalised (|lo| <= u |hi|, which TwoSum leaves):
//  - a sum: TwoSum of the high parts, the low parts and that error added in double, then TwoSum:
//    the two roundings in double are at most u^2 (|x.hi| + |y.hi|) and 2 u^2 (1 + u) of the
//    same, so 3.01 u^2 (|x.hi| + |y.hi|);
//  - a product: the exact product of the high parts, x.hi y.lo + x.lo y.hi added to its error in
//    double, then TwoSum: x.lo y.lo (u^2 |x.hi y.hi|) is left out and four roundings add at most
//    u^2, u^2, 2 u^2 (1 + u) and 3 u^2 (1 + 2u) of |x.hi y.hi|: 8.1 u^2 |x.hi y.hi|;
//  - inputs off their exact values by e_x, e_y: |X Y - x y| <= |x| e_y + |Y| e_x, with `magnitude`
//    bounding |x|, |X|, |hi|; radii add under sums;
//  - a result or rounding below the normal range: at most 2^-1075 for each of the few roundings
//    of an operation, all within the 2^-1070 floor added to every operation's bound.
// Every bound and magnitude is summed in double from positive terms, at most five roundings,
// and widened by (1 + 16u). Contracting a product and a sum into a fused multiply-add only
// removes roundings, so the bounds hold on builds that do. Callers keep inputs in
// inExpansionRange(), far from overflow.
#pragma once

#include <cmath>

#include "expansion.h"
#include "tracked_double_double.h"

namespace collido::obbtree::detail {

/// hi + lo, normalised, within `error` of the exact value it stands for; `magnitude` bounds
/// |hi|, |hi + lo| and the exact value's absolute value.
struct BoundedDoubleDouble {
  double hi = 0.0;
  double lo = 0.0;
  double error = 0.0;
  double magnitude = 0.0;

  /// -1 or +1 when every value within the error has that sign; TrackedDoubleDouble::kUnsure
  /// otherwise (an exact zero included: the bound is never zero).
  int certainSign() const {
    // |lo| + error, rounded up: (1 + 4u) covers the rounding of the sum and of this product.
    const double reach = (std::abs(lo) + error) * (1.0 + 0x1p-51);
    if (hi > reach) return 1;
    if (hi < -reach) return -1;
    return TrackedDoubleDouble::kUnsure;
  }
};

namespace bounded_detail {
constexpr double kU = 0x1p-53;
constexpr double kWiden = 1.0 + 16.0 * kU;
constexpr double kFloor = 0x1p-1070;
constexpr double kSumError = 3.01 * kU * kU;
constexpr double kProductError = 8.1 * kU * kU;
}  // namespace bounded_detail

/// A tracked double-double as a bounded one: its radius is the error.
inline BoundedDoubleDouble boundedOf(const TrackedDoubleDouble& x) {
  using namespace bounded_detail;
  return {x.hi, x.lo, x.radius, (std::abs(x.hi) + std::abs(x.lo) + x.radius + kFloor) * kWiden};
}

inline BoundedDoubleDouble operator+(const BoundedDoubleDouble& x, const BoundedDoubleDouble& y) {
  using namespace bounded_detail;
  double high_error = 0.0;
  const double high = twoSum(x.hi, y.hi, high_error);
  const double low = high_error + (x.lo + y.lo);
  BoundedDoubleDouble z;
  z.hi = twoSum(high, low, z.lo);
  const double magnitudes = x.magnitude + y.magnitude;
  z.magnitude = (magnitudes + kFloor) * kWiden;
  z.error = (x.error + y.error + kSumError * magnitudes + kFloor) * kWiden;
  return z;
}

inline BoundedDoubleDouble operator-(const BoundedDoubleDouble& x) {
  return {-x.hi, -x.lo, x.error, x.magnitude};
}

inline BoundedDoubleDouble operator-(const BoundedDoubleDouble& x, const BoundedDoubleDouble& y) {
  return x + (-y);
}

inline BoundedDoubleDouble operator*(const BoundedDoubleDouble& x, const BoundedDoubleDouble& y) {
  using namespace bounded_detail;
  double high_error = 0.0;
  const double high = twoProduct(x.hi, y.hi, high_error);
  const double low = high_error + (x.hi * y.lo + x.lo * y.hi);
  BoundedDoubleDouble z;
  z.hi = twoSum(high, low, z.lo);
  const double magnitudes = x.magnitude * y.magnitude;
  z.magnitude = (magnitudes + kFloor) * kWiden;
  z.error = (x.magnitude * y.error + y.magnitude * x.error + kProductError * magnitudes + kFloor) *
            kWiden;
  return z;
}

}  // namespace collido::obbtree::detail
