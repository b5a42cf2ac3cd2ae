#pragma once

#include <memory>
#include <vector>

#include <collido/constraints/problem.h>
#include <collido/host/backend_instance.h>
#include <collido/mesh/triangle_mesh.h>

namespace collido {

/// The clearance constraints' distance query through a backend: its kDistance answer (distance
/// and closest points). Overlaps get no depth: the mesh backends' contact depths are per
/// triangle pair, not how deep the shapes overlap (FCL's, measured on two spheres overlapping
/// by 0.3, steered the solve away), so shapes must start apart. One model per body.
class BackendSeparation : public constraints::SeparationQuery {
 public:
  /// Builds a model of each body's mesh (meshes[i] for body i; null for bodies no clearance
  /// names). The backend must answer kDistance.
  static Result<std::unique_ptr<BackendSeparation>> create(
      BackendInstance& backend, const std::vector<std::shared_ptr<const TriangleMesh>>& meshes);

  BackendSeparation(const BackendSeparation&) = delete;
  BackendSeparation& operator=(const BackendSeparation&) = delete;
  ~BackendSeparation() override;

  Result<constraints::Separation> measure(int body_a, const Pose& pose_a, int body_b,
                                          const Pose& pose_b) override;

 private:
  explicit BackendSeparation(BackendInstance& backend) : backend_(backend) {}

  BackendInstance& backend_;
  std::vector<ModelHandle> models_;  ///< per body, 0 where it has no mesh
  QueryResult result_;
};

}  // namespace collido
