// Orientation and comparison signs of points known only to within an error radius, decided in
// double precision with a certified bound: a sign is returned only when no choice of the exact
// points within their radii, and no rounding of the evaluation, can change it. Otherwise the
// kernel records that it was unsure and the caller decides exactly.
//
// The bound for a determinant det(U) of computed difference vectors U (columns b - a, ...):
// the exact differences lie within D = e_a + e_b + eps|U| of the computed ones per coordinate
// (the radii, plus the rounding of the subtraction), and for any matrix E with |E| <= D
// entrywise, |det(U + E) - det(U)| <= perm(|U| + D) - perm(|U|), perm being the permanent (the
// determinant's expansion with every sign positive). The rounding of det(U) itself is below
// 5 u perm(|U|), and that of the two permanents and their difference below 8 eps perm(|U| + D);
// the certificate adds 16 eps perm(|U| + D) for all of these together.
#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Core>

#include <collido/obbtree/triangle_intersection.h>

namespace collido::obbtree::detail {

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
    const Eigen::Vector3d bu = au * (1.0 + kEps) + Eigen::Vector3d::Constant(a.error + b.error);
    const Eigen::Vector3d bv = av * (1.0 + kEps) + Eigen::Vector3d::Constant(a.error + c.error);
    const Eigen::Vector3d bw = aw * (1.0 + kEps) + Eigen::Vector3d::Constant(a.error + d.error);
    const double inflated = permanent3(bu, bv, bw);
    const double bound = (inflated - permanent3(au, av, aw)) + kSlack * inflated + kTiny;
    return certain(det, bound);
  }

  int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    const int i = drop == 0 ? 1 : 0;
    const int j = drop == 2 ? 1 : 2;
    const double ui = b.p[i] - a.p[i];
    const double uj = b.p[j] - a.p[j];
    const double vi = c.p[i] - a.p[i];
    const double vj = c.p[j] - a.p[j];
    const double det = ui * vj - uj * vi;
    const double eu = a.error + b.error;
    const double ev = a.error + c.error;
    const double bui = std::abs(ui) * (1.0 + kEps) + eu;
    const double buj = std::abs(uj) * (1.0 + kEps) + eu;
    const double bvi = std::abs(vi) * (1.0 + kEps) + ev;
    const double bvj = std::abs(vj) * (1.0 + kEps) + ev;
    const double inflated = bui * bvj + buj * bvi;
    const double plain = std::abs(ui) * std::abs(vj) + std::abs(uj) * std::abs(vi);
    const double bound = (inflated - plain) + kSlack * inflated + kTiny;
    return certain(det, bound);
  }

  bool collinear(const Point& a, const Point& b, const Point& c) {
    // Not collinear as soon as one projection certainly is not; collinearity itself (all three
    // zero) can never be certified by a filter.
    for (int drop = 0; drop < 3; ++drop) {
      const bool was_unsure = unsure_;
      unsure_ = false;
      const int s = orient2d(a, b, c, drop);
      const bool this_unsure = unsure_;
      unsure_ = was_unsure;
      if (!this_unsure && s != 0) return false;
    }
    unsure_ = true;
    return true;
  }

  int compare(const Point& a, const Point& b, int k) {
    const double x = a.p[k];
    const double y = b.p[k];
    const double radius = a.error + b.error;
    if (radius == 0.0) return (x > y) - (x < y);  // exact doubles compare exactly
    const double difference = x - y;              // rounded: within eps |x - y| of the truth
    if (std::abs(difference) > radius * (1.0 + 4.0 * kEps) + kTiny) return difference > 0 ? 1 : -1;
    unsure_ = true;
    return 0;
  }

 private:
  static constexpr double kEps = std::numeric_limits<double>::epsilon();
  static constexpr double kSlack = 16.0 * kEps;
  // Covers products that underflow into the subnormal range, where relative bounds fail.
  static constexpr double kTiny = 1e-290;

  static double permanent3(const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                           const Eigen::Vector3d& w) {
    return u.x() * (v.y() * w.z() + v.z() * w.y()) + u.y() * (v.x() * w.z() + v.z() * w.x()) +
           u.z() * (v.x() * w.y() + v.y() * w.x());
  }

  int certain(double value, double bound) {
    if (value > bound) return 1;
    if (value < -bound) return -1;
    unsure_ = true;
    return 0;
  }

  bool unsure_ = false;
};

}  // namespace collido::obbtree::detail
