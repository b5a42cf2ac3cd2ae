// The FRep base surfaces: quadrics, the torus, the superellipsoid, the block and the half-space,
// each with its double-precision value, its interval range and its exact superlevel bounds.
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <collido/frep/solid.h>

#include "bounds_util.h"

namespace collido::frep {
namespace {

using boost::numeric::square;
using detail::centredBox;
using detail::emptyBox;
using detail::infiniteBox;

using detail::require;

void requireFinite(const Eigen::Vector3d& v, const char* what) {
  require(v.allFinite(), std::string(what) + " must be finite");
}

Interval squared(double r) {
  return square(point(r));
}

Interval offsetSquared(const IntervalBox& box, const Eigen::Vector3d& centre, int axis) {
  return square(box.axis[axis] - centre[axis]);
}

class Sphere final : public Solid {
 public:
  Sphere(const Eigen::Vector3d& centre, double radius) : centre_(centre), radius_(radius) {}
  double value(const Eigen::Vector3d& p) const override {
    return radius_ * radius_ - (p - centre_).squaredNorm();
  }
  Interval range(const IntervalBox& box) const override {
    return squared(radius_) - (offsetSquared(box, centre_, 0) + offsetSquared(box, centre_, 1) +
                               offsetSquared(box, centre_, 2));
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    const double half = detail::sqrtOfDifferenceUp(squared(radius_), level);
    if (half < 0.0) return emptyBox();
    return centredBox(centre_, Eigen::Vector3d::Constant(half));
  }

 private:
  Eigen::Vector3d centre_;
  double radius_;
};

class Ellipsoid final : public Solid {
 public:
  Ellipsoid(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii)
      : centre_(centre), radii_(radii) {}
  double value(const Eigen::Vector3d& p) const override {
    return 1.0 - (p - centre_).cwiseQuotient(radii_).squaredNorm();
  }
  Interval range(const IntervalBox& box) const override {
    Interval sum(0.0);
    for (int i = 0; i < 3; ++i)
      sum += square((box.axis[i] - centre_[i]) / radii_[i]);
    return 1.0 - sum;
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    const double scale = detail::sqrtOfDifferenceUp(point(1.0), level);
    if (scale < 0.0) return emptyBox();
    return centredBox(centre_, radii_ * scale * (1.0 + 1e-15));
  }

 private:
  Eigen::Vector3d centre_;
  Eigen::Vector3d radii_;
};

class Cylinder final : public Solid {
 public:
  Cylinder(const Eigen::Vector3d& centre, double radius, double height)
      : centre_(centre), radius_(radius), half_height_(height / 2) {}
  double value(const Eigen::Vector3d& p) const override {
    const Eigen::Vector3d d = p - centre_;
    const double side = radius_ * radius_ - d.x() * d.x() - d.y() * d.y();
    if (std::isinf(half_height_)) return side;
    return std::min(side, half_height_ * half_height_ - d.z() * d.z());
  }
  Interval range(const IntervalBox& box) const override {
    const Interval side =
        squared(radius_) - offsetSquared(box, centre_, 0) - offsetSquared(box, centre_, 1);
    if (std::isinf(half_height_)) return side;
    return minOf(side, squared(half_height_) - offsetSquared(box, centre_, 2));
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    const double radial = detail::sqrtOfDifferenceUp(squared(radius_), level);
    if (radial < 0.0) return emptyBox();
    if (std::isinf(half_height_)) {
      Eigen::AlignedBox3d box = centredBox(centre_, Eigen::Vector3d::Constant(radial));
      box.min().z() = -std::numeric_limits<double>::infinity();
      box.max().z() = std::numeric_limits<double>::infinity();
      return box;
    }
    const double axial = detail::sqrtOfDifferenceUp(squared(half_height_), level);
    if (axial < 0.0) return emptyBox();
    return centredBox(centre_, Eigen::Vector3d(radial, radial, axial));
  }

