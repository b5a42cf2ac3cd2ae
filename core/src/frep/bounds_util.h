// Box helpers for the FRep nodes' superlevel bounds: empty and infinite boxes, and the padding
// that keeps a bound computed in double precision conservative.
#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace collido::frep::detail {

inline Eigen::AlignedBox3d emptyBox() {
  return Eigen::AlignedBox3d();  // Eigen's default box is empty
}

inline Eigen::AlignedBox3d infiniteBox() {
  const double inf = std::numeric_limits<double>::infinity();
  return Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-inf), Eigen::Vector3d::Constant(inf));
}

inline bool isFinite(const Eigen::AlignedBox3d& box) {
  return box.min().allFinite() && box.max().allFinite();
}

/// The box grown by a relative 1e-12 of its magnitude: covers the rounding of the few
/// operations (a square root, a product) that produced its corners.
inline Eigen::AlignedBox3d padded(const Eigen::AlignedBox3d& box) {
  if (box.isEmpty() || !isFinite(box)) return box;
  const double magnitude =
      std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
  const double pad = 1e-12 * magnitude + 1e-300;
  return Eigen::AlignedBox3d(box.min().array() - pad, box.max().array() + pad);
}

/// A centred box of the given half extents, padded.
inline Eigen::AlignedBox3d centredBox(const Eigen::Vector3d& centre, const Eigen::Vector3d& half) {
  return padded(Eigen::AlignedBox3d(centre - half, centre + half));
}

/// Where a coordinate may be unbounded, an infinite half extent is kept infinite.
inline Eigen::AlignedBox3d unionOf(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  if (a.isEmpty()) return b;
  if (b.isEmpty()) return a;
  return a.merged(b);
}

inline Eigen::AlignedBox3d intersectionOf(const Eigen::AlignedBox3d& a,
                                          const Eigen::AlignedBox3d& b) {
  if (a.isEmpty() || b.isEmpty()) return emptyBox();
  Eigen::AlignedBox3d both = a.intersection(b);
  return both.isEmpty() ? emptyBox() : both;
}

}  // namespace collido::frep::detail
