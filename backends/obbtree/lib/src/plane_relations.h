// How two posed triangles lie against each other's planes, for contact sets: each corner's side
// of the other triangle's plane (PlaneSigns, which contact_signs.h's PlaneSides computes), and for
// coplanar triangles the combinatorics of their overlap, written once over a kernel of exactly
// placed world points (orient2d, compare).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace collido::obbtree::detail {

/// The exact signs of B's corners against A's plane ([0]) and of A's corners against B's plane
/// ([1]): the signs of n.(x - corner 0), with n the plane's normal by its winding.
using PlaneSigns = std::array<std::array<int, 3>, 2>;

/// The combinatorics of two exactly coplanar triangles' overlap: the corners of each inside or on
/// the other, the edges that cross properly (edge i runs from corner i to corner i + 1), and the
/// corners of B that equal one of A's (so a shared corner is listed once). `drop` is the
/// coordinate dropped to decide in 2D.
struct CoplanarOverlap {
  int drop = 2;
  std::array<bool, 3> a_in_b{};
  std::array<bool, 3> b_in_a{};
  std::array<std::array<bool, 3>, 3> crossing{};  ///< [edge of A][edge of B]
  std::array<int, 3> b_equals_a{-1, -1, -1};      ///< A's corner equal to B's corner k, or -1
  bool collinear_corners = false;  ///< every corner listed lies on one line (no crossing then)
};

/// The overlap of triangles a and b, known to be coplanar (every corner of B in A's plane:
/// PlaneSides::signs), or std::nullopt when either is degenerate. `normal_a` (A's normal in double)
/// picks the coordinate to drop.
template <typename Kernel, typename Point>
std::optional<CoplanarOverlap> coplanarOverlapWith(Kernel& kernel, const std::array<Point, 3>& pa,
                                                   const std::array<Point, 3>& pb,
                                                   const Eigen::Vector3d& normal_a) {
  CoplanarOverlap overlap;
  normal_a.cwiseAbs().maxCoeff(&overlap.drop);
  const int drop = overlap.drop;
  const int sign_a = kernel.orient2d(pa[0], pa[1], pa[2], drop);
  const int sign_b = kernel.orient2d(pb[0], pb[1], pb[2], drop);
  if (sign_a == 0 || sign_b == 0) return std::nullopt;
  // Each corner's side of each edge of the other triangle, once: the inside tests and the
  // crossing tests ask the same 18 orientations (the crossings each of them twice).
  std::array<std::array<int, 3>, 3> b_side{};  // [edge i of A][corner j of B]
  std::array<std::array<int, 3>, 3> a_side{};  // [edge j of B][corner i of A]
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      b_side[i][j] = kernel.orient2d(pa[i], pa[(i + 1) % 3], pb[j], drop);
      a_side[j][i] = kernel.orient2d(pb[j], pb[(j + 1) % 3], pa[i], drop);
    }
  }
  for (std::size_t k = 0; k < 3; ++k) {
    overlap.a_in_b[k] =
        a_side[0][k] * sign_b >= 0 && a_side[1][k] * sign_b >= 0 && a_side[2][k] * sign_b >= 0;
    overlap.b_in_a[k] =
        b_side[0][k] * sign_a >= 0 && b_side[1][k] * sign_a >= 0 && b_side[2][k] * sign_a >= 0;
    for (std::size_t i = 0; i < 3 && overlap.b_equals_a[k] < 0; ++i) {
      if (kernel.compare(pb[k], pa[i], 0) == 0 && kernel.compare(pb[k], pa[i], 1) == 0 &&
          kernel.compare(pb[k], pa[i], 2) == 0)
        overlap.b_equals_a[k] = static_cast<int>(i);
    }
  }
  bool any_crossing = false;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      const std::size_t i_next = (i + 1) % 3;
      const std::size_t j_next = (j + 1) % 3;
      overlap.crossing[i][j] =
          b_side[i][j] * b_side[i][j_next] < 0 && a_side[j][i] * a_side[j][i_next] < 0;
      any_crossing = any_crossing || overlap.crossing[i][j];
    }
  }
  if (!any_crossing) {
    // The corners listed (distinct points), all on one line: the overlap is a segment.
    std::vector<const Point*> listed;
    for (std::size_t k = 0; k < 3; ++k) {
      if (overlap.a_in_b[k]) listed.push_back(&pa[k]);
      if (overlap.b_in_a[k] && overlap.b_equals_a[k] < 0) listed.push_back(&pb[k]);
    }
    overlap.collinear_corners = true;
    for (std::size_t k = 2; k < listed.size() && overlap.collinear_corners; ++k)
      overlap.collinear_corners = kernel.orient2d(*listed[0], *listed[1], *listed[k], drop) == 0;
  }
  return overlap;
}

}  // namespace collido::obbtree::detail
