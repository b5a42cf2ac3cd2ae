#pragma once

#include <Eigen/Core>

namespace collido::obbtree::detail {

/// Sign (-1, 0, +1) of the orientation of d relative to the plane through a, b, c; exact for any
/// finite double inputs. The sign convention is CGAL's: +1 when (a, b, c, d) is positively
/// oriented. Only the comparison of signs matters to the callers.
int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d);

/// Sign of the 2D orientation of (a, b, c) after dropping coordinate `drop` (0, 1 or 2); exact.
int orient2d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             int drop);

/// Whether a, b, c lie on one line (repeated points included); exact.
bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace collido::obbtree::detail
