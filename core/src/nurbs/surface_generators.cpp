// Test and scene surfaces whose distances are known or hard: exact sphere zones and saddles,
// interleaved wavy sheets, twisted blades.
#include <collido/nurbs/surface_generators.h>

#include <cmath>
#include <vector>

#include <Eigen/Geometry>

namespace collido::nurbs {
namespace {

std::vector<double> clampedUniform(int count, int degree) {
  std::vector<double> knots;
  for (int k = 0; k <= degree; ++k)
    knots.push_back(0.0);
  const int interior = count - degree - 1;
  for (int k = 1; k <= interior; ++k)
    knots.push_back(static_cast<double>(k) / (interior + 1));
  for (int k = 0; k <= degree; ++k)
    knots.push_back(1.0);
  return knots;
}

}  // namespace

NurbsSurface sphereZone(const Eigen::Vector3d& centre, double radius, double from_degrees) {
  const double h = std::sqrt(0.5);
  // The profile in the (r, z) half plane: a 90-degree arc from -45 to 45 degrees of latitude.
  const Eigen::Vector2d profile[3] = {{h, -h}, {2 * h, 0.0}, {h, h}};
  const double profile_w[3] = {1.0, h, 1.0};
  const double a = from_degrees * M_PI / 180.0;
  const Eigen::Vector2d e1(std::cos(a), std::sin(a));
  const Eigen::Vector2d e2(-std::sin(a), std::cos(a));
  const Eigen::Vector2d around[3] = {e1, e1 + e2, e2};
  const double around_w[3] = {1.0, h, 1.0};
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector2d xy = profile[i].x() * around[j];
      points.push_back(centre + radius * Eigen::Vector3d(xy.x(), xy.y(), profile[i].y()));
      weights.push_back(profile_w[i] * around_w[j]);
    }
  }
  return NurbsSurface::fromPoints(2, 2, 3, 3, clampedUniform(3, 2), clampedUniform(3, 2), points,
                                  weights);
}

NurbsSurface saddle(const Eigen::Vector3d& centre, double half, double curvature) {
  // x^2 on [-half, half] as a quadratic Bezier: control values half^2, -half^2, half^2.
  const double square[3] = {half * half, -half * half, half * half};
  const double at[3] = {-half, 0.0, half};
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      points.push_back(centre + Eigen::Vector3d(at[i], at[j], curvature * (square[i] - square[j])));
  }
  return NurbsSurface::fromPoints(2, 2, 3, 3, clampedUniform(3, 2), clampedUniform(3, 2), points,
                                  std::vector<double>(9, 1.0));
}

NurbsSurface wavySheet(const Eigen::Vector3d& origin, double size, int count, double waves,
                       double amplitude, double phase) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < count; ++j) {
      const double x = size * i / (count - 1);
      const double y = size * j / (count - 1);
      const double z = amplitude * std::sin(2 * M_PI * waves * x / size + phase) *
                       std::cos(2 * M_PI * waves * y / size);
      points.push_back(origin + Eigen::Vector3d(x, y, z));
    }
  }
  return NurbsSurface::fromPoints(3, 3, count, count, clampedUniform(count, 3),
                                  clampedUniform(count, 3), points,
                                  std::vector<double>(points.size(), 1.0));
}

NurbsSurface sweptBlade(const Eigen::Vector3d& root, double chord, double camber, double span,
                        double twist_degrees) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 4; ++i) {
    const double along = static_cast<double>(i) / 3.0;  // root to tip
    const Eigen::AngleAxisd twist(twist_degrees * M_PI / 180.0 * along, Eigen::Vector3d::UnitZ());
    for (int j = 0; j < 4; ++j) {
      const double s = static_cast<double>(j) / 3.0;  // leading to trailing edge
      // A cambered line: x across the chord, y the camber's parabola.
      const Eigen::Vector3d section(chord * (s - 0.5), 4.0 * camber * s * (1.0 - s), 0.0);
      points.push_back(root + twist * section + Eigen::Vector3d(0, 0, span * along));
    }
  }
  return NurbsSurface::fromPoints(3, 3, 4, 4, clampedUniform(4, 3), clampedUniform(4, 3), points,
                                  std::vector<double>(16, 1.0));
}

}  // namespace collido::nurbs