 private:
  Eigen::Vector3d centre_;
  double radius_;
  double half_height_;
};

class Cone final : public Solid {
 public:
  Cone(const Eigen::Vector3d& apex, double half_angle, double height)
      : apex_(apex), slope_(std::tan(half_angle)), height_(height) {}
  double value(const Eigen::Vector3d& p) const override {
    const Eigen::Vector3d d = p - apex_;
    const double side = d.z() * d.z() * slope_ * slope_ - d.x() * d.x() - d.y() * d.y();
    if (std::isinf(height_)) return side;
    return std::min(side, d.z() * (height_ - d.z()));
  }
  Interval range(const IntervalBox& box) const override {
    const Interval z = box.axis[2] - apex_.z();
    const Interval side =
        square(z * slope_) - offsetSquared(box, apex_, 0) - offsetSquared(box, apex_, 1);
    if (std::isinf(height_)) return side;
    return minOf(side, z * (height_ - z));
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    if (std::isinf(height_)) return infiniteBox();
    // z (height - z) >= level bounds z; the side term then bounds x and y.
    const double root = detail::sqrtOfDifferenceUp(squared(height_), 4.0 * level);
    if (root < 0.0) return emptyBox();
    const Interval z_range = (height_ + Interval(-root, root)) / 2.0;
    const double z_low = z_range.lower();
    const double z_high = z_range.upper();
    const double z_far = std::max(std::abs(z_low), std::abs(z_high));
    const double r = detail::sqrtOfDifferenceUp(square(point(z_far) * slope_), level);
    if (r < 0.0) return emptyBox();
    return detail::padded(Eigen::AlignedBox3d(apex_ + Eigen::Vector3d(-r, -r, z_low),
                                              apex_ + Eigen::Vector3d(r, r, z_high)));
  }

 private:
  Eigen::Vector3d apex_;
  double slope_;
  double height_;
};

class Torus final : public Solid {
 public:
  Torus(const Eigen::Vector3d& centre, double major, double minor)
      : centre_(centre), major_(major), minor_(minor) {}
  double value(const Eigen::Vector3d& p) const override {
    const Eigen::Vector3d d = p - centre_;
    const double ring = std::hypot(d.x(), d.y()) - major_;
    return minor_ * minor_ - ring * ring - d.z() * d.z();
  }
  Interval range(const IntervalBox& box) const override {
    const Interval rho = sqrt(offsetSquared(box, centre_, 0) + offsetSquared(box, centre_, 1));
    return squared(minor_) - square(rho - major_) - offsetSquared(box, centre_, 2);
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    const double tube = detail::sqrtOfDifferenceUp(squared(minor_), level);
    if (tube < 0.0) return emptyBox();
    const double reach = (point(major_) + tube).upper();
    return centredBox(centre_, Eigen::Vector3d(reach, reach, tube));
  }

 private:
  Eigen::Vector3d centre_;
  double major_;
  double minor_;
};

class Quadric final : public Solid {
 public:
  Quadric(const Eigen::Matrix3d& a, const Eigen::Vector3d& b, double c) : a_(a), b_(b), c_(c) {}
  double value(const Eigen::Vector3d& p) const override { return p.dot(a_ * p) + b_.dot(p) + c_; }
  Interval range(const IntervalBox& box) const override {
    const auto& x = box.axis;
    Interval sum = point(c_);
    for (int i = 0; i < 3; ++i) {
      sum += a_(i, i) * square(x[i]) + b_[i] * x[i];
      for (int j = i + 1; j < 3; ++j)
        sum += (2.0 * a_(i, j)) * (x[i] * x[j]);
    }
    return sum;
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    // Bounded only for A negative definite. About a computed near-maximum t, with d = x - t:
    // f(x) = f(t) + g.d + d^T A d <= F + G |d| - mu |d|^2, where F and G bound f(t) and |grad f(t)|
    // (interval arithmetic) and mu <= the smallest eigenvalue of -A. So f(x) >= level needs
    // |d| <= (G + sqrt(G^2 + 4 mu (F - level))) / (2 mu): a ball, rounded outward throughout.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(-a_);
    // Weyl: the computed eigenvalues are within a few ulps of |A| of the exact ones; the margin
    // of 1e-10 |A| is far beyond that, and a matrix closer to singular counts as unbounded.
    const double norm = a_.norm();
    const double mu = eigen.eigenvalues().minCoeff() - 1e-10 * norm;
    if (!(mu > 0.0)) return infiniteBox();
    const Eigen::Vector3d top =
        0.5 * (eigen.eigenvectors() * eigen.eigenvalues().cwiseInverse().asDiagonal() *
               eigen.eigenvectors().transpose() * b_);
    const IntervalBox at = IntervalBox::ofPoint(top);
    const double f_top = range(at).upper();
    Interval g_squared(0.0);
    for (int i = 0; i < 3; ++i) {
      Interval g = point(b_[i]);
      for (int j = 0; j < 3; ++j)
        g += (2.0 * a_(i, j)) * at.axis[j];
      g_squared += square(g);
    }
    const Interval grad = sqrt(g_squared);
    const Interval excess = f_top - point(level);
    const Interval inner = square(grad) + 4.0 * point(mu) * excess;
    if (inner.upper() < 0.0) return emptyBox();
    const Interval reach =
        (grad + sqrt(Interval(std::max(0.0, inner.lower()), inner.upper()))) / (2.0 * point(mu));
    return centredBox(top, Eigen::Vector3d::Constant(reach.upper()));
  }

