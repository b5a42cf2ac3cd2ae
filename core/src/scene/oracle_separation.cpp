#include "oracle_separation.h"

#include <collido/oracle/distance_oracle.h>

namespace collido::scene_reading {

Result<constraints::Separation> OracleSeparation::measure(int body_a, const Pose& pose_a,
                                                          int body_b, const Pose& pose_b) {
  const MeshDistance found = exactMeshDistance(*meshes_[body_a], pose_a, *meshes_[body_b], pose_b);
  constraints::Separation separation;
  separation.distance = found.distance;
  separation.point_a = found.point_a;
  separation.point_b = found.point_b;
  return separation;
}

}  // namespace collido::scene_reading
