// Orientation and comparison signs of points known only to within per-coordinate error radii,
// decided in double precision with a certified bound: a sign is returned only when no choice of
// the exact points within their radii, and no rounding of the evaluation, can change it. When
// the bound cannot decide and every input is exact (all radii zero), the exact predicate on the
// doubles decides; otherwise the kernel records that it was unsure and the caller decides the
// whole pair exactly.
//
// The bound for a determinant det(U) of computed difference vectors U (columns b - a, ...):
// the exact differences lie within D = e_a + e_b + eps|U| of the computed ones per coordinate
// (the radii, plus the rounding of the subtraction), and for any matrix E with |E| <= D
// entrywise, |det(U + E) - det(U)| <= perm(|U| + D) - perm(|U|), perm being the permanent (the
// determinant's expansion with every sign positive). The rounding of det(U) itself is below
// 5 u perm(|U|), and that of the two permanents and their difference below 8 eps perm(|U| + D);
// the certificate adds 16 eps perm(|U| + D) for all of these together. When perm(|U| + D) is
// exactly zero, every term of every admissible determinant has a zero factor: the sign is
// certainly zero (e.g. four points whose z coordinates are exact and equal).
#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Core>

#include <collido/obbtree/triangle_intersection.h>
#include <collido/oracle/orientation.h>

namespace collido::obbtree::detail {

/// The permanent of the 3x3 matrix with columns u, v, w (the determinant's expansion with every
/// sign positive) is w . permanentWeights(u, v): the weights depend on u and v alone, so a
/// triangle's can be computed once (prepared_triangle.h).
inline Eigen::Vector3d permanentWeights(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  return Eigen::Vector3d(u.y() * v.z() + u.z() * v.y(), u.x() * v.z() + u.z() * v.x(),
                         u.x() * v.y() + u.y() * v.x());
}

class FilteredKernel {
 public:
  using Point = UncertainPoint;

  bool unsure() const { return unsure_; }

  int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    const Eigen::Vector3d u = b.p - a.p;
    const Eigen::Vector3d v = c.p - a.p;
    const Eigen::Vector3d w = d.p - a.p;
    const double det = u.x() * (v.y() * w.z() - v.z() * w.y()) -
                       u.y() * (v.x() * w.z() - v.z() * w.x()) +
                       u.z() * (v.x() * w.y() - v.y() * w.x());
    const Eigen::Vector3d au = u.cwiseAbs();
    const Eigen::Vector3d av = v.cwiseAbs();
    const Eigen::Vector3d aw = w.cwiseAbs();
    const Eigen::Vector3d bu = au * (1.0 + kEps) + a.error + b.error;
    const Eigen::Vector3d bv = av * (1.0 + kEps) + a.error + c.error;
    const Eigen::Vector3d bw = aw * (1.0 + kEps) + a.error + d.error;
    const double inflated = permanent3(bu, bv, bw);
    const double bound = (inflated - permanent3(au, av, aw)) + kSlack * inflated;
    const bool zero_is_exact =
        inflated == 0.0 && !underflows(bu) && !underflows(bv) && !underflows(bw);
    const int sign = certain(det, bound, zero_is_exact);
    if (sign != kUnsure) return sign;
    if (exact(a) && exact(b) && exact(c) && exact(d)) return exact::orient3d(a.p, b.p, c.p, d.p);
    return unsureSign();
  }

  int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    const int i = exact::keptFirst(drop);  // the exact kernels' projection order (orientation.h)
    const int j = exact::keptSecond(drop);
    const double ui = b.p[i] - a.p[i];
    const double uj = b.p[j] - a.p[j];
    const double vi = c.p[i] - a.p[i];
    const double vj = c.p[j] - a.p[j];
    const double det = ui * vj - uj * vi;
    const double bui = std::abs(ui) * (1.0 + kEps) + a.error[i] + b.error[i];
    const double buj = std::abs(uj) * (1.0 + kEps) + a.error[j] + b.error[j];
    const double bvi = std::abs(vi) * (1.0 + kEps) + a.error[i] + c.error[i];
    const double bvj = std::abs(vj) * (1.0 + kEps) + a.error[j] + c.error[j];
    const double inflated = bui * bvj + buj * bvi;
    const double plain = std::abs(ui) * std::abs(vj) + std::abs(uj) * std::abs(vi);
    const double bound = (inflated - plain) + kSlack * inflated;
    const bool zero_is_exact = inflated == 0.0 && !underflows(Eigen::Vector3d(bui, buj, 0.0)) &&
                               !underflows(Eigen::Vector3d(bvi, bvj, 0.0));
    const int sign = certain(det, bound, zero_is_exact);
    if (sign != kUnsure) return sign;
    if (exact(a) && exact(b) && exact(c)) return exact::orient2d(a.p, b.p, c.p, drop);
    return unsureSign();
  }

  bool collinear(const Point& a, const Point& b, const Point& c) {
    // Collinear exactly when all three projections are; the first one certainly non-zero
    // settles it. Decided per projection, so an unsure projection leaves the kernel unsure.
    for (int drop = 0; drop < 3; ++drop) {
      if (orient2d(a, b, c, drop) != 0) return false;
    }
    return true;
  }

  int compare(const Point& a, const Point& b, int k) {
    const double x = a.p[k];
    const double y = b.p[k];
    const double radius = a.error[k] + b.error[k];
    if (radius == 0.0) return (x > y) - (x < y);  // exact doubles compare exactly
    const double difference = x - y;              // rounded: within eps |x - y| of the truth
    if (std::abs(difference) > radius * (1.0 + 4.0 * kEps) + kTiny) return difference > 0 ? 1 : -1;
    return unsureSign();
  }

 private:
  static constexpr double kEps = std::numeric_limits<double>::epsilon();
  static constexpr double kSlack = 16.0 * kEps;
  // Covers products that underflow into the subnormal range, where relative bounds fail.
  static constexpr double kTiny = 1e-290;
  static constexpr int kUnsure = 2;

  static bool exact(const Point& p) { return (p.error.array() == 0.0).all(); }

  static double permanent3(const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                           const Eigen::Vector3d& w) {
    return permanentWeights(u, v).dot(w);
  }

  // Whether a factor is so small that a product of three could underflow to zero: then a zero
  // permanent proves nothing.
  static bool underflows(const Eigen::Vector3d& factors) {
    return ((factors.array() > 0.0) && (factors.array() < 1e-100)).any();
  }

  // The sign when the bound settles it, else kUnsure. `zero_is_exact`: the inflated permanent is
  // exactly zero, so is every admissible determinant.
  static int certain(double value, double bound, bool zero_is_exact) {
    if (zero_is_exact) return 0;
    if (value > bound + kTiny) return 1;
    if (value < -(bound + kTiny)) return -1;
    return kUnsure;
  }

  int unsureSign() {
    unsure_ = true;
    return 0;
  }

  bool unsure_ = false;
};

}  // namespace collido::obbtree::detail