 private:
  Eigen::Matrix3d a_;
  Eigen::Vector3d b_;
  double c_;
};

class Superellipsoid final : public Solid {
 public:
  Superellipsoid(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii, double east_west,
                 double north_south)
      : centre_(centre), radii_(radii), e2_(east_west), e1_(north_south) {}
  double value(const Eigen::Vector3d& p) const override {
    const Eigen::Vector3d u = (p - centre_).cwiseQuotient(radii_).cwiseAbs();
    const double ring = std::pow(std::pow(u.x(), 2 / e2_) + std::pow(u.y(), 2 / e2_), e2_ / e1_);
    return 1.0 - (ring + std::pow(u.z(), 2 / e1_));
  }
  Interval range(const IntervalBox& box) const override {
    Interval u[3];
    for (int i = 0; i < 3; ++i)
      u[i] = abs((box.axis[i] - centre_[i]) / radii_[i]);
    const Interval ring =
        powNonNegative(powNonNegative(u[0], 2 / e2_) + powNonNegative(u[1], 2 / e2_), e2_ / e1_);
    return 1.0 - (ring + powNonNegative(u[2], 2 / e1_));
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    // The sum is homogeneous of degree 2/e1 and at most 1 only inside the radii's box.
    const double s = (1.0 - point(level)).upper();
    if (s < 0.0) return emptyBox();
    return centredBox(centre_, radii_ * powNonNegative(point(s), e1_ / 2).upper() * (1.0 + 1e-12));
  }

 private:
  Eigen::Vector3d centre_;
  Eigen::Vector3d radii_;
  double e2_;
  double e1_;
};

class Block final : public Solid {
 public:
  Block(const Eigen::Vector3d& centre, const Eigen::Vector3d& half)
      : centre_(centre), half_(half) {}
  double value(const Eigen::Vector3d& p) const override {
    const Eigen::Vector3d d = p - centre_;
    return (half_.cwiseProduct(half_) - d.cwiseProduct(d)).minCoeff();
  }
  Interval range(const IntervalBox& box) const override {
    Interval result = squared(half_[0]) - offsetSquared(box, centre_, 0);
    for (int i = 1; i < 3; ++i)
      result = minOf(result, squared(half_[i]) - offsetSquared(box, centre_, i));
    return result;
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    Eigen::Vector3d half;
    for (int i = 0; i < 3; ++i) {
      half[i] = detail::sqrtOfDifferenceUp(squared(half_[i]), level);
      if (half[i] < 0.0) return emptyBox();
    }
    return centredBox(centre_, half);
  }

