// The clearance constraints' distance query at scene load: the exact oracle's mesh distance,
// so that a scene is placed the same whichever backend the study then compares.
#pragma once

#include <memory>
#include <vector>

#include <collido/constraints/problem.h>
#include <collido/mesh/triangle_mesh.h>

namespace collido::scene_reading {

/// Separation of the bodies' meshes (one per body, in its model frame) by exactMeshDistance:
/// exact distances and closest points; an overlap is reported as distance 0 without a depth.
class OracleSeparation : public constraints::SeparationQuery {
 public:
  explicit OracleSeparation(std::vector<std::shared_ptr<const TriangleMesh>> meshes)
      : meshes_(std::move(meshes)) {}

  Result<constraints::Separation> measure(int body_a, const Pose& pose_a, int body_b,
                                          const Pose& pose_b) override;

 private:
  std::vector<std::shared_ptr<const TriangleMesh>> meshes_;
};

}  // namespace collido::scene_reading
