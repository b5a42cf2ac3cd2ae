// slvs.h uses memset without including <string.h>.
#include <cstring>  // IWYU pragma: keep

#include <slvs.h>

#include "solvers.h"

namespace collido::slvs_comparison {

Solution solveWithSlvs(const PointChain& chain) {
  // Group 1 holds what is fixed (the plane, the target), group 2 what the solve may change.
  constexpr Slvs_hGroup kFixed = 1;
  constexpr Slvs_hGroup kFree = 2;
  std::vector<Slvs_Param> params;
  std::vector<Slvs_Entity> entities;
  std::vector<Slvs_Constraint> constraints;
  const auto param = [&](Slvs_hGroup group, double value) {
    const auto h = static_cast<Slvs_hParam>(params.size() + 1);
    params.push_back(Slvs_MakeParam(h, group, value));
    return h;
  };
  const auto point = [&](Slvs_hGroup group, const Eigen::Vector3d& at) {
    const Slvs_hParam x = param(group, at.x());
    const Slvs_hParam y = param(group, at.y());
    const Slvs_hParam z = param(group, at.z());
    const auto h = static_cast<Slvs_hEntity>(entities.size() + 1);
    entities.push_back(Slvs_MakePoint3d(h, group, x, y, z));
    return h;
  };
  const auto constraint = [&](int type, double value, Slvs_hEntity a, Slvs_hEntity b,
                              Slvs_hEntity entity) {
    const auto h = static_cast<Slvs_hConstraint>(constraints.size() + 1);
    constraints.push_back(
        Slvs_MakeConstraint(h, kFree, type, SLVS_FREE_IN_3D, value, a, b, entity, 0));
  };

  const Slvs_hEntity origin = point(kFixed, Eigen::Vector3d::Zero());
  const Slvs_hParam qw = param(kFixed, 1.0);  // the identity rotation: the plane's normal is +z
  const Slvs_hParam qx = param(kFixed, 0.0);
  const Slvs_hParam qy = param(kFixed, 0.0);
  const Slvs_hParam qz = param(kFixed, 0.0);
  const auto normal = static_cast<Slvs_hEntity>(entities.size() + 1);
  entities.push_back(Slvs_MakeNormal3d(normal, kFixed, qw, qx, qy, qz));
  const auto floor = static_cast<Slvs_hEntity>(entities.size() + 1);
  entities.push_back(Slvs_MakeWorkplane(floor, kFixed, origin, normal));
  const Slvs_hEntity target = point(kFixed, chain.target);

  std::vector<Slvs_hEntity> points;
  for (const Eigen::Vector3d& p : chain.start)
    points.push_back(point(kFree, p));
  constraint(SLVS_C_PT_IN_PLANE, 0.0, points.front(), 0, floor);
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    constraint(SLVS_C_PT_PT_DISTANCE, chain.lengths[i], points[i], points[i + 1], 0);
  constraint(SLVS_C_POINTS_COINCIDENT, 0.0, points.back(), target, 0);

  std::vector<Slvs_hConstraint> failed(constraints.size());
  Slvs_System system{};
  system.param = params.data();
  system.params = static_cast<int>(params.size());
  system.entity = entities.data();
  system.entities = static_cast<int>(entities.size());
  system.constraint = constraints.data();
  system.constraints = static_cast<int>(constraints.size());
  system.failed = failed.data();
  system.faileds = static_cast<int>(failed.size());
  system.calculateFaileds = 0;
  Slvs_Solve(&system, kFree);

  Solution solution;
  switch (system.result) {
    case SLVS_RESULT_OKAY:
      solution.solved = true;
      break;
    case SLVS_RESULT_INCONSISTENT:
      solution.failure = "inconsistent";
      break;
    case SLVS_RESULT_DIDNT_CONVERGE:
      solution.failure = "did not converge";
      break;
    case SLVS_RESULT_TOO_MANY_UNKNOWNS:
      solution.failure = "too many unknowns";
      break;
    default:
      solution.failure = "result " + std::to_string(system.result);
  }
  for (const Slvs_hEntity h : points) {
    const Slvs_Entity& e = entities[h - 1];
    solution.points.emplace_back(params[e.param[0] - 1].val, params[e.param[1] - 1].val,
                                 params[e.param[2] - 1].val);
  }
  return solution;
}

}  // namespace collido::slvs_comparison
