#include "scene_models.h"

#include "backend_run.h"

#include <chrono>

#include <collido/runner/heap_probe.h>

namespace collido::detail {
namespace {

using Clock = std::chrono::steady_clock;

// Memory: the backend's own figure, and the C heap's growth across build measured by the probe.
BuiltModel buildModel(BackendInstance& backend, const TriangleMesh& mesh, const BuildNeeds& needs,
                      ModelHandle state_of) {
  BuiltModel built;
  resetHeapPeak();
  const std::optional<HeapHookSample> hooks_before = heapHookSample();
  const std::optional<std::size_t> heap_before = heapBytesInUse();
  const Clock::time_point start = Clock::now();
  Result<ModelHandle> handle = backend.build(mesh.view(), needs, state_of);
  const Clock::time_point stop = Clock::now();
  const std::optional<std::size_t> heap_after = heapBytesInUse();
  const std::optional<HeapHookSample> hooks_after = heapHookSample();
  if (hooks_before && hooks_after) {
    built.heap_peak_bytes = hooks_after->peak_bytes > hooks_before->live_bytes
                                ? hooks_after->peak_bytes - hooks_before->live_bytes
                                : 0;
    built.heap_allocations = hooks_after->allocations - hooks_before->allocations;
  }
  if (!handle.ok()) {
    built.error = handle.status().toString();
    return built;
  }
  built.handle = handle.value();
  built.build_ms = std::chrono::duration<double, std::milli>(stop - start).count();
  if (heap_before && heap_after) {
    built.heap_bytes = *heap_after > *heap_before ? *heap_after - *heap_before : 0;
  }
  Result<std::uint64_t> bytes = backend.memory(built.handle);
  if (bytes.ok()) built.memory_bytes = static_cast<std::size_t>(bytes.value());
  return built;
}

template <typename T>
std::optional<T> sumIfBoth(const std::optional<T>& a, const std::optional<T>& b) {
  if (a && b) return *a + *b;
  return std::nullopt;
}

}  // namespace

SceneModels buildSceneModels(const Scene& scene, BackendInstance& backend,
                             const RunOptions& options, const std::string& label, int substeps) {
  SceneModels models;
  const Capabilities& caps = backend.capabilities();
  for (std::size_t index : scene.queriedObjects()) {
    BuildNeeds needs = scene.needsOf(index);
    needs.queries = askedKinds(needs.queries, substeps);
    needs.linked_queries = askedKinds(needs.linked_queries, substeps);
    if (options.build_every_need) needs.queries = needs.linked_queries = caps.queries;
    needs.queries = QueryKindSet(needs.queries.bits() & caps.queries.bits());
    needs.linked_queries = QueryKindSet(needs.linked_queries.bits() & caps.queries.bits());
    if (needs.queries.empty()) continue;
    const SceneObject& object = scene.objects[index];
    if (options.progress) options.progress(label + ": building " + object.name);
    for (std::size_t state = 0; state < object.stateCount(); ++state) {
      const TriangleMesh& mesh = *object.stateMesh(state);
      const TriangleMesh& first = *object.stateMesh(0);
      const BuiltModel* sibling = models[index].empty() ? nullptr : &models[index].front();
      const bool same_topology = sibling != nullptr && sibling->error.empty() &&
                                 mesh.vertices.cols() == first.vertices.cols() &&
                                 mesh.triangles.cols() == first.triangles.cols() &&
                                 mesh.triangles == first.triangles;
      models[index].push_back(
          buildModel(backend, mesh, needs, same_topology ? sibling->handle : ModelHandle{0}));
    }
  }
  return models;
}

void addBuildFigures(const Scene& scene, const SceneModels& models,
                     const std::vector<std::size_t>& objects, QueryMeasurement& m) {
  std::optional<std::size_t> heap_bytes = 0;
  std::optional<std::size_t> heap_peak_bytes = 0;
  std::optional<std::uint64_t> heap_allocations = 0;
  for (std::size_t index : objects) {
    m.triangles += scene.objects[index].mesh->triangleCount();
    const auto found = models.find(index);
    if (found == models.end()) continue;
    for (const BuiltModel& model : found->second) {
      m.build_ms += model.build_ms;
      m.memory_bytes += model.memory_bytes;
      heap_bytes = sumIfBoth(heap_bytes, model.heap_bytes);
      heap_peak_bytes = sumIfBoth(heap_peak_bytes, model.heap_peak_bytes);
      heap_allocations = sumIfBoth(heap_allocations, model.heap_allocations);
    }
  }
  m.heap_bytes = heap_bytes;
  m.heap_peak_bytes = heap_peak_bytes;
  m.heap_allocations = heap_allocations;
  m.heap_probe = heapProbeName();
}

std::string buildError(const SceneModels& models, const std::vector<std::size_t>& objects) {
  for (std::size_t i : objects) {
    const auto found = models.find(i);
    if (found == models.end()) continue;
    for (const BuiltModel& model : found->second) {
      if (!model.error.empty()) return model.error;
    }
  }
  return "";
}

void releaseModels(BackendInstance& backend, const SceneModels& models) {
  for (const auto& [index, states] : models) {
    for (const BuiltModel& model : states) {
      if (model.error.empty()) (void)backend.release(model.handle);
    }
  }
}

}  // namespace collido::detail
