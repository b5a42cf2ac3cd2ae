#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include <Eigen/Geometry>

namespace collido {

/// Uniform numbers from mt19937_64 with our own conversions: the standard distributions are
/// implementation-defined, and a seed must give the same scene poses and stress cases with any
/// standard library (callers draw in separate statements, as the order in which a call's
/// arguments are evaluated is unspecified).
class PortableRandom {
 public:
  explicit PortableRandom(std::uint64_t seed) : engine_(seed) {}

  /// The engine's next 64 raw bits.
  std::uint64_t bits() { return engine_(); }
  /// [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  /// A standard normal number (Box-Muller; one uniform pair per call).
  double normal() {
    const double u1 = 1.0 - uniform();  // (0, 1]: log stays finite
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
  }

  /// A uniform random unit vector.
  Eigen::Vector3d direction() {
    const double z = uniform(-1.0, 1.0);
    const double phi = uniform(0.0, 2.0 * M_PI);
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
  }

  /// A uniform random rotation (Shoemake, "Uniform random rotations", Graphics Gems III, 1992).
  Eigen::Matrix3d rotation() {
    const double u1 = uniform();
    const double u2 = uniform(0.0, 2.0 * M_PI);
    const double u3 = uniform(0.0, 2.0 * M_PI);
    const double a = std::sqrt(1.0 - u1);
    const double b = std::sqrt(u1);
    const Eigen::Quaterniond q(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2),
                               b * std::sin(u3));
    return q.normalized().toRotationMatrix();
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace collido
