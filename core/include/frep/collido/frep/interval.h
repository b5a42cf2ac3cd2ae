#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/numeric/interval.hpp>

namespace collido::frep {

/// Boost.Interval's rounding policy for guaranteed enclosures without switching the FPU's
/// rounding mode: each operation is computed rounded to nearest (IEEE: within half an ulp for
/// + - * / sqrt) and the bound is stepped one ulp outward. Boost's own policies change the
/// rounding mode per operation, which GCC may reorder or fold across unless the whole program is
/// built with -frounding-math; this one is correct under any optimisation. Transcendental
/// functions step two ulps outward (glibc documents exp and cos within 1 ulp on x86-64).
struct OutwardRounding {
  using unprotected_rounding = OutwardRounding;

  static double down(double x) {
    return std::nextafter(x, -std::numeric_limits<double>::infinity());
  }
  static double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

  void init() {}
  template <class U>
  double conv_down(const U& v) {
    return static_cast<double>(v);
  }
  template <class U>
  double conv_up(const U& v) {
    return static_cast<double>(v);
  }
  double add_down(double x, double y) { return down(x + y); }
  double add_up(double x, double y) { return up(x + y); }
  double sub_down(double x, double y) { return down(x - y); }
  double sub_up(double x, double y) { return up(x - y); }
  double mul_down(double x, double y) { return exactOr(x * y, x, y, &OutwardRounding::down); }
  double mul_up(double x, double y) { return exactOr(x * y, x, y, &OutwardRounding::up); }
  double div_down(double x, double y) { return down(x / y); }
  double div_up(double x, double y) { return up(x / y); }
  double median(double x, double y) { return (x + y) / 2; }
  double sqrt_down(double x) { return std::max(0.0, down(std::sqrt(x))); }
  double sqrt_up(double x) { return up(std::sqrt(x)); }
  double int_down(double x) { return std::floor(x); }
  double int_up(double x) { return std::ceil(x); }
  double cos_down(double x) { return std::max(-1.0, down(down(std::cos(x)))); }
  double cos_up(double x) { return std::min(1.0, up(up(std::cos(x)))); }
  double exp_down(double x) { return std::max(0.0, down(down(std::exp(x)))); }
  double exp_up(double x) { return up(up(std::exp(x))); }

 private:
  // A product with a zero factor is exactly zero; stepping it would turn 0 * [a, b] into a
  // tiny non-zero interval and break sign tests on empty bumps.
  static double exactOr(double product, double x, double y, double (*step)(double)) {
    return (x == 0.0 || y == 0.0) ? 0.0 : step(product);
  }
};

/// A closed interval of doubles with guaranteed (outward-rounded) arithmetic: every operation's
/// result holds the exact result of the operation on any points of its operands.
using Interval = boost::numeric::interval<
    double, boost::numeric::interval_lib::policies<
                OutwardRounding, boost::numeric::interval_lib::checking_strict<double>>>;

/// The interval [x, x].
inline Interval point(double x) {
  return Interval(x);
}

/// The larger of two intervals pointwise (max over every choice of points).
inline Interval maxOf(const Interval& a, const Interval& b) {
  return boost::numeric::max(a, b);
}

/// The smaller of two intervals pointwise.
inline Interval minOf(const Interval& a, const Interval& b) {
  return boost::numeric::min(a, b);
}

/// x^p for x >= 0 and a real p > 0 (monotone increasing), from std::pow stepped two ulps
/// outward (glibc documents pow within 1 ulp). Negative parts of x are clamped to 0.
inline Interval powNonNegative(const Interval& x, double p) {
  const double lo = std::max(0.0, x.lower());
  const double hi = std::max(0.0, x.upper());
  const double lower =
      lo == 0.0 ? 0.0
                : std::max(0.0, OutwardRounding::down(OutwardRounding::down(std::pow(lo, p))));
  const double upper = hi == 0.0 ? 0.0 : OutwardRounding::up(OutwardRounding::up(std::pow(hi, p)));
  return Interval(lower, upper);
}

}  // namespace collido::frep
