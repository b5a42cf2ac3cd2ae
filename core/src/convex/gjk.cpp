// GJK distance with a certified lower bound.
#include <collido/convex/gjk.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace collido::convex {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Vertex {
  Eigen::Vector3d w;  // a - b
  Eigen::Vector3d a;
  Eigen::Vector3d b;
};

struct Closest {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d on_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d on_b = Eigen::Vector3d::Zero();
  double distance = std::numeric_limits<double>::infinity();
  unsigned subset = 0;  // the face (bit mask) holding it
  int size = 0;
};

// The point of the simplex's hull closest to the origin: the best projection of the origin onto
// a face's affine hull that falls inside the face (all barycentric weights >= 0), over every
// face. A face whose Gram matrix is (nearly) singular is skipped: its own faces cover it.
Closest closestToOrigin(const std::array<Vertex, 4>& s, int n) {
  Closest best;
  for (unsigned subset = 1; subset < (1u << n); ++subset) {
    int index[4];
    int k = 0;
    for (int i = 0; i < n; ++i) {
      if ((subset & (1u << i)) != 0) index[k++] = i;
    }
    double lambda[4] = {1.0, 0.0, 0.0, 0.0};
    if (k > 1) {
      const Eigen::Vector3d& p0 = s[static_cast<std::size_t>(index[0])].w;
      // Fixed maximum sizes: no allocation in the inner loop.
      using Edges = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3>;
      using Gram = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
      using Weights = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
      Edges e(3, k - 1);
      for (int c = 1; c < k; ++c)
        e.col(c - 1) = s[static_cast<std::size_t>(index[c])].w - p0;
      const Gram gram = e.transpose() * e;
      const double scale = gram.diagonal().prod();
      const double det = gram.determinant();
      if (!(scale > 0.0) || !(det > 1e-24 * scale)) continue;
      const Weights mu = gram.ldlt().solve(-e.transpose() * p0);
      double sum = 0.0;
      bool inside = true;
      for (int c = 1; c < k; ++c) {
        lambda[c] = mu[c - 1];
        sum += mu[c - 1];
        inside = inside && mu[c - 1] >= 0.0;
      }
      lambda[0] = 1.0 - sum;
      if (!inside || lambda[0] < 0.0) continue;
    }
    Closest c;
    for (int i = 0; i < k; ++i) {
      const Vertex& v = s[static_cast<std::size_t>(index[i])];
      c.point += lambda[i] * v.w;
      c.on_a += lambda[i] * v.a;
      c.on_b += lambda[i] * v.b;
    }
    c.distance = c.point.norm();
    c.subset = subset;
    c.size = k;
    if (c.distance < best.distance || (c.distance == best.distance && k < best.size)) best = c;
  }
  return best;
}

}  // namespace

PointSetSupport::PointSetSupport(const Eigen::Matrix3Xd& points, const Eigen::Isometry3d& pose,
                                 double radius)
    : points_(points), pose_(pose), posed_(!pose.matrix().isIdentity(0.0)), radius_(radius) {}

Eigen::Vector3d PointSetSupport::support(const Eigen::Vector3d& direction) const {
  // The support of R P + t along d is R (support of P along R^T d) + t.
  const Eigen::Vector3d local =
      posed_ ? Eigen::Vector3d(pose_.linear().transpose() * direction) : direction;
  Eigen::Index best = 0;
  double best_dot = -std::numeric_limits<double>::infinity();
  for (Eigen::Index c = 0; c < points_.cols(); ++c) {
    const double dot = local.dot(points_.col(c));
    if (dot > best_dot) {
      best_dot = dot;
      best = c;
    }
  }
  return posed_ ? Eigen::Vector3d(pose_ * points_.col(best)) : Eigen::Vector3d(points_.col(best));
}

Eigen::Vector3d PointSetSupport::anyPoint() const {
  return posed_ ? Eigen::Vector3d(pose_ * points_.col(0)) : Eigen::Vector3d(points_.col(0));
}

GjkResult gjkDistance(const SupportFunction& a, const SupportFunction& b,
                      const GjkOptions& options) {
  GjkResult result;
  const double radii = a.radius() + b.radius();
  // The simplex starts as one point of A - B; each step adds the support point against the
  // current closest point and keeps the face holding the new closest point.
  std::array<Vertex, 4> simplex;
  simplex[0].a = a.anyPoint();
  simplex[0].b = b.anyPoint();
  simplex[0].w = simplex[0].a - simplex[0].b;
  int n = 1;
  Closest closest;
  closest.on_a = simplex[0].a;
  closest.on_b = simplex[0].b;
  closest.point = simplex[0].w;
  closest.distance = closest.point.norm();
  closest.subset = 1;
  closest.size = 1;
  double lower = 0.0;  // of the cores
  const auto finish = [&](GjkStatus status) {
    result.status = status;
    const double core = closest.distance;
    if (status == GjkStatus::kIntersecting || core <= radii) {
      result.intersecting = true;
      result.distance = 0.0;
      result.lower_bound = 0.0;
      result.point_a = closest.on_a;
      result.point_b = closest.on_a;
      if (status != GjkStatus::kIntersecting) result.status = GjkStatus::kIntersecting;
      return result;
    }
    const Eigen::Vector3d towards_b = -closest.point / core;
    result.point_a = closest.on_a + a.radius() * towards_b;
    result.point_b = closest.on_b - b.radius() * towards_b;
    result.distance = core - radii;
    result.lower_bound = std::max(0.0, std::min(lower, core) - radii);
    return result;
  };
  for (result.iterations = 0; result.iterations < options.max_iterations; ++result.iterations) {
    const double vn = closest.distance;
    if (!(vn > 0.0)) return finish(GjkStatus::kIntersecting);
    const Eigen::Vector3d& v = closest.point;
    Vertex w;
    w.a = a.support(-v);
    w.b = b.support(v);
    w.w = w.a - w.b;
    // min over A - B of v·x is v·w: the plane through w normal to v separates the origin from
    // A - B by (v·w) / |v|. Rounding: a few units of |v| (|a| + |b|) in the dot product.
    const double slack = 8.0 * kEps * (w.a.norm() + w.b.norm()) + 1e-300;
    const double gap = v.dot(w.w) / vn - slack;
    if (gap > 0.0) lower = std::max(lower, gap * (1.0 - 4.0 * kEps));
    const double tolerance = std::max(options.abs_tolerance, options.rel_tolerance * vn);
    if (vn - lower <= tolerance) return finish(GjkStatus::kConverged);
    bool seen = false;
    for (int i = 0; i < n; ++i)
      seen = seen || simplex[static_cast<std::size_t>(i)].w == w.w;
    if (seen) return finish(GjkStatus::kNoProgress);
    simplex[static_cast<std::size_t>(n++)] = w;
    const Closest next = closestToOrigin(simplex, n);
    if (next.distance >= vn) {
      // Rounding: the new simplex does not bring the origin closer; the bounds are final.
      return finish(GjkStatus::kNoProgress);
    }
    closest = next;
    // Keep only the face holding the closest point.
    std::array<Vertex, 4> kept;
    int m = 0;
    for (int i = 0; i < n; ++i) {
      if ((next.subset & (1u << i)) != 0)
        kept[static_cast<std::size_t>(m++)] = simplex[static_cast<std::size_t>(i)];
    }
    simplex = kept;
    n = m;
    if (n == 4 || closest.distance <= options.abs_tolerance * 1e-3) {
      closest.distance = 0.0;
      return finish(GjkStatus::kIntersecting);
    }
  }
  return finish(GjkStatus::kMaxIterations);
}

}  // namespace collido::convex
