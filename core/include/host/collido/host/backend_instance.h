#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include <collido/capabilities.h>
#include <collido/geometry.h>
#include <collido/host/plugin_library.h>
#include <collido/query.h>
#include <collido/status.h>

namespace collido {

/// A model handle issued by a backend instance; 0 is never valid.
using ModelHandle = std::uint64_t;

/// The host's side of one backend instance: calls through the plugin's C table, turns codes and
/// messages back into Status, and converts results. Not thread-safe (neither is an instance).
class BackendInstance {
 public:
  /// Creates an instance of `variant` with key/value options.
  static Result<std::unique_ptr<BackendInstance>> create(
      const std::shared_ptr<PluginLibrary>& library, const std::string& variant,
      const std::map<std::string, std::string>& options = {});

  BackendInstance(const BackendInstance&) = delete;
  BackendInstance& operator=(const BackendInstance&) = delete;
  ~BackendInstance();

  /// The variant name, e.g. "obbtree" or "fcl:obb".
  const std::string& name() const { return variant_; }
  const Capabilities& capabilities() const { return capabilities_; }
  const PluginLibrary& library() const { return *library_; }

  /// Builds a model; `state_of` (0: none) names another active state of the same object, built
  /// from the same triangle list, whose position-independent parts the backend may share.
  Result<ModelHandle> build(const MeshView& mesh, const BuildNeeds& needs,
                            ModelHandle state_of = 0);
  /// Builds a model of a NURBS surface (backends whose capabilities list kNurbsSurface).
  Result<ModelHandle> build(const SurfaceView& surface, const BuildNeeds& needs);
  /// Moves a deforming model's vertices; `counters` (optional) receives the work the backend
  /// reports (UpdateCounters::counted false when it does not count).
  Status update(ModelHandle model, const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                UpdateCounters* counters = nullptr);
  /// Fills `result` (cleared first; its vectors keep their capacity).
  Status query(ModelHandle a, const Pose& pose_a, ModelHandle b, const Pose& pose_b,
               const QueryRequest& request, QueryResult& result);
  Result<std::uint64_t> memory(ModelHandle model);
  Status release(ModelHandle model);

 private:
  Result<ModelHandle> buildShape(const CollidoShapeView& shape, const BuildNeeds& needs,
                                 ModelHandle state_of);

  BackendInstance(std::shared_ptr<PluginLibrary> library, std::string variant,
                  CollidoInstance* instance)
      : library_(std::move(library)), variant_(std::move(variant)), instance_(instance) {}

  std::shared_ptr<PluginLibrary> library_;
  std::string variant_;
  CollidoInstance* instance_ = nullptr;
  Capabilities capabilities_;
};

}  // namespace collido
