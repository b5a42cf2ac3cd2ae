// What a tree-tree query must allow for when it maps B into A's frame in double precision, and
// the box and size of a node as a query sees them; shared by collide() and distance().
#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include <collido/obbtree/tree.h>

namespace collido::obbtree::detail {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kUnderflowGuard = 1e-290;

// The error of the computed relative map and what the box test must allow for.
struct QueryBounds {
  double linear = 0.0;  // mapped point error <= linear |v|_1 + constant
  double constant = 0.0;
  double axis_error = 0.0;  // SeparationTolerance::axis_error for every box pair

  // kUnderflowGuard: relative bounds fail where a product or sum is subnormal.
  double pointError(const Eigen::Vector3d& v) const {
    return linear * v.lpNorm<1>() + constant + kUnderflowGuard;
  }
};

// Derivation (2-norms are bounded by 1-norms throughout): with E = R_a^T R_a - I and
// d_a = axisDefect(R_a) >= |E|_2, R_a^-1 = (I + E)^-1 R_a^T, so |R_a^-1 - R_a^T|_2 <=
// k = d_a / (1 - d_a) (1 + d_a). The exact map's linear part R_a^-1 R_b then differs from
// R_a^T R_b by k (1 + d_b); rounding R_a^T R_b, t_b - t_a, R_a^T (t_b - t_a) and M v + s adds
// fewer than 12 ulps of |v|_1 and of |t_b - t_a|_1 (64 allowed). The box test's axis error adds
// both trees' axis defects and the deviation of the mapped axes from orthonormality (below
// 2 (d_a + d_b) + 2 linear). Poses far from rigid (defect >= 1e-3; the scene loader rejects them)
// get infinite bounds: nothing is culled and every triangle pair is decided exactly.
inline QueryBounds queryBounds(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
                               const Eigen::Isometry3d& pose_b) {
  QueryBounds bounds;
  const double defect_a = axisDefect(pose_a.linear());
  const double defect_b = axisDefect(pose_b.linear());
  const double shift = (pose_b.translation() - pose_a.translation()).lpNorm<1>();
  if (!(defect_a < 1e-3 && defect_b < 1e-3) || !std::isfinite(shift)) {
    const double infinite = std::numeric_limits<double>::infinity();
    return QueryBounds{infinite, infinite, infinite};
  }
  const double inverse_error = defect_a / (1.0 - defect_a) * (1.0 + defect_a);
  bounds.linear = inverse_error * (1.0 + defect_b) + 64.0 * kEps;
  bounds.constant = (inverse_error + 64.0 * kEps) * shift * (1.0 + kEps);
  bounds.axis_error = a.axisDefect() + b.axisDefect() + 2.0 * (defect_a + defect_b) +
                      2.0 * bounds.linear + 32.0 * kEps;
  return bounds;
}

// The relative map of B's model frame into A's as a query computes it (R_a^T R_b, R_a^T (t_b -
// t_a)), with its error bounds; `identity` when both have one pose: the map is then exactly the
// identity and mapped points carry no error.
struct RelativeMap {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  QueryBounds bounds;
  bool identity = false;

  Eigen::Vector3d operator()(const Eigen::Vector3d& v) const { return rotation * v + translation; }
};

inline RelativeMap relativeMap(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
                               const Eigen::Isometry3d& pose_b) {
  RelativeMap map;
  if (pose_a.matrix() == pose_b.matrix()) {
    map.bounds.axis_error = a.axisDefect() + b.axisDefect() + 32.0 * kEps;
    map.identity = true;
    return map;
  }
  // The transpose stands for the inverse; the bounds account for the rotations not being
  // exactly orthonormal.
  map.rotation = pose_a.linear().transpose() * pose_b.linear();
  map.translation = pose_a.linear().transpose() * (pose_b.translation() - pose_a.translation());
  map.bounds = queryBounds(a, pose_a, b, pose_b);
  return map;
}

// The box a query uses: a double box as stored, a float box decoded (expandBox).
inline const OrientedBox& boxOf(const Node& node) {
  return node.box;
}
inline OrientedBox boxOf(const CompactNode& node) {
  return expandBox(node.box);
}

inline double boxSize(const Node& node) {
  return node.box.half_extents.sum();
}
inline double boxSize(const CompactNode& node) {
  return static_cast<double>(halfExtent(node.box, 0)) + halfExtent(node.box, 1) +
         halfExtent(node.box, 2);
}

}  // namespace collido::obbtree::detail
