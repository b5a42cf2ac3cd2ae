// One backend on one scene: building, per query the checks, the frame stepping (the checked
// call of each object pair, seen by the observers), and the timed calls.
//
// Timing: per frame, one untimed call (whose answer is the one checked), then `repetitions`
// timed calls with a steady clock around the whole interface call, so every backend pays the
// same boundary cost (the repeated protocol); or, cycled, one timed call per frame in each of
// `repetitions` passes over the frames. Medians and p90 are over all timed calls of the query.
#include "backend_run.h"

#include <algorithm>
#include <chrono>
#include <memory>

#include <collido/host/backend_instance.h>
#include <collido/runner/statistics.h>
#include <collido/runner/timed_calls.h>

#include "frame_observers.h"
#include "scene_models.h"

namespace collido::detail {
namespace {

using Clock = std::chrono::steady_clock;

// One timed call of a frame: every candidate object pair asked once, in microseconds, or the
// failure that stopped it. Both timing protocols time frames this way.
template <typename Ask>
Result<double> timeFrameCall(const ObjectPairs& candidates, const Ask& ask) {
  return timeCall([&]() -> Status {
    for (const auto& [ia, ib] : candidates) {
      if (Status s = ask(ia, ib); !s.ok()) return s;
    }
    return {};
  });
}

MeasurementStatus frameFailure(std::size_t frame, const std::string& what) {
  return MeasurementStatus::failed("frame " + std::to_string(frame) + ": " + what);
}

// Why the backend cannot answer `query` of `scene` (a skipped measurement), or nothing.
std::optional<MeasurementStatus> cannotAnswer(const Scene& scene, const SceneQuery& query,
                                              const Capabilities& caps, const std::string& label) {
  if (!caps.buildsShape(ShapeKind::kTriangleMesh)) {
    return MeasurementStatus::skipped(
        label + " builds no triangle meshes (the scene's objects are meshes)");
  }
  if (!caps.queries.contains(query.request.kind)) {
    return MeasurementStatus::skipped(label + " does not answer " +
                                      queryKindName(query.request.kind) + " queries");
  }
  const std::vector<std::size_t> objects = query.objects();
  const bool deforms = std::any_of(objects.begin(), objects.end(), [&](std::size_t i) {
    return scene.objects[i].deformation != nullptr;
  });
  if (!caps.update && deforms) {
    return MeasurementStatus::skipped(label +
                                      " does not update models (the scene deforms an object)");
  }
  return std::nullopt;
}

// What one query's frames are stepped with.
struct QueryRun {
  const Scene& scene;
  const SceneQuery& query;
  const std::vector<std::size_t> objects;
  const SceneModels& models;
  BackendInstance& backend;
  OracleCache& oracle;

