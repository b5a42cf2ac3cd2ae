#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <collido/geometry.h>
#include <collido/status.h>

namespace collido::nurbs {

/// A rational B-spline surface (NURBS): degrees p and q, clamped knot vectors U and V, and a net
/// of count_u x count_v control points with weights, stored homogeneously as (w x, w y, w z, w)
/// with the u index outermost (control[i * count_v + j]).
struct NurbsSurface {
  int degree_u = 3;
  int degree_v = 3;
  int count_u = 0;
  int count_v = 0;
  std::vector<double>
      knots_u;  ///< count_u + degree_u + 1 values, first and last degree_u + 1 equal
  std::vector<double> knots_v;           ///< count_v + degree_v + 1 values, likewise
  std::vector<Eigen::Vector4d> control;  ///< homogeneous control points, weights > 0

  /// The control point (i, j) in Cartesian coordinates.
  Eigen::Vector3d point(int i, int j) const;
  double weight(int i, int j) const { return at(i, j).w(); }
  const Eigen::Vector4d& at(int i, int j) const {
    return control[static_cast<std::size_t>(i) * static_cast<std::size_t>(count_v) +
                   static_cast<std::size_t>(j)];
  }
  Eigen::Vector4d& at(int i, int j) {
    return control[static_cast<std::size_t>(i) * static_cast<std::size_t>(count_v) +
                   static_cast<std::size_t>(j)];
  }
  /// The Cartesian control points as columns: the surface lies in their convex hull (weights
  /// > 0), so a bound on the distance between two nets' hulls bounds the surfaces'.
  Eigen::Matrix3Xd controlPoints() const;
  /// The parameter domain: [knots_u[p], knots_u[count_u]] x [knots_v[q], knots_v[count_v]].
  double uMin() const { return knots_u[static_cast<std::size_t>(degree_u)]; }
  double uMax() const { return knots_u[static_cast<std::size_t>(count_u)]; }
  double vMin() const { return knots_v[static_cast<std::size_t>(degree_v)]; }
  double vMax() const { return knots_v[static_cast<std::size_t>(count_v)]; }

  /// A surface from Cartesian control points (u outermost) and weights.
  static NurbsSurface fromPoints(int degree_u, int degree_v, int count_u, int count_v,
                                 std::vector<double> knots_u, std::vector<double> knots_v,
                                 const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<double>& weights);
};

/// A view of the surface for a backend's build (borrowed: valid while `surface` is unchanged).
SurfaceView viewOf(const NurbsSurface& surface);

/// A copy of a viewed surface (not validated: call validate()).
NurbsSurface fromView(const SurfaceView& view);

/// The surface moved rigidly: a NURBS surface follows an affine map of its control points, the
/// weights unchanged, so the homogeneous net (w x, w) becomes (R w x + w t, w).
NurbsSurface transformed(const NurbsSurface& surface, const Pose& pose);

/// Checks what evaluation and splitting rely on; the error names the field and the problem
/// ("knots_u: not non-decreasing at index 5", "weight of control point (2, 3) is -1: must be
/// > 0 and finite").
Status validate(const NurbsSurface& surface);

/// The surface point and its first partial derivatives at (u, v).
struct SurfacePoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d du = Eigen::Vector3d::Zero();
  Eigen::Vector3d dv = Eigen::Vector3d::Zero();
};

/// The point at (u, v) (clamped to the domain), by the rational B-spline basis.
Eigen::Vector3d evaluate(const NurbsSurface& surface, double u, double v);

/// The point and its first derivatives at (u, v) (clamped to the domain): the homogeneous
/// derivatives by the derivatives of the basis, then the quotient rule.
SurfacePoint evaluateWithDerivatives(const NurbsSurface& surface, double u, double v);

/// Which parameter a knot operation works on.
enum class Direction { kU, kV };

/// The same surface with knot t inserted `times` more times in `direction` (Boehm's algorithm,
/// on the homogeneous net): the shape is unchanged; t must lie inside the domain, and the
/// resulting multiplicity must not exceed the degree.
NurbsSurface insertKnot(const NurbsSurface& surface, Direction direction, double t, int times);

/// The two pieces of the surface on either side of parameter t in `direction` (strictly inside
/// the domain): t is inserted up to multiplicity equal to the degree, then the net and knots are
/// cut there; each piece is a clamped NURBS surface on its half of the domain.
std::array<NurbsSurface, 2> splitAt(const NurbsSurface& surface, Direction direction, double t);

/// The four sub-patches at the domain's midpoints, in the order (low u, low v), (low u, high
/// v), (high u, low v), (high u, high v).
std::array<NurbsSurface, 4> splitInFour(const NurbsSurface& surface);

}  // namespace collido::nurbs
