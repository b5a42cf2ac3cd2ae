// Exact sums and products of doubles as floating-point expansions (Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997): a value held as the sum
// of non-overlapping doubles in increasing magnitude, built with error-free transformations
// (TwoSum, and TwoProduct through a fused multiply-add), so its sign is its largest component's.
// Every result is exact as long as no component overflows or underflows: callers keep their
// inputs in the range that inExpansionRange() admits, which keeps every product of up to six
// inputs, and every component derived from one, away from both. An expansion that would outgrow
// its fixed capacity (no heap: the exact fallback of the collision query must stay cheap) marks
// itself overflowed instead, and the caller decides the sign some other way.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace collido::obbtree::detail {

/// Whether x is zero, or finite with |x| < 2^150 and its lowest set bit >= 2^-170. A world
/// coordinate r v + t of such inputs has its bits between 2^-340 and 2^302, and an orientation
/// determinant of such coordinates (degree 3) between 2^-1020 and about 2^912: every component the
/// expansion algorithms derive is a multiple of the lowest (never subnormal) and far from
/// overflow, so no error term is ever lost.
inline bool inExpansionRange(double x) {
  if (x == 0.0) return true;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  if (biased == 0x7ff || biased == 0) return false;  // inf, NaN; subnormals reach below 2^-170
  const int exponent = biased - 1023;                // 2^exponent <= |x| < 2^(exponent + 1)
  if (exponent >= 150) return false;
  const std::uint64_t mantissa = (bits & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t{1} << 52);
  return exponent - 52 + __builtin_ctzll(mantissa) >= -170;  // the lowest set bit's weight
}

/// sum = fl(a + b) and error = a + b - sum exactly (Knuth's TwoSum).
inline double twoSum(double a, double b, double& error) {
  const double sum = a + b;
  const double b_virtual = sum - a;
  const double a_virtual = sum - b_virtual;
  error = (a - a_virtual) + (b - b_virtual);
  return sum;
}

/// product = fl(a b) and error = a b - product exactly, through a fused multiply-add (exact
/// unless the error term underflows, which inExpansionRange() inputs keep from happening).
inline double twoProduct(double a, double b, double& error) {
  const double product = a * b;
  error = std::fma(a, b, -product);
  return product;
}

/// TwoSum for |a| >= |b| (or a == 0): Dekker's FastTwoSum.
inline double fastTwoSum(double a, double b, double& error) {
  const double sum = a + b;
  error = b - (sum - a);
  return sum;
}

template <int Capacity>
class Expansion {
 public:
  Expansion() = default;
  explicit Expansion(double x) {
    if (x != 0.0) push(x);
  }
  // Only the components in use are copied.
  Expansion(const Expansion& other) { assign(other); }
  Expansion& operator=(const Expansion& other) {
    if (this != &other) assign(other);
    return *this;
  }
  ~Expansion() = default;

  /// a * b exactly, as at most two components.
  static Expansion product(double a, double b) {
    Expansion result;
    double error = 0.0;
    const double p = twoProduct(a, b, error);
    if (error != 0.0) result.push(error);
    if (p != 0.0) result.push(p);
    return result;
  }

  int size() const { return size_; }
  double component(int i) const { return components_[i]; }
  bool overflowed() const { return overflowed_; }
  /// The value to within a few units in the last place: the components summed from the
  /// smallest, so the largest absorbs the rest's rounded sum.
  double estimate() const {
    double sum = 0.0;
    for (int i = 0; i < size_; ++i)
      sum += components_[i];
    return sum;
  }
  /// -1, 0 or +1: the sign of the largest component, which outweighs all the others together.
  int sign() const {
    if (size_ == 0) return 0;
    const double top = components_[size_ - 1];
    return (top > 0.0) - (top < 0.0);
  }

  /// Adds b exactly: Shewchuk's GROW-EXPANSION with zero elimination, in place (step i has
  /// written at most i components when it reads component i).
  void add(double b) {
    double q = b;
    const int count = size_;
    size_ = 0;
    for (int i = 0; i < count; ++i) {
      double error = 0.0;
      q = twoSum(q, components_[i], error);
      if (error != 0.0) components_[size_++] = error;
    }
    if (q != 0.0) push(q);
  }

  /// Adds f exactly, subtracts it with `subtract`, and compresses the result (repeated sums
  /// leave many small components, and every later product pays for each).
  template <int OtherCapacity>
  void add(const Expansion<OtherCapacity>& f, bool subtract = false) {
    Expansion sum;
    sumInto(*this, f, subtract, sum);
    assign(sum);
    compress();
  }