  ModelHandle modelAt(std::size_t object, std::size_t frame) const {
    return models.at(object)[scene.objects[object].stateAt(frame)].handle;
  }
  Status ask(std::size_t ia, std::size_t ib, std::size_t frame, QueryResult& result) const {
    return backend.query(modelAt(ia, frame), scene.objects[ia].poseAt(frame), modelAt(ib, frame),
                         scene.objects[ib].poseAt(frame), query.request, result);
  }
};

// Updates the frame's deforming objects to their shapes in it, timing the calls (one per object)
// into `record` when asked to; fails the measurement when an update fails.
void updateDeforming(const QueryRun& run, std::size_t frame,
                     std::map<std::size_t, std::shared_ptr<const TriangleMesh>>& shapes,
                     FrameRecord* record, QueryMeasurement& m) {
  for (std::size_t i : run.objects) {
    shapes[i] = run.scene.objects[i].shapeAt(frame);
    if (run.scene.objects[i].deformation == nullptr) continue;
    const Clock::time_point start = Clock::now();
    UpdateCounters work;
    const Status s =
        run.backend.update(run.modelAt(i, frame), shapes[i]->vertices, record ? &work : nullptr);
    const Clock::time_point stop = Clock::now();
    if (!s.ok()) {
      m.status = frameFailure(frame, "update " + run.scene.objects[i].name + ": " + s.toString());
      return;
    }
    if (record == nullptr) continue;
    record->update_us = record->update_us.value_or(0.0) +
                        std::chrono::duration<double, std::micro>(stop - start).count();
    if (work.counted) {
      record->update_work.counted = true;
      record->update_work.nodes_refit += work.nodes_refit;
      record->update_work.rebuilds += work.rebuilds;
      record->update_work.nodes_rebuilt += work.nodes_rebuilt;
    }
  }
}

// Steps through the query's frames: each frame's shapes (deforming objects updated, timed), the
// checked call of each candidate object pair (which the observers see), the repeated protocol's
// timed calls, then the observers' frame figures. Returns each frame's candidates.
std::vector<ObjectPairs> stepFrames(const QueryRun& run,
                                    const std::optional<BroadPhase>& broad_phase,
                                    const std::vector<FrameObserver*>& observers,
                                    const RunOptions& options, std::size_t& frames_done,
                                    std::size_t frames_total, QueryMeasurement& m) {
  std::vector<ObjectPairs> frame_candidates;
  QueryResult result;
  for (std::size_t frame = 0; frame < run.scene.frames && m.ok(); ++frame) {
    const ObjectPairs candidates = objectPairsAt(broad_phase, run.query, frame);
    FrameRecord record;
    record.frame = frame;
    record.object_pairs = candidates.size();
    std::map<std::size_t, std::shared_ptr<const TriangleMesh>> shapes;
    updateDeforming(run, frame, shapes, &record, m);
    if (!m.ok()) break;
    for (const auto& [ia, ib] : candidates) {
      if (Status s = run.ask(ia, ib, frame, result); !s.ok()) {
        m.status = frameFailure(frame, s.toString());
        break;
      }
      const OracleAnswer& truth =
          run.oracle.get(ia, ib, frame, run.query.request.kind == QueryKind::kDistance);
      const AskedPair asked{frame,
                            ia,
                            ib,
                            *shapes[ia],
                            *shapes[ib],
                            run.scene.objects[ia].poseAt(frame),
                            run.scene.objects[ib].poseAt(frame),
                            run.query.request,
                            result,
                            truth};
      for (FrameObserver* observer : observers)
        observer->pair(asked, record);
      record.bv_tests += result.counters.bv_tests;
      record.primitive_tests += result.counters.primitive_tests;
      m.counts_bv_tests = result.counters.counts_bv_tests;
      m.counts_primitive_tests = result.counters.counts_primitive_tests;
    }
    if (!m.ok()) break;

    std::vector<double> frame_times;
    const int repetitions = options.protocol == TimingProtocol::kRepeated ? options.repetitions : 0;
    for (int rep = 0; rep < repetitions; ++rep) {
      const Result<double> took = timeFrameCall(candidates, [&](std::size_t ia, std::size_t ib) {
        return run.ask(ia, ib, frame, result);
      });
      if (!took.ok()) {
        m.status = frameFailure(frame, took.status().toString());
        break;
      }
      frame_times.push_back(took.value());
    }
    record.median_us = quantile(frame_times, 0.5);
    if (m.ok()) {
      const SteppedFrame stepped{frame, candidates, shapes};
      for (FrameObserver* observer : observers)
        observer->frame(stepped, record);
    }
    m.times_us.insert(m.times_us.end(), frame_times.begin(), frame_times.end());
    m.frames.push_back(std::move(record));
    frame_candidates.push_back(candidates);
    if (options.frame_progress) options.frame_progress(++frames_done, frames_total);
  }
  return frame_candidates;
}

// The cycled protocol's timed passes: each pass asks every frame once, in order, so that no
// call finds the previous one's data in cache. A deforming object is updated to each frame
// first, untimed. Each frame's median is over its calls; times_us holds every call.
void timeCycled(const QueryRun& run, const std::vector<ObjectPairs>& candidates, int repetitions,
                QueryMeasurement& m) {
  std::vector<std::vector<double>> times(m.frames.size());
  QueryResult result;
  for (int rep = 0; rep < repetitions && m.ok(); ++rep) {
    for (std::size_t k = 0; k < m.frames.size() && m.ok(); ++k) {
      const std::size_t frame = m.frames[k].frame;
      std::map<std::size_t, std::shared_ptr<const TriangleMesh>> shapes;
      updateDeforming(run, frame, shapes, nullptr, m);
      if (!m.ok()) break;
      const Result<double> took = timeFrameCall(candidates[k], [&](std::size_t ia, std::size_t ib) {
        return run.ask(ia, ib, frame, result);
      });
      if (!took.ok()) {
        m.status = frameFailure(frame, took.status().toString());
        break;
      }
      times[k].push_back(took.value());
    }
  }
  for (std::size_t k = 0; k < m.frames.size(); ++k) {
    m.frames[k].median_us = quantile(times[k], 0.5);
    m.times_us.insert(m.times_us.end(), times[k].begin(), times[k].end());
  }
}

}  // namespace

void runSceneOnBackend(const Scene& scene, const BackendSpec& spec, OracleCache& oracle,
                       OracleCache* finest_oracle, const RunOptions& options, RunReport& report) {
  const std::string label = spec.label();
  const auto measurementOf = [&](const SceneQuery& q) {
    QueryMeasurement m;
    m.backend = label;
    m.scene = scene.name;
    m.query = q.name;
    m.kind = q.request.kind;
    return m;
  };
  Result<std::unique_ptr<BackendInstance>> created =
      BackendInstance::create(spec.library, spec.variant, spec.options);
  if (!created.ok()) {
    report.problems.push_back(created.status().message());
    for (const SceneQuery& q : scene.queries) {
      QueryMeasurement m = measurementOf(q);
      m.status = MeasurementStatus::failed(created.status().message());
      report.measurements.push_back(m);
    }
    return;
  }
  BackendInstance& backend = *created.value();
  const Capabilities& caps = backend.capabilities();
  // Queries the backend cannot answer are skipped below with the reason.
  const SceneModels models = caps.buildsShape(ShapeKind::kTriangleMesh)
                                 ? buildSceneModels(scene, backend, options, label)
                                 : SceneModels();

  // Objects posed from tracked markers: the same scene at the true poses, whose exact answers
  // say what tracking error did to the collision answer.
  const Scene truth_scene = scene.hasTrackedObjects() ? scene.withTruePoses() : Scene{};
  std::optional<OracleCache> truth_oracle;
  if (scene.hasTrackedObjects()) truth_oracle.emplace(truth_scene, /*witness_only=*/true);

  std::size_t frames_done = 0;
  const std::size_t frames_total = scene.frames * scene.queries.size();
  for (const SceneQuery& query : scene.queries) {
    QueryMeasurement m = measurementOf(query);
    m.protocol = timingProtocolName(options.protocol);
    if (std::optional<MeasurementStatus> skipped = cannotAnswer(scene, query, caps, label)) {
      m.status = *skipped;
      report.measurements.push_back(m);
      continue;
    }
    const QueryRun run{scene, query, query.objects(), models, backend, oracle};
    if (const std::string error = buildError(models, run.objects); !error.empty()) {
      m.status = MeasurementStatus::failed("build: " + error);
      report.measurements.push_back(m);
      continue;
    }
    addBuildFigures(scene, models, run.objects, m);
    if (options.progress) {
      options.progress(label + ": " + scene.name + " / " + query.name + " (" +
                       std::to_string(scene.frames) + " frames)");
    }

    // The observers this scene and these options call for.
    OracleComparison comparison;
    std::optional<AnswerKeeper> keeper;
    std::optional<FloorTimer> floor;
    std::optional<FinestComparison> finest;
    std::optional<TrackingComparison> tracking;
    std::vector<FrameObserver*> observers{&comparison};
    if (options.keep_answers) observers.push_back(&keeper.emplace());
    if (query.request.kind == QueryKind::kAllPairs)
      observers.push_back(&floor.emplace(options.repetitions));
    if (finest_oracle != nullptr) observers.push_back(&finest.emplace(*finest_oracle, query));
    if (truth_oracle) {
      observers.push_back(&tracking.emplace(scene, *truth_oracle, query, options.tracking_sigmas));
    }

    std::optional<BroadPhase> broad_phase;
    if (query.isGroup()) broad_phase.emplace(scene, query);
    const std::vector<ObjectPairs> candidates =
        stepFrames(run, broad_phase, observers, options, frames_done, frames_total, m);
    if (options.protocol == TimingProtocol::kCycled && m.ok())
      timeCycled(run, candidates, options.repetitions, m);
    summariseMeasurement(m);
    report.measurements.push_back(std::move(m));
  }
  releaseModels(backend, models);
}

}  // namespace collido::detail
