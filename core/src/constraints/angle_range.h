#pragma once

namespace collido::constraints::detail {

inline constexpr double kPi = 3.14159265358979323846;

/// An angle constraint's target must lie this far inside (0, π): at the ends its cosine has no
/// slope, and 0, π and π/2 are the parallel and perpendicular kinds.
inline bool angleTargetInRange(double radians) {
  constexpr double kMargin = 1e-6;
  return radians > kMargin && radians < kPi - kMargin;
}

}  // namespace collido::constraints::detail
