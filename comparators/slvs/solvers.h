// The two solvers of the comparison on a PointChain: Collidoscope's least-change solver and
// SolveSpace's (libslvs, GPL-3: this directory builds only with COLLIDO_WITH_SLVS).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "point_chain.h"

namespace collido::slvs_comparison {

struct Solution {
  bool solved = false;
  std::string failure;                  ///< why not, when not solved
  std::vector<Eigen::Vector3d> points;  ///< the solved points
};

/// core/constraints: one body per point, its rotation fixed (3 parameters, as in libslvs).
Solution solveWithCollidoscope(const PointChain& chain);

/// libslvs: one 3D point entity per point, the plane a workplane, the target a fixed point.
Solution solveWithSlvs(const PointChain& chain);

}  // namespace collido::slvs_comparison