 private:
  Eigen::Vector3d centre_;
  Eigen::Vector3d half_;
};

class HalfSpace final : public Solid {
 public:
  HalfSpace(const Eigen::Vector3d& normal, double offset) : normal_(normal), offset_(offset) {}
  double value(const Eigen::Vector3d& p) const override { return offset_ - normal_.dot(p); }
  Interval range(const IntervalBox& box) const override {
    return offset_ -
           (normal_[0] * box.axis[0] + normal_[1] * box.axis[1] + normal_[2] * box.axis[2]);
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    // Finite on one side only where the normal is exactly a coordinate axis.
    Eigen::AlignedBox3d box = infiniteBox();
    for (int i = 0; i < 3; ++i) {
      if (normal_[(i + 1) % 3] != 0.0 || normal_[(i + 2) % 3] != 0.0) continue;
      if (normal_[i] > 0)
        box.max()[i] = OutwardRounding::up(offset_ - level);
      else
        box.min()[i] = OutwardRounding::down(level - offset_);
    }
    return box;
  }

 private:
  Eigen::Vector3d normal_;
  double offset_;
};

}  // namespace

SolidPtr sphere(const Eigen::Vector3d& centre, double radius) {
  requireFinite(centre, "sphere centre");
  require(radius > 0 && std::isfinite(radius), "sphere radius must be finite and > 0");
  return std::make_shared<Sphere>(centre, radius);
}

SolidPtr ellipsoid(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii) {
  requireFinite(centre, "ellipsoid centre");
  require(radii.allFinite() && radii.minCoeff() > 0, "ellipsoid radii must be finite and > 0");
  return std::make_shared<Ellipsoid>(centre, radii);
}

SolidPtr cylinder(const Eigen::Vector3d& centre, double radius, double height) {
  requireFinite(centre, "cylinder centre");
  require(radius > 0 && std::isfinite(radius), "cylinder radius must be finite and > 0");
  require(height > 0 && !std::isnan(height), "cylinder height must be > 0 (or infinite)");
  return std::make_shared<Cylinder>(centre, radius, height);
}

SolidPtr cone(const Eigen::Vector3d& centre, double half_angle_radians, double height) {
  requireFinite(centre, "cone apex");
  require(half_angle_radians > 0 && half_angle_radians < M_PI / 2,
          "cone half angle must be in (0, 90) degrees");
  require(height > 0 && !std::isnan(height), "cone height must be > 0 (or infinite)");
  return std::make_shared<Cone>(centre, half_angle_radians, height);
}

SolidPtr torus(const Eigen::Vector3d& centre, double major_radius, double minor_radius) {
  requireFinite(centre, "torus centre");
  require(minor_radius > 0 && std::isfinite(minor_radius), "torus minor radius must be > 0");
  require(major_radius > 0 && std::isfinite(major_radius), "torus major radius must be > 0");
  return std::make_shared<Torus>(centre, major_radius, minor_radius);
}

SolidPtr quadric(const Eigen::Matrix3d& a, const Eigen::Vector3d& b, double c) {
  require(a.allFinite() && b.allFinite() && std::isfinite(c),
          "quadric coefficients must be finite");
  require((a - a.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * (1.0 + a.cwiseAbs().maxCoeff()),
          "quadric matrix must be symmetric");
  return std::make_shared<Quadric>(0.5 * (a + a.transpose()), b, c);
}

SolidPtr superellipsoid(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii,
                        double east_west, double north_south) {
  requireFinite(centre, "superellipsoid centre");
  require(radii.allFinite() && radii.minCoeff() > 0, "superellipsoid radii must be > 0");
  require(east_west > 0 && east_west <= 4 && north_south > 0 && north_south <= 4,
          "superellipsoid exponents must be in (0, 4]");
  return std::make_shared<Superellipsoid>(centre, radii, east_west, north_south);
}

SolidPtr block(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents) {
  requireFinite(centre, "block centre");
  require(half_extents.allFinite() && half_extents.minCoeff() > 0,
          "block half extents must be finite and > 0");
  return std::make_shared<Block>(centre, half_extents);
}

SolidPtr halfSpace(const Eigen::Vector3d& normal, double offset) {
  require(normal.allFinite() && normal.norm() > 0, "half-space normal must be finite and non-zero");
  require(std::isfinite(offset), "half-space offset must be finite");
  return std::make_shared<HalfSpace>(normal.normalized(), offset);
}

}  // namespace collido::frep
