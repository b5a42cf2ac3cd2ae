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
#include <map>
#include <memory>
#include <set>
#include <utility>

#include <collido/host/backend_instance.h>
#include <collido/motion.h>
#include <collido/runner/statistics.h>
#include <collido/runner/timed_calls.h>

#include "check.h"
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

// A step's answer from boolean answers at t = k / substeps, k = 0 .. substeps: the first that
// touches closes the bracket. Counters are the calls' summed.
Status substepAnswer(BackendInstance& backend, ModelHandle model_a, const Pose& pose_a,
                     ModelHandle model_b, const Pose& pose_b, const QueryRequest& request,
                     int substeps, QueryResult& result) {
  // The scene reader and the runner made these poses; a step between them always exists.
  const StepMotion motion_a = StepMotion::between(pose_a, request.step->pose_a, "A").value();
  const StepMotion motion_b = StepMotion::between(pose_b, request.step->pose_b, "B").value();
  QueryRequest boolean;
  boolean.kind = QueryKind::kBoolean;
  FirstContactResult answer;
  WorkCounters counters;
  for (int k = 0; k <= substeps; ++k) {
    const double t = static_cast<double>(k) / substeps;
    if (Status s = backend.query(model_a, motion_a.at(t), model_b, motion_b.at(t), boolean, result);
        !s.ok()) {
      return s;
    }
    counters.bv_tests += result.counters.bv_tests;
    counters.primitive_tests += result.counters.primitive_tests;
    counters.counts_bv_tests = result.counters.counts_bv_tests;
    counters.counts_primitive_tests = result.counters.counts_primitive_tests;
    if (!result.intersecting) continue;
    answer.touches = true;
    answer.t_lo = k == 0 ? 0.0 : static_cast<double>(k - 1) / substeps;
    answer.t_hi = t;
    if (!result.pairs.empty()) {
      answer.triangle_a = result.pairs.front().a;
      answer.triangle_b = result.pairs.front().b;
    }
    break;
  }
  result.clear();
  result.intersecting = answer.touches;
  result.first_contact = answer;
  result.counters = counters;
  return {};
}

MeasurementStatus frameFailure(std::size_t frame, const std::string& what) {
  return MeasurementStatus::failed("frame " + std::to_string(frame) + ": " + what);
}

