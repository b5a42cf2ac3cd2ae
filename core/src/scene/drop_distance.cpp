#include "drop_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace collido::scene_reading {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Distance along `dir` from `origin` to triangle (a, b, c), or infinity (Moller-Trumbore).
double rayHit(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, const Eigen::Vector3d& a,
              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d e1 = b - a;
  const Eigen::Vector3d e2 = c - a;
  const Eigen::Vector3d p = dir.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-300) return kInfinity;  // the ray runs along the triangle's plane
  const double inv = 1.0 / det;
  const Eigen::Vector3d s = origin - a;
  const double u = s.dot(p) * inv;
  if (u < 0.0 || u > 1.0) return kInfinity;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = dir.dot(q) * inv;
  if (v < 0.0 || u + v > 1.0) return kInfinity;
  const double t = e2.dot(q) * inv;
  return t >= 0.0 ? t : kInfinity;
}

}  // namespace

std::vector<double> dropDistances(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& direction,
                                  const TriangleMesh& target, const Pose& target_pose) {
  std::vector<double> out(static_cast<std::size_t>(points.cols()), kInfinity);
  const Eigen::Index n = target.triangles.cols();
  if (n == 0 || points.cols() == 0) return out;
  // Coordinates across the direction: the grid lives in that plane.
  const Eigen::Vector3d u = direction.unitOrthogonal();
  const Eigen::Vector3d w = direction.cross(u);
  const Eigen::Matrix3Xd world = target_pose * target.vertices;
  Eigen::Array2d low = Eigen::Array2d::Constant(kInfinity);
  Eigen::Array2d high = -low;
  for (Eigen::Index v = 0; v < world.cols(); ++v) {
    const Eigen::Array2d q(world.col(v).dot(u), world.col(v).dot(w));
    low = low.min(q);
    high = high.max(q);
  }
  const int cells = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(n))));
  const Eigen::Array2d size = ((high - low) / cells).max(1e-300);
  const auto cellOf = [&](double x, double y) {
    const int i = std::clamp(static_cast<int>((x - low[0]) / size[0]), 0, cells - 1);
    const int j = std::clamp(static_cast<int>((y - low[1]) / size[1]), 0, cells - 1);
    return std::make_pair(i, j);
  };
  const auto slot = [cells](int i, int j) {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(cells) +
           static_cast<std::size_t>(j);
  };
  std::vector<std::vector<Eigen::Index>> grid(slot(cells, 0));
  for (Eigen::Index t = 0; t < n; ++t) {
    Eigen::Array2d lo = Eigen::Array2d::Constant(kInfinity);
    Eigen::Array2d hi = -lo;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = world.col(target.triangles(k, t));
      const Eigen::Array2d q(p.dot(u), p.dot(w));
      lo = lo.min(q);
      hi = hi.max(q);
    }
    const auto [i0, j0] = cellOf(lo[0], lo[1]);
    const auto [i1, j1] = cellOf(hi[0], hi[1]);
    for (int i = i0; i <= i1; ++i) {
      for (int j = j0; j <= j1; ++j)
        grid[slot(i, j)].push_back(t);
    }
  }
  for (Eigen::Index v = 0; v < points.cols(); ++v) {
    const Eigen::Vector3d origin = points.col(v);
    const double x = origin.dot(u);
    const double y = origin.dot(w);
    if (x < low[0] || x > high[0] || y < low[1] || y > high[1]) continue;
    const auto [i, j] = cellOf(x, y);
    double best = kInfinity;
    for (Eigen::Index t : grid[slot(i, j)]) {
      best = std::min(best,
                      rayHit(origin, direction, world.col(target.triangles(0, t)),
                             world.col(target.triangles(1, t)), world.col(target.triangles(2, t))));
    }
    out[static_cast<std::size_t>(v)] = best;
  }
  return out;
}

}  // namespace collido::scene_reading