  /// e + f (e - f with `subtract`) exactly, into `result`: Shewchuk's FAST-EXPANSION-SUM with
  /// zero elimination, a merge of the two by magnitude and one pass of TwoSums, so linear in
  /// their sizes (TwoSum throughout, where Shewchuk takes FastTwoSum for the first two). Both
  /// must be strongly non-overlapping, as every expansion built here is
  /// (round-to-nearest-even keeps the property through every operation of this class).
  template <int CapacityE, int CapacityF, int ResultCapacity>
  static void sumInto(const Expansion<CapacityE>& e, const Expansion<CapacityF>& f, bool subtract,
                      Expansion<ResultCapacity>& result) {
    result.size_ = 0;
    result.overflowed_ = e.overflowed_ || f.overflowed_;
    const double sign = subtract ? -1.0 : 1.0;
    const int e_size = e.size_;
    const int f_size = f.size_;
    if (f_size == 0) {
      for (int i = 0; i < e_size; ++i)
        result.push(e.components_[i]);
      return;
    }
    if (e_size == 0) {
      for (int i = 0; i < f_size; ++i)
        result.push(sign * f.components_[i]);
      return;
    }
    // Merge by magnitude, the smaller of the two next components first, and sum as it goes.
    int i = 0;
    int j = 0;
    double q = 0.0;
    bool started = false;
    while (i < e_size && j < f_size) {
      const double e_now = e.components_[i];
      const double f_now = sign * f.components_[j];
      double next = 0.0;
      if ((f_now > e_now) == (f_now > -e_now)) {
        next = e_now;
        ++i;
      } else {
        next = f_now;
        ++j;
      }
      if (!started) {
        q = next;
        started = true;
        continue;
      }
      double error = 0.0;
      q = twoSum(q, next, error);
      if (error != 0.0) result.push(error);
    }
    for (; i < e_size; ++i) {
      double error = 0.0;
      q = twoSum(q, e.components_[i], error);
      if (error != 0.0) result.push(error);
    }
    for (; j < f_size; ++j) {
      double error = 0.0;
      q = twoSum(q, sign * f.components_[j], error);
      if (error != 0.0) result.push(error);
    }
    if (q != 0.0) result.push(q);
  }

  /// this * b exactly: Shewchuk's SCALE-EXPANSION with zero elimination.
  template <int ResultCapacity>
  void scaleInto(double b, Expansion<ResultCapacity>& result) const {
    result.size_ = 0;
    result.overflowed_ = overflowed_;
    if (size_ == 0 || b == 0.0) return;
    double low = 0.0;
    double q = twoProduct(components_[0], b, low);
    if (low != 0.0) result.push(low);
    for (int i = 1; i < size_; ++i) {
      const double high = twoProduct(components_[i], b, low);
      double error = 0.0;
      const double sum = twoSum(q, low, error);
      if (error != 0.0) result.push(error);
      q = fastTwoSum(high, sum, error);
      if (error != 0.0) result.push(error);
    }
    if (q != 0.0) result.push(q);
  }

  /// this * f exactly, into `result`: the sum over the shorter factor's components of the
  /// longer scaled by each, summed by merges and compressed.
  template <int OtherCapacity, int ResultCapacity>
  void multiplyInto(const Expansion<OtherCapacity>& f, Expansion<ResultCapacity>& result) const {
    if (f.size() > size_) {
      f.multiplyInto(*this, result);
      return;
    }
    result.size_ = 0;
    result.overflowed_ = overflowed_ || f.overflowed();
    Expansion<2 * Capacity> scaled;
    Expansion<ResultCapacity> partial;
    for (int j = 0; j < f.size(); ++j) {
      scaleInto(f.component(j), scaled);
      sumInto(result, scaled, /*subtract=*/false, partial);
      result.assign(partial);
    }
    result.compress();
  }

 private:
  template <int>
  friend class Expansion;

  void assign(const Expansion& other) {
    size_ = other.size_;
    overflowed_ = other.overflowed_;
    for (int i = 0; i < size_; ++i)
      components_[i] = other.components_[i];
  }

  void push(double x) {
    if (size_ == Capacity) {
      overflowed_ = true;
      return;
    }
    components_[size_++] = x;
  }

  // Shewchuk's COMPRESS, in place: the same value in fewer non-overlapping components (repeated
  // growth leaves many small ones).
  void compress() {
    if (size_ < 2) return;
    int bottom = size_ - 1;
    double q = components_[bottom];
    for (int i = size_ - 2; i >= 0; --i) {
      double error = 0.0;
      const double sum = fastTwoSum(q, components_[i], error);
      if (error != 0.0) {
        components_[bottom--] = sum;
        q = error;
      } else {
        q = sum;
      }
    }
    int top = 0;
    for (int i = bottom + 1; i < size_; ++i) {
      double error = 0.0;
      const double sum = fastTwoSum(components_[i], q, error);
      if (error != 0.0) components_[top++] = error;
      q = sum;
    }
    components_[top++] = q;
    size_ = (q == 0.0 && top == 1) ? 0 : top;
  }

  double components_[Capacity];
  int size_ = 0;
  bool overflowed_ = false;
};

}  // namespace collido::obbtree::detail
