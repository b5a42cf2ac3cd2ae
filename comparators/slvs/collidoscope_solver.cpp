#include <collido/constraints/solve.h>

#include "solvers.h"

namespace collido::slvs_comparison {

Solution solveWithCollidoscope(const PointChain& chain) {
  using namespace collido::constraints;
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Problem problem(1.0);
  const int n = static_cast<int>(chain.start.size());
  for (int i = 0; i < n; ++i) {
    Pose pose = Pose::Identity();
    pose.translation() = chain.start[i];
    const int body = problem.addBody("p" + std::to_string(i), pose, 1.0).value();
    (void)problem.fixRotation(body);  // a point: 3 parameters, as in libslvs
  }
  (void)problem.addPointOnPlane(
      "on floor", PointRef{0, origin},
      Plane{PointRef{kWorld, origin}, DirectionRef{kWorld, Eigen::Vector3d::UnitZ()}});
  for (int i = 0; i + 1 < n; ++i) {
    (void)problem.addDistance("link " + std::to_string(i), PointRef{i, origin},
                              PointRef{i + 1, origin}, Target{chain.lengths[i]});
  }
  (void)problem.addCoincident("drag", PointRef{n - 1, origin}, PointRef{kWorld, chain.target});
  Solution solution;
  const Result<SolveReport> report = solve(problem);
  if (!report.ok()) {
    solution.failure = report.status().message();
    return solution;
  }
  solution.solved = true;
  for (const Body& body : problem.bodies())
    solution.points.push_back(body.pose.translation());
  return solution;
}

}  // namespace collido::slvs_comparison
