#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <collido/backend_options.h>
#include <collido/capabilities.h>
#include <collido/geometry.h>
#include <collido/query.h>
#include <collido/status.h>

namespace collido {

/// A structure a backend built for one shape. Owned by the plugin adapter, reached by handle.
class BackendModel {
 public:
  virtual ~BackendModel() = default;
  /// Bytes the built structure holds, as the backend counts them (mesh copies included).
  virtual std::size_t memoryBytes() const = 0;
};

/// What a plugin author implements. The adapter (plugin_export.h) has already checked handles,
/// sizes, finiteness, and that requests and needs are within capabilities() before any call here,
/// and it catches every exception, so implementations may throw on engine failures.
class Backend {
 public:
  virtual ~Backend() = default;

  /// What this instance can do; constant over the instance's life.
  virtual Capabilities capabilities() const = 0;

  /// Builds the structure for a mesh, computing only what `needs` asks for. The view is valid
  /// only during the call. `sibling` names another active state of the same object (same
  /// triangle list) whose position-independent parts the new model may share.
  virtual Result<std::unique_ptr<BackendModel>> build(const MeshView& mesh, const BuildNeeds& needs,
                                                      const StateSibling& sibling) = 0;

  /// Builds the structure for a NURBS surface, for backends whose capabilities list
  /// ShapeKind::kNurbsSurface; the adapter has checked sizes, finiteness and weights > 0 (the
  /// backend checks knot semantics it relies on). The default refuses.
  virtual Result<std::unique_ptr<BackendModel>> buildSurface(const SurfaceView& surface,
                                                             const BuildNeeds& needs);

  /// Replaces the vertex positions of a model built with needs.deforms (same count and order);
  /// a backend that counts its work (Capabilities::counts_update_work) fills `counters`.
  virtual Status update(BackendModel& model, const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                        UpdateCounters& counters) = 0;

  /// Answers one question about two posed models. `result` arrives cleared.
  virtual Status query(BackendModel& a, const Pose& pose_a, BackendModel& b, const Pose& pose_b,
                       const QueryRequest& request, QueryResult& result) = 0;
};

/// A backend that builds NURBS surfaces only (capabilities list ShapeKind::kNurbsSurface alone):
/// triangle meshes and updates are refused with the reason.
class SurfaceBackend : public Backend {
 public:
  Result<std::unique_ptr<BackendModel>> build(const MeshView& mesh, const BuildNeeds& needs,
                                              const StateSibling& sibling) override;
  Status update(BackendModel& model, const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                UpdateCounters& counters) override;
};

/// One variant a plugin offers ("fcl:obb").
struct VariantInfo {
  std::string name;     ///< unique among all plugins
  std::string summary;  ///< one line for people
};

/// Everything the adapter needs to export a plugin.
struct PluginInfo {
  std::string name;            ///< the plugin ("obbtree", "fcl")
  std::string version;         ///< of the plugin code
  std::string engine_name;     ///< of the engine it wraps
  std::string engine_version;  ///< as the engine reports it, or the package version
  std::vector<VariantInfo> variants;
  /// Creates an instance of `variant`; must consume every option it understands.
  Result<std::unique_ptr<Backend>> (*create)(const std::string& variant,
                                             BackendOptions& options) = nullptr;
};

}  // namespace collido
