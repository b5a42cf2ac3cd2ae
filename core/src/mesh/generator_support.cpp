#include "generator_support.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace collido {
namespace generator_support {

std::string formatNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string formatCount(double value) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(0) << value;
  return text.str();
}

Status invalid(const std::string& message) {
  return {StatusCode::kInvalidArgument, message};
}

Status checkPositive(const std::string& where, const char* name, double value) {
  if (std::isfinite(value) && value > 0.0) return {};
  return invalid(where + name + " = " + formatNumber(value) + ", must be finite and > 0");
}

Status checkFinite(const std::string& where, const char* name, double value) {
  if (std::isfinite(value)) return {};
  return invalid(where + name + " = " + formatNumber(value) + ", must be finite");
}

Status checkAtLeast(const std::string& where, const char* name, int value, int minimum) {
  if (value >= minimum) return {};
  return invalid(where + name + " = " + std::to_string(value) +
                 ", must be >= " + std::to_string(minimum));
}

Status checkTriangleBudget(const std::string& where, const std::string& what, double triangles) {
  if (triangles <= kMaxTriangles) return {};
  return invalid(where + what + " gives " + formatCount(triangles) +
                 " triangles, must be <= " + formatCount(kMaxTriangles));
}

// P(phi, z) = (r cos phi, r sin phi, z) has dP/dphi x dP/dz = (r cos phi, r sin phi, 0), the
// outward normal, so the side quad (k, i) -> (k, i+1) -> (k+1, i+1) -> (k+1, i) is
// counter-clockwise seen from outside. The caps are fans from their centres: (centre, (k, i),
// (k, i+1)) faces +z, so the top cap uses it and the bottom cap the reverse.
void appendCylinder(double radius, double z0, double z1, int segments, int rings,
                    Eigen::Index& vertex_base, Eigen::Index& triangle_base, TriangleMesh& mesh) {
  const auto index = [&](int k, int i) {
    return static_cast<int>(vertex_base) + k * segments + (i % segments);
  };
  for (int k = 0; k <= rings; ++k) {
    // Pin the last ring to z1 exactly: it must not depend on the rounding of the step.
    const double z = k == rings ? z1 : z0 + (z1 - z0) * k / rings;
    for (int i = 0; i < segments; ++i) {
      const double phi = 2.0 * kPi * i / segments;
      mesh.vertices.col(index(k, i)) =
          Eigen::Vector3d(radius * std::cos(phi), radius * std::sin(phi), z);
    }
  }
  const int bottom = static_cast<int>(vertex_base) + (rings + 1) * segments;
  const int top = bottom + 1;
  mesh.vertices.col(bottom) = Eigen::Vector3d(0.0, 0.0, z0);
  mesh.vertices.col(top) = Eigen::Vector3d(0.0, 0.0, z1);
  Eigen::Index t = triangle_base;
  for (int k = 0; k < rings; ++k) {
    for (int i = 0; i < segments; ++i) {
      const int a = index(k, i);
      const int b = index(k, i + 1);
      const int c = index(k + 1, i + 1);
      const int d = index(k + 1, i);
      mesh.triangles.col(t++) = Eigen::Vector3i(a, b, c);
      mesh.triangles.col(t++) = Eigen::Vector3i(a, c, d);
    }
  }
  for (int i = 0; i < segments; ++i) {
    mesh.triangles.col(t++) = Eigen::Vector3i(bottom, index(0, i + 1), index(0, i));
    mesh.triangles.col(t++) = Eigen::Vector3i(top, index(rings, i), index(rings, i + 1));
  }
  vertex_base = top + 1;
  triangle_base = t;
}

}  // namespace generator_support

}  // namespace collido
