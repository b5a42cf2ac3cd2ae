// Benchmark bodies written once, registered at run time per backend x scene x query.
#include "scene_benchmarks.h"

#include "bench_variant.h"
#include "deform_benchmarks.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <benchmark/benchmark.h>

#include <collido/host/backend_instance.h>
#include <collido/host/static_backends.h>
#include <collido/oracle/double_triangle_test.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/runner/floor.h>
#include <collido/runner/runner.h>
#include <collido/scene/broad_phase.h>
#include <collido/scene/scene.h>

namespace collido::bench {
namespace {

std::vector<std::shared_ptr<PluginLibrary>> staticLibraries() {
  std::vector<std::shared_ptr<PluginLibrary>> out;
  for (const StaticBackendTable& entry : staticBackendTables()) {
    Result<std::shared_ptr<PluginLibrary>> library =
        PluginLibrary::fromTable(entry.entry(), entry.name + " (static)");
    if (library.ok()) out.push_back(library.value());
  }
  return out;
}

// Whether a variant builds triangle meshes (the scenes' objects); surface-only backends have
// their own benchmarks (nurbs_benchmarks.cpp).
bool buildsMeshes(const std::shared_ptr<PluginLibrary>& library, const std::string& variant) {
  Result<std::unique_ptr<BackendInstance>> instance = BackendInstance::create(library, variant);
  return instance.ok() && instance.value()->capabilities().buildsShape(ShapeKind::kTriangleMesh);
}

// Every mesh variant with its default options, or the backends named (study syntax).
Result<std::vector<Variant>> variantsToRun(const std::vector<std::string>& backends) {
  const std::vector<std::shared_ptr<PluginLibrary>> libraries = staticLibraries();
  std::vector<Variant> out;
  if (backends.empty()) {
    for (const auto& library : libraries) {
      for (const VariantInfo& v : library->variants()) {
        if (buildsMeshes(library, v.name)) out.push_back({library, v.name, {}, v.name});
      }
    }
    return out;
  }
  Result<std::vector<BackendSpec>> specs = resolveBackends(backends, libraries);
  if (!specs.ok()) return specs.status();
  for (const BackendSpec& spec : specs.value())
    out.push_back({spec.library, spec.variant, spec.options, spec.label()});
  return out;
}

// Whether the variant (with its options) answers queries of this kind.
bool answers(const Variant& variant, QueryKind kind) {
  Result<std::unique_ptr<BackendInstance>> instance =
      BackendInstance::create(variant.library, variant.name, variant.options);
  return instance.ok() && instance.value()->capabilities().queries.contains(kind);
}

void buildBenchmark(benchmark::State& state, const Variant& variant,
                    const std::shared_ptr<const Scene>& scene, std::size_t object) {
  std::unique_ptr<BackendInstance> backend = createOrSkip(variant, state);
  if (!backend) return;
  const BuildNeeds needs = scene->needsOf(object);
  const MeshView mesh = scene->objects[object].mesh->view();
  std::uint64_t bytes = 0;
  for (auto _ : state) {
    Result<ModelHandle> model = backend->build(mesh, needs);
    if (!model.ok()) {
      state.SkipWithError(model.status().message().c_str());
      return;
    }
    state.PauseTiming();
    Result<std::uint64_t> memory = backend->memory(model.value());
    bytes = memory.ok() ? memory.value() : 0;
    (void)backend->release(model.value());
    state.ResumeTiming();
  }
  const double triangles = static_cast<double>(scene->objects[object].mesh->triangleCount());
  state.counters["triangles"] = triangles;
  state.counters["bytes_per_triangle"] = static_cast<double>(bytes) / triangles;
}

void queryBenchmark(benchmark::State& state, const Variant& variant,
                    const std::shared_ptr<const Scene>& scene, std::size_t query_index) {
  // Loaded scenes have a frame at least; one built otherwise could have none, and the frame
  // counter below wraps modulo the count.
  if (scene->frames == 0) {
    state.SkipWithError("the scene has no frames");
    return;
  }
  std::unique_ptr<BackendInstance> backend = createOrSkip(variant, state);
  if (!backend) return;
  const SceneQuery& query = scene->queries[query_index];
  if (!backend->capabilities().queries.contains(query.request.kind)) {
    state.SkipWithError("the backend does not answer this kind of query");
    return;
  }
  // Build every object asked about; a group query's candidate pairs come from the shared broad
  // phase, computed for every frame ahead of timing (it is the same for every backend).
  std::map<std::size_t, ModelHandle> models;
  for (std::size_t object : query.objects()) {
    BuildNeeds needs = scene->needsOf(object);
    needs.queries = QueryKindSet(needs.queries.bits() & backend->capabilities().queries.bits());
    Result<ModelHandle> model = backend->build(scene->objects[object].mesh->view(), needs);
    if (!model.ok()) {
      state.SkipWithError(model.status().message().c_str());
      return;
    }
    models[object] = model.value();
  }
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> candidates(scene->frames);
  if (query.isGroup()) {
    const BroadPhase broad_phase(*scene, query);
    for (std::size_t f = 0; f < scene->frames; ++f)
      candidates[f] = broad_phase.pairsAt(f);
  } else {
    for (auto& frame_pairs : candidates)
      frame_pairs = {{query.a, query.b}};
  }
  QueryResult result;
  std::size_t frame = 0;
  double bv_tests = 0.0;
  double primitive_tests = 0.0;
  double pairs = 0.0;
  for (auto _ : state) {
    for (const auto& [ia, ib] : candidates[frame]) {
      const Status status = backend->query(models[ia], scene->objects[ia].poseAt(frame), models[ib],
                                           scene->objects[ib].poseAt(frame), query.request, result);
      if (!status.ok()) {
        state.SkipWithError(status.message().c_str());
        return;
      }
      bv_tests += static_cast<double>(result.counters.bv_tests);
      primitive_tests += static_cast<double>(result.counters.primitive_tests);
      pairs += static_cast<double>(result.pairs.size());
    }
    frame = (frame + 1) % scene->frames;
  }
  if (pairs > 0.0) {
    // Work per reported pair (for an exact backend, per truly intersecting pair).
    state.counters["box_tests_per_pair"] = bv_tests / pairs;
    state.counters["triangle_tests_per_pair"] = primitive_tests / pairs;
  }
  state.counters["box_tests"] = benchmark::Counter(bv_tests, benchmark::Counter::kAvgIterations);
  state.counters["triangle_tests"] =
      benchmark::Counter(primitive_tests, benchmark::Counter::kAvgIterations);
  state.counters["pairs"] = benchmark::Counter(pairs, benchmark::Counter::kAvgIterations);
  state.counters["frames"] = static_cast<double>(scene->frames);
}

// The floor an all-pairs query cannot go below: one exact triangle-triangle test for each pair
// the exact oracle finds (on the world coordinates as doubles), frame by frame as the query
// benchmarks cycle them. A backend's floor ratio is its query time over this time, both from one
// run. Two exact tests: floor/ uses the fastest we have (the OBB tree's trianglesIntersect over
// CGAL's statically filtered predicates); floor_oracle/ the oracle's exactTrianglesIntersect.
using ExactTriangleTest = bool (*)(const std::array<Eigen::Vector3d, 3>&,
                                   const std::array<Eigen::Vector3d, 3>&);

bool obbtreeExactTest(const std::array<Eigen::Vector3d, 3>& a,
                      const std::array<Eigen::Vector3d, 3>& b) {
  return exact::trianglesIntersect(a[0], a[1], a[2], b[0], b[1], b[2]);
}

void floorBenchmark(benchmark::State& state, const std::shared_ptr<const Scene>& scene,
                    std::size_t query_index, ExactTriangleTest exact_test) {
  if (scene->frames == 0) {
    state.SkipWithError("the scene has no frames");
    return;
  }
  const SceneQuery& query = scene->queries[query_index];
  std::vector<std::vector<WorldTrianglePair>> frames(scene->frames);
  for (std::size_t f = 0; f < scene->frames; ++f) {
    const SceneObject& a = scene->objects[query.a];
    const SceneObject& b = scene->objects[query.b];
    const auto shape_a = a.shapeAt(f);
    const auto shape_b = b.shapeAt(f);
    const OracleAnswer answer =
        exactIntersectingPairs(*shape_a, a.poseAt(f), *shape_b, b.poseAt(f));
    appendWorldPairs(*shape_a, a.poseAt(f), *shape_b, b.poseAt(f), answer.pairs, frames[f]);
  }
  std::size_t frame = 0;
  double pairs = 0.0;
  for (auto _ : state) {
    for (const auto& [ta, tb] : frames[frame]) {
      const bool hit = exact_test(ta, tb);
      benchmark::DoNotOptimize(hit);
    }
    pairs += static_cast<double>(frames[frame].size());
    frame = (frame + 1) % scene->frames;
  }
  state.counters["pairs"] = benchmark::Counter(pairs, benchmark::Counter::kAvgIterations);
  state.counters["ns_per_test"] =
      benchmark::Counter(pairs, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Refit after a deformation: every vertex moved a little (a breathing scale about the centroid,
// alternating between two states so each call really moves the vertices).
void refitBenchmark(benchmark::State& state, const Variant& variant,
                    const std::shared_ptr<const Scene>& scene, std::size_t object) {
  std::unique_ptr<BackendInstance> backend = createOrSkip(variant, state);
  if (!backend) return;
  if (!backend->capabilities().update) {
    state.SkipWithError("the backend does not update models");
    return;
  }
  const TriangleMesh& mesh = *scene->objects[object].mesh;
  BuildNeeds needs = scene->needsOf(object);
  needs.queries = QueryKindSet(needs.queries.bits() & backend->capabilities().queries.bits());
  needs.deforms = true;
  Result<ModelHandle> model = backend->build(mesh.view(), needs);
  if (!model.ok()) {
    state.SkipWithError(model.status().message().c_str());
    return;
  }
  const Eigen::Vector3d centre = mesh.vertices.rowwise().mean();
  Eigen::Matrix3Xd states[2] = {mesh.vertices, mesh.vertices};
  states[1] = ((mesh.vertices.colwise() - centre) * 1.01).colwise() + centre;
  std::size_t which = 0;
  for (auto _ : state) {
    which ^= 1u;
    const Status status = backend->update(model.value(), states[which]);
    if (!status.ok()) {
      state.SkipWithError(status.message().c_str());
      return;
    }
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangleCount());
  (void)backend->release(model.value());
}

// The scaling family: scenes/scaling_spheres.json at resolutions giving about 1k, 10k, 100k and
// 1M triangles per sphere; Google Benchmark fits the growth (BigO) over the four sizes.
constexpr double kScalingResolutions[] = {0.1, 0.316, 1.0, 3.16};

std::shared_ptr<const Scene> scalingScene(const std::string& file, int size_index) {
  static std::map<int, std::shared_ptr<const Scene>> cache;
  auto found = cache.find(size_index);
  if (found != cache.end()) return found->second;
  Result<Scene> loaded =
      loadScene(file, SceneLoadOptions{kScalingResolutions[static_cast<std::size_t>(size_index)]});
  std::shared_ptr<const Scene> scene =
      loaded.ok() ? std::make_shared<const Scene>(std::move(loaded).value()) : nullptr;
  cache.emplace(size_index, scene);
  return scene;
}

void scalingBenchmark(benchmark::State& state, const Variant& variant, const std::string& file,
                      std::size_t query_index) {
  const std::shared_ptr<const Scene> scene = scalingScene(file, static_cast<int>(state.range(0)));
  if (!scene) {
    state.SkipWithError(("cannot load " + file).c_str());
    return;
  }
  queryBenchmark(state, variant, scene, query_index);
  state.SetComplexityN(static_cast<benchmark::IterationCount>(
      scene->objects[scene->queries[query_index].a].mesh->triangleCount()));
}

}  // namespace

Result<int> registerSceneBenchmarks(const std::string& scenes_directory,
                                    const std::vector<std::string>& backends) {
  Result<std::vector<Variant>> resolved = variantsToRun(backends);
  if (!resolved.ok()) return resolved.status();
  const std::vector<Variant>& variants = resolved.value();
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(scenes_directory, ec)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  int registered = 0;
  for (const std::string& file : files) {
    Result<Scene> loaded = loadScene(file);
    if (!loaded.ok()) continue;
    const auto scene = std::make_shared<const Scene>(std::move(loaded).value());
    // Objects of the same shape (a pile of copies) are built the same way: benchmark one of
    // them. The mesh report names the shape's source (file or generator with its parameters).
    std::vector<std::size_t> distinct_meshes;
    std::set<std::string> seen;
    for (std::size_t object : scene->queriedObjects()) {
      if (seen.insert(scene->objects[object].report.summary()).second) {
        distinct_meshes.push_back(object);
      }
    }
    for (std::size_t q = 0; q < scene->queries.size(); ++q) {
      const SceneQuery& query = scene->queries[q];
      if (query.isGroup() || query.request.kind != QueryKind::kAllPairs) continue;
      for (const auto& [prefix, test] :
           {std::pair<const char*, ExactTriangleTest>{"floor/", &obbtreeExactTest},
            {"floor_oracle/", &exactTrianglesIntersect}}) {
        const std::string name = prefix + scene->name + "/" + query.name;
        benchmark::RegisterBenchmark(name.c_str(), floorBenchmark, scene, q, test)
            ->Unit(benchmark::kMicrosecond);
        ++registered;
      }
    }
    const bool deforms = std::any_of(scene->objects.begin(), scene->objects.end(),
                                     [](const SceneObject& o) { return o.changesShape(); });
    registered += registerDeformBenchmarks(scene, variants);
    for (const Variant& variant : variants) {
      for (std::size_t object : distinct_meshes) {
        const std::string name =
            "build/" + variant.label + "/" + scene->name + "/" + scene->objects[object].name;
        benchmark::RegisterBenchmark(name.c_str(), buildBenchmark, variant, scene, object)
            ->Unit(benchmark::kMicrosecond);
        const std::string refit =
            "refit/" + variant.label + "/" + scene->name + "/" + scene->objects[object].name;
        benchmark::RegisterBenchmark(refit.c_str(), refitBenchmark, variant, scene, object)
            ->Unit(benchmark::kMicrosecond);
        registered += 2;
      }
      // A deforming scene's queries are measured with their updates (deform_benchmarks.h).
      for (std::size_t q = 0; q < scene->queries.size() && !deforms; ++q) {
        const std::string name =
            "query/" + variant.label + "/" + scene->name + "/" + scene->queries[q].name;
        benchmark::RegisterBenchmark(name.c_str(), queryBenchmark, variant, scene, q)
            ->Unit(benchmark::kMicrosecond);
        ++registered;
      }
    }
  }
  const std::string scaling_file =
      (std::filesystem::path(scenes_directory) / "scaling_spheres.json").string();
  if (std::filesystem::exists(scaling_file, ec)) {
    for (const Variant& variant : variants) {
      for (const auto& [query_index, query_name, kind] :
           {std::tuple<std::size_t, const char*, QueryKind>{0, "all_pairs", QueryKind::kAllPairs},
            {1, "boolean", QueryKind::kBoolean}}) {
        // Google Benchmark's complexity fit crashes on a family whose every run was skipped.
        if (!answers(variant, kind)) continue;
        const std::string name = "scaling/" + variant.label + "/" + query_name;
        benchmark::RegisterBenchmark(name.c_str(), scalingBenchmark, variant, scaling_file,
                                     query_index)
            ->DenseRange(0, 3)
            ->Complexity(benchmark::oAuto)
            ->Unit(benchmark::kMicrosecond);
        ++registered;
      }
    }
  }
  return registered;
}

}  // namespace collido::bench
