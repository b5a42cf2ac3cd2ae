#pragma once

#include <optional>

#include <Eigen/Geometry>

namespace collido::obbtree {

/// A point known only to within `error` of the exact point it stands for, per coordinate
/// (|p[k] - exact[k]| <= error[k], all >= 0), e.g. a vertex brought into another frame by a
/// rounded transform; a zero error marks a coordinate that is exact.
struct UncertainPoint {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Vector3d error = Eigen::Vector3d::Zero();
};

/// exact::trianglesIntersect (collido/oracle/double_triangle_test.h) for the exact corners that the
/// uncertain ones stand for, decided in double precision with certified error bounds: the answer
/// when no exact corners within the radii, and no rounding, can change it; std::nullopt when one
/// might (touching, coplanar, degenerate or nearly so, with inexact corners), and the caller must
/// decide exactly (posedTrianglesIntersect). A sign whose inputs are all exact is decided by exact
/// predicates when the filter cannot, and a sign that is zero for every point within the radii
/// (e.g. exact equal coordinates) is certified as zero, so exactly placed contacts are answered
/// here too.
std::optional<bool> trianglesIntersectCertified(const UncertainPoint& p1, const UncertainPoint& q1,
                                                const UncertainPoint& r1, const UncertainPoint& p2,
                                                const UncertainPoint& q2, const UncertainPoint& r2);

/// Whether triangle (a[0], a[1], a[2]) placed by pose_a and triangle b placed by pose_b share a
/// point, with the world corners pose * v evaluated in exact rational arithmetic on the doubles
/// given (the rotation used as given, as the exact oracle does). Slow: the fallback of the
/// certified test.
bool posedTrianglesIntersect(const Eigen::Vector3d* a, const Eigen::Isometry3d& pose_a,
                             const Eigen::Vector3d* b, const Eigen::Isometry3d& pose_b);

}  // namespace collido::obbtree
