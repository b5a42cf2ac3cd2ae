#include <collido/study/worker.h>

#include <algorithm>
#include <optional>

#include <collido/runner/runner.h>
#include <collido/scene/scene.h>
#include <collido/study/oracle_store.h>
#include <collido/study/plan.h>
#include <collido/study/resident_memory.h>

#include "comparison_worker.h"

namespace collido::study {
namespace {

/// The fewest timed calls a query gets in one round, however few its frames.
constexpr int kMinTimedCalls = 12;
/// The fewest back-to-back calls a frame gets for the repeated protocol's secondary figure.
constexpr int kMinRepeatedCalls = 3;

// The combination's backend setting, found among the worker's plugins; none for a seed method.
Result<std::vector<BackendSpec>> backendsOf(const WorkerRequest& request) {
  if (request.combination.backend == kSeedMethod) return std::vector<BackendSpec>{};
  const PluginDiscovery found = discoverPlugins(request.plugin_paths, request.default_plugins);
  return resolveBackends({request.combination.backend}, found.plugins);
}

}  // namespace

bool failsItsWorker(const CombinationResult& result) {
  return result.combination.kind != InputKind::kScene && !result.problems.empty();
}

Result<CombinationResult> runCombination(const WorkerRequest& request) {
  const Combination& c = request.combination;
  Result<std::vector<BackendSpec>> specs = backendsOf(request);
  if (!specs.ok()) return specs.status();
  if (c.kind != InputKind::kScene)
    return runComparisonCombination(request, std::move(specs).value());
  // The scene's solved placement is kept beside the oracle's answers, solved once per study.
  SceneLoadOptions load{c.resolution};
  if (!request.oracle_directory.empty())
    load.placement_store = request.oracle_directory + "/placements";
  Result<Scene> loaded = loadScene(c.scene_path, load);
  if (!loaded.ok()) return loaded.status();
  Scene scene = std::move(loaded).value();
  std::optional<Scene> finest;
  // Only a coarser mesh is judged against the finest one; a finer one is itself the finest.
  if (c.resolution < 1.0) {
    load.resolution = 1.0;
    Result<Scene> fine = loadScene(c.scene_path, load);
    if (!fine.ok()) return fine.status();
    finest = std::move(fine).value();
    // Motions placed relative to bounding spheres differ a little between resolutions; the
    // coarse mesh must answer for the poses the finest one is judged at.
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      scene.objects[i].poses = finest->objects[i].poses;
  }
  // A sub-step setting answers like its backend but over a step: studied there alone, its
  // other answers being its backend's own, studied already.
  if (answersBySubsteps(c.backend)) {
    scene.queries.erase(std::remove_if(scene.queries.begin(), scene.queries.end(),
                                       [](const SceneQuery& q) {
                                         return !queryKindInfo(q.request.kind).over_a_step;
                                       }),
                        scene.queries.end());
  }
  if (c.limit != 0) {
    for (SceneQuery& q : scene.queries) {
      if (const auto limit = queryKindInfo(q.request.kind).limit) q.request.*limit = c.limit;
    }
  }

  RunOptions options;
  options.repetitions = request.repetitions;
  // A scene of a few frames still gets enough timed calls a round for an interval of its own:
  // a one-frame scene's figure would otherwise rest on `repetitions` calls.
  if (scene.frames > 0) {
    const auto frames = static_cast<int>(std::min<std::size_t>(scene.frames, kMinTimedCalls));
    options.repetitions = std::max(options.repetitions, (kMinTimedCalls + frames - 1) / frames);
  }
  options.protocol = c.protocol;
  // The secondary figure is measured in the first round only: it informs, it decides no pick,
  // and the study's time budget goes to the headline's rounds.
  if (options.protocol == TimingProtocol::kCycled && c.round == 0)
    options.repeated_calls = std::max(kMinRepeatedCalls, options.repetitions);
  options.build_every_need = c.needs == NeedsMode::kEvery;
  options.reuse_unchanged = c.needs == NeedsMode::kChanged;
  options.skip_apart_pairs = c.needs == NeedsMode::kChanged;
  options.frame_progress = request.progress;
  // The exact answers of this scene may be stored already by an earlier combination.
  OracleCache oracle(scene);
  std::optional<OracleCache> finest_oracle;
  if (finest) finest_oracle.emplace(*finest, /*witness_only=*/true);
  const StoredOracle stored(request.oracle_directory, oracle);
  std::optional<StoredOracle> finest_stored;
  if (finest_oracle) finest_stored.emplace(request.oracle_directory, *finest_oracle);

  // The exact answers first, kept at once: their memory is then not charged to the backend.
  precomputeOracleAnswers(oracle);
  if (finest_oracle) precomputeOracleAnswers(*finest_oracle, /*distances=*/false);
  stored.keepNew();
  if (finest_stored) finest_stored->keepNew();

  const ResidentPeak backend_memory;
  RunReport report = runScene(scene, specs.value().front(), options, oracle,
                              finest_oracle ? &*finest_oracle : nullptr);

  CombinationResult result;
  result.backend_rss_bytes = backend_memory.addedBytes();
  result.combination = c;
  result.measurements = std::move(report.measurements);
  result.problems = std::move(report.problems);
  return result;
}

}  // namespace collido::study
