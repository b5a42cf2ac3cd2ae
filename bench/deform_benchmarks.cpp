// Benchmarks of deforming scenes: update cost, query cost after updates, and both, against
// queries on freshly built models (deform_benchmarks.h).
#include "deform_benchmarks.h"

#include <map>
#include <string>

namespace collido::bench {
namespace {

enum class Timed { kUpdateAndQuery, kUpdate, kQuery, kFreshQuery };

void deformBenchmark(benchmark::State& state, const Variant& variant,
                     const std::shared_ptr<const Scene>& scene, std::size_t query_index,
                     Timed timed) {
  // Loaded scenes have a frame at least; one built otherwise could have none, and the frame
  // counter below wraps modulo the count.
  if (scene->frames == 0) {
    state.SkipWithError("the scene has no frames");
    return;
  }
  std::unique_ptr<BackendInstance> backend = createOrSkip(variant, state);
  if (!backend) return;
  const Capabilities& caps = backend->capabilities();
  const SceneQuery& query = scene->queries[query_index];
  if (!caps.queries.contains(query.request.kind)) {
    state.SkipWithError("the backend does not answer this kind of query");
    return;
  }
  if (!caps.update) {
    state.SkipWithError("the backend does not update models");
    return;
  }
  const bool fresh = timed == Timed::kFreshQuery;
  // Models: per object and state (updated each frame), or per object and frame (fresh).
  std::map<std::size_t, std::vector<ModelHandle>> models;
  std::map<std::size_t, std::vector<Eigen::Matrix3Xd>> positions;
  for (std::size_t object : query.objects()) {
    const SceneObject& o = scene->objects[object];
    BuildNeeds needs = scene->needsOf(object);
    needs.queries = QueryKindSet(needs.queries.bits() & caps.queries.bits());
    const std::size_t count = fresh ? scene->frames : o.stateCount();
    for (std::size_t k = 0; k < count; ++k) {
      const std::shared_ptr<const TriangleMesh> shape = fresh ? o.shapeAt(k) : o.stateMesh(k);
      Result<ModelHandle> model = backend->build(shape->view(), needs);
      if (!model.ok()) {
        state.SkipWithError(model.status().message().c_str());
        return;
      }
      models[object].push_back(model.value());
    }
    if (o.deformation && !fresh) {
      for (std::size_t f = 0; f < scene->frames; ++f)
        positions[object].push_back(o.shapeAt(f)->vertices);
    }
  }
  const auto modelAt = [&](std::size_t object, std::size_t frame) {
    return models[object][fresh ? frame : scene->objects[object].stateAt(frame)];
  };
  QueryResult result;
  std::size_t frame = 0;
  for (auto _ : state) {
    if (timed == Timed::kQuery) state.PauseTiming();
    for (const auto& [object, frames] : positions) {
      const Status status = backend->update(modelAt(object, frame), frames[frame]);
      if (!status.ok()) {
        state.SkipWithError(status.message().c_str());
        return;
      }
    }
    if (timed == Timed::kQuery) state.ResumeTiming();
    if (timed != Timed::kUpdate) {
      const Status status = backend->query(
          modelAt(query.a, frame), scene->objects[query.a].poseAt(frame), modelAt(query.b, frame),
          scene->objects[query.b].poseAt(frame), query.request, result);
      if (!status.ok()) {
        state.SkipWithError(status.message().c_str());
        return;
      }
    }
    frame = (frame + 1) % scene->frames;
  }
  state.counters["frames"] = static_cast<double>(scene->frames);
  for (const auto& [object, handles] : models) {
    for (ModelHandle handle : handles)
      (void)backend->release(handle);
  }
}

}  // namespace

int registerDeformBenchmarks(const std::shared_ptr<const Scene>& scene,
                             const std::vector<Variant>& variants) {
  const bool deforms = std::any_of(scene->objects.begin(), scene->objects.end(),
                                   [](const SceneObject& o) { return o.changesShape(); });
  if (!deforms) return 0;
  int registered = 0;
  for (const Variant& variant : variants) {
    for (std::size_t q = 0; q < scene->queries.size(); ++q) {
      if (scene->queries[q].isGroup()) continue;
      for (const auto& [prefix, timed] :
           {std::pair<const char*, Timed>{"deform/", Timed::kUpdateAndQuery},
            {"deform_update/", Timed::kUpdate},
            {"deform_query/", Timed::kQuery},
            {"deform_fresh/", Timed::kFreshQuery}}) {
        const std::string name =
            prefix + variant.label + "/" + scene->name + "/" + scene->queries[q].name;
        benchmark::RegisterBenchmark(name.c_str(), deformBenchmark, variant, scene, q, timed)
            ->Unit(benchmark::kMicrosecond);
        ++registered;
      }
    }
  }
  return registered;
}

}  // namespace collido::bench
