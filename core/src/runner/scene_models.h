#pragma once
// A backend's models of a scene's objects, built ahead of the queries: one per active state of
// each object, with what each build cost.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <collido/host/backend_instance.h>
#include <collido/runner/runner.h>

namespace collido::detail {

/// One built model and what building it cost.
struct BuiltModel {
  ModelHandle handle = 0;
  double build_ms = 0.0;
  std::size_t memory_bytes = 0;  ///< the backend's own figure
  std::optional<std::size_t> heap_bytes;
  std::optional<std::size_t> heap_peak_bytes;
  std::optional<std::uint64_t> heap_allocations;
  std::string error;  ///< non-empty when the build failed
};

/// Per object index, one model per active state (an object without states has one).
using SceneModels = std::map<std::size_t, std::vector<BuiltModel>>;

/// Builds every queried object of `scene` for what the scene needs of it (every query kind the
/// backend answers with RunOptions::build_every_need), restricted to what the backend answers;
/// objects it needs for nothing are left out. A state with the first state's triangle list is
/// built as its sibling, so the backend may share what does not depend on positions.
/// With `substeps` (BackendSpec::substeps), models are built for the kinds asked of the backend
/// (askedKinds).
SceneModels buildSceneModels(const Scene& scene, BackendInstance& backend,
                             const RunOptions& options, const std::string& label, int substeps);

/// Adds the build figures of `objects`' models (every state's) to `m`: build time, triangles,
/// the backend's bytes, and the heap figures where every model has them.
void addBuildFigures(const Scene& scene, const SceneModels& models,
                     const std::vector<std::size_t>& objects, QueryMeasurement& m);

/// The first build error among `objects`' models, or "".
std::string buildError(const SceneModels& models, const std::vector<std::size_t>& objects);

/// Releases every model that was built.
void releaseModels(BackendInstance& backend, const SceneModels& models);

}  // namespace collido::detail