// Why the backend cannot answer `query` of `scene` (a skipped measurement), or nothing.
std::optional<MeasurementStatus> cannotAnswer(const Scene& scene, const SceneQuery& query,
                                              const Capabilities& caps, const std::string& label,
                                              int substeps) {
  if (!caps.buildsShape(ShapeKind::kTriangleMesh)) {
    return MeasurementStatus::skipped(
        label + " builds no triangle meshes (the scene's objects are meshes)");
  }
  const QueryKindSet asked = askedKinds(query.request.kind, substeps);
  if (!caps.queries.containsAll(asked)) {
    return MeasurementStatus::skipped(
        label + " does not answer " + queryKindsText(asked) + " queries" +
        (asked == QueryKindSet(query.request.kind)
             ? std::string()
             : std::string(" (its ") + queryKindName(query.request.kind) +
                   " by sub-steps asks them)"));
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
  int substeps = 0;  ///< BackendSpec::substeps

  ModelHandle modelAt(std::size_t object, std::size_t frame) const {
    return models.at(object)[scene.objects[object].stateAt(frame)].handle;
  }
  // The query's request in `frame`: over a step, with the poses of the frame after.
  QueryRequest requestAt(std::size_t frame) const {
    QueryRequest request = query.request;
    if (queryKindInfo(request.kind).over_a_step) {
      // A scene made in code may leave the step out: the reader's default width then.
      if (!request.step)
        request.step = StepEnd{Pose::Identity(), Pose::Identity(), kDefaultBracketWidth};
      request.step->pose_a = scene.objects[query.a].poseAt(frame + 1);
      request.step->pose_b = scene.objects[query.b].poseAt(frame + 1);
    }
    return request;
  }
  Status ask(std::size_t ia, std::size_t ib, std::size_t frame, const QueryRequest& request,
             QueryResult& result) const {
    if (substeps > 0 && queryKindInfo(request.kind).over_a_step) {
      return substepAnswer(backend, modelAt(ia, frame), scene.objects[ia].poseAt(frame),
                           modelAt(ib, frame), scene.objects[ib].poseAt(frame), request, substeps,
                           result);
    }
    return backend.query(modelAt(ia, frame), scene.objects[ia].poseAt(frame), modelAt(ib, frame),
                         scene.objects[ib].poseAt(frame), request, result);
  }
};

using Shapes = std::map<std::size_t, std::shared_ptr<const TriangleMesh>>;

// The object pairs `query` asks about in `frame`: its one pair, or those of its group it asks
// whose objects both exist then (an absent object's pairs are not the broad phase's culling).
std::size_t askedPairCount(const Scene& scene, const SceneQuery& query, std::size_t frame) {
  if (!query.isGroup()) return 1;
  const auto exists = [&](std::size_t i) { return scene.objects[i].present.contains(frame); };
  std::size_t count = 0;
  for (std::size_t i = 0; i < query.among.size(); ++i) {
    if (!exists(query.among[i])) continue;
    for (std::size_t j = i + 1; j < query.among.size(); ++j) {
      count += exists(query.among[j]) && query.asksPair(query.among[i], query.among[j]) ? 1 : 0;
    }
  }
  return count;
}

// The query's objects' shapes in `frame`.
Shapes shapesAt(const QueryRun& run, std::size_t frame) {
  Shapes shapes;
  for (std::size_t i : run.objects)
    shapes[i] = run.scene.objects[i].shapeAt(frame);
  return shapes;
}

// The query's objects that are as they were in the frame the query was last asked in
// (`previous`, with its shapes `before`; none in its first frame): the same pose, active state
// and vertices, to the bit. A query asked in some frames only compares with its last one, not
// with the frame before, which it may not have asked.
std::set<std::size_t> heldObjects(const QueryRun& run, std::size_t frame,
                                  std::optional<std::size_t> previous, const Shapes& now,
                                  const Shapes& before) {
  std::set<std::size_t> held;
  if (!previous || before.empty()) return held;
  // An answer over a step depends on the frame after too.
  if (queryKindInfo(run.query.request.kind).over_a_step) return held;
  for (std::size_t i : run.objects) {
    const SceneObject& o = run.scene.objects[i];
    if (o.poseAt(frame).matrix() != o.poseAt(*previous).matrix()) continue;
    if (o.stateAt(frame) != o.stateAt(*previous)) continue;
    const TriangleMesh& a = *now.at(i);
    const TriangleMesh& b = *before.at(i);
    if (&a != &b && a.vertices != b.vertices) continue;
    held.insert(i);
  }
  return held;
}

// Updates the frame's deforming objects to their `shapes`, but for those `held` as they were
// (their models have those positions already), timing the calls (one per object) into `record`
// when asked to; fails the measurement when an update fails.
void updateDeforming(const QueryRun& run, std::size_t frame, const Shapes& shapes,
                     const std::set<std::size_t>& held, FrameRecord* record, QueryMeasurement& m) {
  for (std::size_t i : run.objects) {
    if (run.scene.objects[i].deformation == nullptr || held.count(i) != 0) continue;
    const Clock::time_point start = Clock::now();
    UpdateCounters work;
    const Status s =
        run.backend.update(run.modelAt(i, frame), shapes.at(i)->vertices, record ? &work : nullptr);
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

// What a frame's timed calls do: the pairs asked (the candidates less the reused ones) and the
// objects held as they were in the frame before (not updated).
struct FrameWork {
  ObjectPairs asked;
  std::set<std::size_t> held;
  bool all_reused = false;  ///< every candidate pair took its answer of the frame before
};

// One timed call of frame `frame`'s `work` (a frame whose every pair is reused costs nothing);
// a call that fails marks `m` failed at that frame and gives none.
std::optional<double> timedCall(const QueryRun& run, const FrameWork& work, std::size_t frame,
                                QueryResult& result, QueryMeasurement& m) {
  if (work.all_reused) return 0.0;
  const QueryRequest request = run.requestAt(frame);
  const Result<double> took = timeFrameCall(work.asked, [&](std::size_t ia, std::size_t ib) {
    return run.ask(ia, ib, frame, request, result);
  });
  if (took.ok()) return took.value();
  m.status = frameFailure(frame, took.status().toString());
  return std::nullopt;
}

// Steps through the query's frames: each frame's shapes (deforming objects updated, timed), the
// checked call of each candidate object pair (which the observers see; with
// RunOptions::reuse_unchanged, a pair of held objects takes its answer of the frame before), the
// repeated protocol's timed calls, then the observers' frame figures. Returns each frame's work.
std::vector<FrameWork> stepFrames(const QueryRun& run, const std::optional<BroadPhase>& broad_phase,
                                  const std::vector<FrameObserver*>& observers,
                                  const RunOptions& options, std::size_t& frames_done,
                                  std::size_t frames_total, QueryMeasurement& m) {
  std::vector<FrameWork> frame_work;
  QueryResult result;
  Shapes before;
  std::optional<std::size_t> last_frame;  // the frame the query was last asked in
  std::map<std::pair<std::size_t, std::size_t>, QueryResult> last_answers;
  // The pairs asked, culled or not: counted once, unless an object of the query comes and goes.
  const bool comes_and_goes = std::any_of(run.objects.begin(), run.objects.end(), [&](auto i) {
    return !run.scene.objects[i].present.everyFrame();
  });
  const std::size_t every_pair = askedPairCount(run.scene, run.query, 0);
  for (std::size_t frame = 0; frame < run.scene.frames && m.ok(); ++frame) {
    if (!run.query.asked.contains(frame)) continue;
    const ObjectPairs candidates = objectPairsAt(broad_phase, run.query, frame);
    FrameRecord record;
    record.frame = frame;
    record.object_pairs = candidates.size();
    record.skipped_pairs =
        (comes_and_goes ? askedPairCount(run.scene, run.query, frame) : every_pair) -
        candidates.size();
    const Shapes shapes = shapesAt(run, frame);
    FrameWork work;
    if (options.reuse_unchanged) work.held = heldObjects(run, frame, last_frame, shapes, before);
    updateDeforming(run, frame, shapes, work.held, &record, m);
    if (!m.ok()) break;
    std::map<std::pair<std::size_t, std::size_t>, QueryResult> answers;
    const QueryRequest request = run.requestAt(frame);
    for (const auto& [ia, ib] : candidates) {
      const auto previous = last_answers.find({ia, ib});
      const bool reuse =
          previous != last_answers.end() && work.held.count(ia) != 0 && work.held.count(ib) != 0;
      if (reuse) {
        result = previous->second;
        ++record.reused_pairs;
      } else if (Status s = run.ask(ia, ib, frame, request, result); !s.ok()) {
        m.status = frameFailure(frame, s.toString());
        break;
      } else {
        work.asked.emplace_back(ia, ib);
      }
      if (options.reuse_unchanged) answers[{ia, ib}] = result;
      const OracleAnswer& truth = run.oracle.answerFor(run.query, ia, ib, frame);
      const AskedPair asked{frame,
                            ia,
                            ib,
                            *shapes.at(ia),
                            *shapes.at(ib),
                            run.scene.objects[ia].poseAt(frame),
                            run.scene.objects[ib].poseAt(frame),
                            request,
                            result,
                            truth};
      for (FrameObserver* observer : observers)
        observer->pair(asked, record);
      m.counts_bv_tests = result.counters.counts_bv_tests;
      m.counts_primitive_tests = result.counters.counts_primitive_tests;
      if (reuse) continue;  // no work was done for it in this frame
      record.bv_tests += result.counters.bv_tests;
      record.primitive_tests += result.counters.primitive_tests;
    }
    if (!m.ok()) break;
    work.all_reused = !candidates.empty() && record.reused_pairs == candidates.size();
    last_answers = std::move(answers);
    before = shapes;
    last_frame = frame;

    std::vector<double> frame_times;
    const int repetitions = options.protocol == TimingProtocol::kRepeated ? options.repetitions : 0;
    for (int rep = 0; rep < repetitions; ++rep) {
      const std::optional<double> took = timedCall(run, work, frame, result, m);
      if (!took) break;
      frame_times.push_back(*took);
    }
    record.median_us = quantile(frame_times, 0.5);
    if (m.ok()) {
      const SteppedFrame stepped{frame, candidates, shapes};
      for (FrameObserver* observer : observers)
        observer->frame(stepped, record);
    }
    m.times_us.insert(m.times_us.end(), frame_times.begin(), frame_times.end());
    m.frames.push_back(std::move(record));
    frame_work.push_back(std::move(work));
    if (options.frame_progress) options.frame_progress(++frames_done, frames_total);
  }
  return frame_work;
}

// The cycled protocol's timed passes: each pass asks every frame once, in order, so that no
// call finds the previous one's data in cache. A deforming object is updated to each frame
// first, untimed (not when held as it was in the frame before, which the pass asked just
// before). Each frame's median is over its calls; times_us holds every call.
void timeCycled(const QueryRun& run, const std::vector<FrameWork>& work, int repetitions,
                QueryMeasurement& m) {
  std::vector<std::vector<double>> times(m.frames.size());
  QueryResult result;
  for (int rep = 0; rep < repetitions && m.ok(); ++rep) {
    for (std::size_t k = 0; k < m.frames.size() && m.ok(); ++k) {
      const std::size_t frame = m.frames[k].frame;
      updateDeforming(run, frame, shapesAt(run, frame), work[k].held, nullptr, m);
      if (!m.ok()) break;
      const std::optional<double> took = timedCall(run, work[k], frame, result, m);
      if (!took) break;
      times[k].push_back(*took);
    }
  }
  for (std::size_t k = 0; k < m.frames.size(); ++k) {
    m.frames[k].median_us = quantile(times[k], 0.5);
    m.times_us.insert(m.times_us.end(), times[k].begin(), times[k].end());
  }
}

// The repeated protocol's figure after the cycled passes: each frame in turn gets one untimed
// call, which brings its data into cache, then `calls` timed calls back to back. One figure per
// process: the mean over frames of each frame's median.
void timeRepeatedAfterCycled(const QueryRun& run, const std::vector<FrameWork>& work, int calls,
                             QueryMeasurement& m) {
  QueryResult result;
  double sum = 0.0;
  for (std::size_t k = 0; k < m.frames.size(); ++k) {
    const std::size_t frame = m.frames[k].frame;
    updateDeforming(run, frame, shapesAt(run, frame), work[k].held, nullptr, m);
    if (!m.ok()) return;
    std::vector<double> times;
    for (int call = -1; call < calls; ++call) {
      const std::optional<double> took = timedCall(run, work[k], frame, result, m);
      if (!took) return;
      if (call >= 0) times.push_back(*took);
    }
    sum += quantile(times, 0.5);
  }
  if (!m.frames.empty()) m.repeated_us = sum / static_cast<double>(m.frames.size());
}

}  // namespace

QueryKindSet askedKinds(QueryKindSet kinds, int substeps) {
  if (substeps <= 0) return kinds;
  QueryKindSet asked;
  for (const QueryKindInfo& kind : kQueryKinds) {
    if (!kinds.contains(kind.kind)) continue;
    asked |= kind.over_a_step ? QueryKindSet(QueryKind::kBoolean) : QueryKindSet(kind.kind);
  }
  return asked;
}

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
      BackendInstance::create(spec.library, spec.variant, spec.pluginOptions());
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
                                 ? buildSceneModels(scene, backend, options, label, spec.substeps())
                                 : SceneModels();

  // Objects posed from tracked markers: the same scene at the true poses, whose exact answers
  // say what tracking error did to the collision answer.
  const Scene truth_scene = scene.hasTrackedObjects() ? scene.withTruePoses() : Scene{};
  std::optional<OracleCache> truth_oracle;
  if (scene.hasTrackedObjects()) truth_oracle.emplace(truth_scene, /*witness_only=*/true);

  std::size_t frames_done = 0;
  std::size_t frames_total = 0;
  for (const SceneQuery& query : scene.queries)
    frames_total += query.asked.countIn(scene.frames);
  for (const SceneQuery& query : scene.queries) {
    QueryMeasurement m = measurementOf(query);
    m.protocol = options.protocol;
    if (std::optional<MeasurementStatus> skipped =
            cannotAnswer(scene, query, caps, label, spec.substeps())) {
      m.status = *skipped;
      report.measurements.push_back(m);
      continue;
    }
    const QueryRun run{scene, query, query.objects(), models, backend, oracle, spec.substeps()};
    if (const std::string error = buildError(models, run.objects); !error.empty()) {
      m.status = MeasurementStatus::failed("build: " + error);
      report.measurements.push_back(m);
      continue;
    }
    addBuildFigures(scene, models, run.objects, m);
    if (options.progress) {
      options.progress(label + ": " + scene.name + " / " + query.name + " (" +
                       std::to_string(query.asked.countIn(scene.frames)) + " frames)");
    }

    // The observers this scene and these options call for.
    OracleComparison comparison;
    std::optional<AnswerKeeper> keeper;
    std::optional<FloorTimer> floor;
    std::optional<FinestComparison> finest;
    std::optional<TrackingComparison> tracking;
    std::vector<FrameObserver*> observers{&comparison};
    if (options.keep_answers) observers.push_back(&keeper.emplace());
    const QueryKindInfo& kind = queryKindInfo(query.request.kind);
    if (kind.has(AnswerPart::kPairSet)) observers.push_back(&floor.emplace(options.repetitions));
    if (finest_oracle != nullptr) observers.push_back(&finest.emplace(*finest_oracle, query));
    if (truth_oracle) {
      observers.push_back(&tracking.emplace(scene, *truth_oracle, query, options.tracking_sigmas));
    }
    std::vector<std::unique_ptr<FrameObserver>> checks;
    for (const std::unique_ptr<Check>& check : registeredChecks()) {
      if (std::unique_ptr<FrameObserver> observer = check->observe(query)) {
        observers.push_back(observer.get());
        checks.push_back(std::move(observer));
      }
    }

    std::optional<BroadPhase> broad_phase;
    // A distance has an answer however far apart: only collision questions can be culled.
    if (query.isGroup() || (options.skip_apart_pairs && kind.settled_when_apart)) {
      broad_phase.emplace(scene, query);
    }
    const std::vector<FrameWork> work =
        stepFrames(run, broad_phase, observers, options, frames_done, frames_total, m);
    if (options.protocol == TimingProtocol::kCycled && m.ok())
      timeCycled(run, work, options.repetitions, m);
    if (options.protocol == TimingProtocol::kCycled && options.repeated_calls > 0 && m.ok())
      timeRepeatedAfterCycled(run, work, options.repeated_calls, m);
    summariseMeasurement(m);
    report.measurements.push_back(std::move(m));
  }
  releaseModels(backend, models);
}

}  // namespace collido::detail
