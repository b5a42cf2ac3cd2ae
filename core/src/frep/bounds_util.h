// Box helpers for the FRep nodes' superlevel bounds: empty and infinite boxes, and the padding
// that keeps a bound computed in double precision conservative.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include <collido/frep/interval.h>

namespace collido::frep::detail {

/// The builders' parameter check: a bad parameter is std::invalid_argument with the reason.
inline void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument(message);
}

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

/// The box grown by a relative 1e-12 of its finite corners' magnitude (infinite sides stay):
/// covers the rounding of the few operations (a sum of a centre and a half extent, a product)
/// that produced its corners.
inline Eigen::AlignedBox3d padded(const Eigen::AlignedBox3d& box) {
  if (box.isEmpty()) return box;
  double magnitude = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (double v : {box.min()[i], box.max()[i]})
      if (std::isfinite(v)) magnitude = std::max(magnitude, std::abs(v));
  }
  const double pad = 1e-12 * magnitude + 1e-300;
  Eigen::AlignedBox3d out = box;
  for (int i = 0; i < 3; ++i) {
    if (std::isfinite(out.min()[i])) out.min()[i] -= pad;
    if (std::isfinite(out.max()[i])) out.max()[i] += pad;
  }
  return out;
}

/// sqrt(a - b) rounded upward; negative (an empty set) when a - b < 0 for sure.
inline double sqrtOfDifferenceUp(const Interval& a, double b) {
  const double k = (a - b).upper();
  if (k < 0.0) return -1.0;
  return OutwardRounding::up(std::sqrt(k));
}

/// a - b rounded downward: the level a child must reach, passed on conservatively.
inline double levelDown(double a, double b) {
  return OutwardRounding::down(a - b);
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
