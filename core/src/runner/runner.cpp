// The runner: every backend on every query of every scene, each answer checked against the exact
// oracle, each query timed.
//
// Timing: per frame, one untimed warm-up call (whose answer is the one checked), then
// `repetitions` timed calls with a steady clock around the whole interface call, so every
// backend pays the same boundary cost. Caches are warm by construction; medians and p90 are
// over all timed calls of the query.
// Memory: the backend's own figure, and the C heap's growth across build measured by the probe.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include <collido/host/backend_instance.h>
#include <collido/oracle/distance_oracle.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/oracle/proximity.h>
#include <collido/oracle/triangle_distance.h>
#include <collido/runner/floor.h>
#include <collido/runner/heap_probe.h>
#include <collido/runner/runner.h>
#include <collido/runner/statistics.h>
#include <collido/runner/timed_calls.h>
#include <collido/scene/broad_phase.h>

namespace collido {
namespace {

using Clock = std::chrono::steady_clock;

double microseconds(Clock::duration d) {
  return std::chrono::duration<double, std::micro>(d).count();
}

struct BuiltModel {
  ModelHandle handle = 0;
  double build_ms = 0.0;
  std::size_t memory_bytes = 0;
  std::optional<std::size_t> heap_bytes;
  std::optional<std::size_t> heap_peak_bytes;
  std::optional<std::uint64_t> heap_allocations;
  std::string error;  // non-empty when the build failed
};

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
  built.build_ms = microseconds(stop - start) / 1000.0;
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

void summariseMeasurement(QueryMeasurement& m) {
  m.median_us = quantile(m.times_us, 0.5);
  m.p90_us = quantile(m.times_us, 0.9);
  m.p99_us = quantile(m.times_us, 0.99);
  m.max_us = m.times_us.empty() ? 0.0 : *std::max_element(m.times_us.begin(), m.times_us.end());
  m.false_negatives = 0;
  m.false_positives = 0;
  m.disagreements = 0;
  m.finest_disagreements.reset();
  m.tracking_false_contacts.reset();
  m.tracking_missed_contacts.reset();
  m.tracking_possible_contacts.reset();
  m.tracking_missed_within_margin.reset();
  std::size_t oracle_pairs = 0;
  std::size_t reported_pairs = 0;
  std::size_t matched_pairs = 0;
  double timed_with_floor_us = 0.0;
  double floor_us = 0.0;
  std::vector<double> updates_us;
  m.update_rebuilds.reset();
  m.max_distance_error.reset();
  m.max_relative_distance_error.reset();
  m.contact.reset();
  for (const FrameRecord& f : m.frames) {
    if (f.contact) {
      if (!m.contact) m.contact.emplace();
      m.contact->add(*f.contact);
    }
    if (f.oracle_distance && f.reported_distance) {
      const double error = std::abs(*f.reported_distance - *f.oracle_distance);
      m.max_distance_error = std::max(m.max_distance_error.value_or(0.0), error);
      if (*f.oracle_distance > 0.0) {
        m.max_relative_distance_error =
            std::max(m.max_relative_distance_error.value_or(0.0), error / *f.oracle_distance);
      }
    }
    if (f.update_us) updates_us.push_back(*f.update_us);
    if (f.update_work.counted)
      m.update_rebuilds = m.update_rebuilds.value_or(0) + f.update_work.rebuilds;
    if (f.floor_us) {
      timed_with_floor_us += f.median_us;
      floor_us += *f.floor_us;
    }
    if (f.oracle_intersecting && !f.reported_intersecting) ++m.false_negatives;
    if (!f.oracle_intersecting && f.reported_intersecting) ++m.false_positives;
    if (f.disagrees(m.kind)) ++m.disagreements;
    if (f.truth_intersecting) {
      m.tracking_false_contacts = m.tracking_false_contacts.value_or(0) +
                                  (f.oracle_intersecting && !*f.truth_intersecting ? 1 : 0);
      m.tracking_missed_contacts = m.tracking_missed_contacts.value_or(0) +
                                   (!f.oracle_intersecting && *f.truth_intersecting ? 1 : 0);
    }
    if (f.possible_contact) {
      m.tracking_possible_contacts =
          m.tracking_possible_contacts.value_or(0) + (*f.possible_contact ? 1 : 0);
      m.tracking_missed_within_margin =
          m.tracking_missed_within_margin.value_or(0) +
          (f.truth_intersecting.value_or(false) && !*f.possible_contact ? 1 : 0);
    }
    if (f.finest_intersecting) {
      m.finest_disagreements = m.finest_disagreements.value_or(0) +
                               (*f.finest_intersecting != f.reported_intersecting ? 1 : 0);
    }
    oracle_pairs += f.oracle_pairs;
    reported_pairs += f.reported_pairs;
    matched_pairs += f.matched_pairs;
  }
  if (m.kind == QueryKind::kAllPairs) {
    m.recall = oracle_pairs == 0 ? 1.0 : static_cast<double>(matched_pairs) / oracle_pairs;
    m.precision = reported_pairs == 0 ? 1.0 : static_cast<double>(matched_pairs) / reported_pairs;
  }
  m.floor_ratio.reset();
  if (floor_us > 0.0) m.floor_ratio = timed_with_floor_us / floor_us;
  m.update_median_us.reset();
  if (!updates_us.empty()) m.update_median_us = quantile(updates_us, 0.5);
}

namespace {

// Adds one object pair's answer to a frame's record (a group query's frame sums its pairs).
void addAnswer(const FrameRecord& one, FrameRecord& frame) {
  frame.oracle_intersecting = frame.oracle_intersecting || one.oracle_intersecting;
  frame.reported_intersecting = frame.reported_intersecting || one.reported_intersecting;
  frame.oracle_pairs += one.oracle_pairs;
  frame.reported_pairs += one.reported_pairs;
  frame.matched_pairs += one.matched_pairs;
  frame.invalid_pairs += one.invalid_pairs;
  frame.truncated = frame.truncated || one.truncated;
  // Distance queries name two objects, never a group: one answer per frame.
  frame.oracle_distance = one.oracle_distance;
  frame.reported_distance = one.reported_distance;
  frame.distance_below = one.distance_below;
  frame.distance_above = one.distance_above;
  frame.invalid_distance_witness = one.invalid_distance_witness;
  if (one.contact) {
    if (!frame.contact) frame.contact.emplace();
    frame.contact->add(*one.contact);
  }
}

// The object pairs a query asks in `frame`: its pair, or those of a group the shared broad phase
// keeps. The run and the oracle's precomputation must ask the same ones.
std::vector<std::pair<std::size_t, std::size_t>> objectPairsAt(
    const std::optional<BroadPhase>& broad_phase, const SceneQuery& query, std::size_t frame) {
  if (broad_phase) return broad_phase->pairsAt(frame);
  return {{query.a, query.b}};
}

// Whether another version of the scene (the finest meshes, the true poses) intersects in
// `frame`: for a group query, whether any pair does (that scene's own broad phase picks the
// candidates).
bool otherIntersecting(OracleCache& other, const SceneQuery& query,
                       const BroadPhase* other_broad_phase, std::size_t frame) {
  if (other_broad_phase == nullptr) return other.get(query.a, query.b, frame).intersecting;
  for (const auto& [ia, ib] : other_broad_phase->pairsAt(frame)) {
    if (other.get(ia, ib, frame).intersecting) return true;
  }
  return false;
}

// The "possible contact within tracking error" answer: whether some candidate object pair
// comes within `sigmas` times the sum of its objects' predicted spreads (tracked objects and
// those mounted on them). Left unset when a spread is unknown (no redundant marker, or a lost
// frame).
void possibleContact(const Scene& scene,
                     const std::vector<std::pair<std::size_t, std::size_t>>& candidates,
                     const std::map<std::size_t, std::shared_ptr<const TriangleMesh>>& shapes,
                     std::size_t frame, double sigmas, FrameRecord& record) {
  bool possible = false;
  double widest = 0.0;
  for (const auto& [ia, ib] : candidates) {
    double margin = 0.0;
    for (std::size_t i : {ia, ib}) {
      const double sigma = scene.trackingSpreadAt(i, *shapes.at(i), frame);
      if (std::isnan(sigma)) return;
      margin += sigmas * sigma;
    }
    widest = std::max(widest, margin);
    if (!possible) {
      possible = meshesWithinDistance(*shapes.at(ia), scene.objects[ia].poseAt(frame),
                                      *shapes.at(ib), scene.objects[ib].poseAt(frame), margin)
                     .within;
    }
  }
  record.possible_contact = possible;
  record.tracking_margin = widest;
}

void say(const RunOptions& options, const std::string& line) {
  if (options.progress) options.progress(line);
}

// One timed call of a frame: every candidate object pair asked once, in microseconds, or the
// failure that stopped it. Both timing protocols time frames this way.
template <typename Ask>
Result<double> timeFrameCall(const std::vector<std::pair<std::size_t, std::size_t>>& candidates,
                             const Ask& ask) {
  return timeCall([&]() -> Status {
    for (const auto& [ia, ib] : candidates) {
      if (Status s = ask(ia, ib); !s.ok()) return s;
    }
    return {};
  });
}

// The cycled protocol's timed passes: each pass asks every frame once, in order, so that no
// call finds the previous one's data in cache. A deforming object is updated to each frame
// first, untimed. Each frame's median is over its calls; times_us holds every call.
void timeCycled(const Scene& scene, const SceneQuery& query,
                const std::vector<std::size_t>& objects,
                const std::map<std::size_t, std::vector<BuiltModel>>& models,
                BackendInstance& backend,
                const std::vector<std::vector<std::pair<std::size_t, std::size_t>>>& candidates,
                int repetitions, QueryMeasurement& m) {
  std::vector<std::vector<double>> times(m.frames.size());
  QueryResult result;
  for (int rep = 0; rep < repetitions && m.ok(); ++rep) {
    for (std::size_t k = 0; k < m.frames.size() && m.ok(); ++k) {
      const std::size_t frame = m.frames[k].frame;
      const auto modelAt = [&](std::size_t i) {
        return models.at(i)[scene.objects[i].stateAt(frame)].handle;
      };
      for (std::size_t i : objects) {
        if (scene.objects[i].deformation == nullptr) continue;
        if (Status s =
                backend.update(modelAt(i), scene.objects[i].shapeAt(frame)->vertices, nullptr);
            !s.ok()) {
          m.status = MeasurementStatus::failed("frame " + std::to_string(frame) + ": update " +
                                               scene.objects[i].name + ": " + s.toString());
        }
      }
      if (!m.ok()) break;
      const Result<double> took = timeFrameCall(candidates[k], [&](std::size_t ia, std::size_t ib) {
        return backend.query(modelAt(ia), scene.objects[ia].poseAt(frame), modelAt(ib),
                             scene.objects[ib].poseAt(frame), query.request, result);
      });
      if (!took.ok()) {
        m.status = MeasurementStatus::failed("frame " + std::to_string(frame) + ": " +
                                             took.status().toString());
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

void runSceneOnBackend(const Scene& scene, const BackendSpec& spec, OracleCache& oracle,
                       OracleCache* finest_oracle, const RunOptions& options, RunReport& report) {
  const std::string label = spec.label();
  const auto record_all = [&](const MeasurementStatus& status) {
    for (const SceneQuery& q : scene.queries) {
      QueryMeasurement m;
      m.backend = label;
      m.scene = scene.name;
      m.query = q.name;
      m.kind = q.request.kind;
      m.status = status;
      report.measurements.push_back(m);
    }
  };
  Result<std::unique_ptr<BackendInstance>> created =
      BackendInstance::create(spec.library, spec.variant, spec.options);
  if (!created.ok()) {
    report.problems.push_back(created.status().message());
    record_all(MeasurementStatus::failed(created.status().message()));
    return;
  }
  BackendInstance& backend = *created.value();
  const Capabilities& caps = backend.capabilities();

  // Build what the scene needs, restricted to what the backend answers; queries it cannot answer
  // are skipped below with the reason.
  // One model per active state of each object (an object without states has one), built ahead:
  // switching states selects a model.
  std::map<std::size_t, std::vector<BuiltModel>> models;
  const bool builds_meshes = caps.buildsShape(ShapeKind::kTriangleMesh);
  for (std::size_t index : scene.queriedObjects()) {
    if (!builds_meshes) break;  // every query is skipped below
    BuildNeeds needs = scene.needsOf(index);
    if (options.build_every_need) needs.queries = caps.queries;
    needs.queries = QueryKindSet(needs.queries.bits() & caps.queries.bits());
    if (needs.queries.empty()) continue;
    const SceneObject& object = scene.objects[index];
    say(options, label + ": building " + object.name);
    for (std::size_t state = 0; state < object.stateCount(); ++state) {
      // A state with the first state's triangle list is built as its sibling: the backend may
      // share what does not depend on positions (the study's memory counts what it shares once).
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

  // Objects posed from tracked markers: the same scene at the true poses, whose exact answers
  // say what tracking error did to the collision answer.
  const Scene truth_scene = scene.hasTrackedObjects() ? scene.withTruePoses() : Scene{};
  std::optional<OracleCache> truth_oracle;
  if (scene.hasTrackedObjects()) truth_oracle.emplace(truth_scene, /*witness_only=*/true);

  std::size_t frames_done = 0;
  const std::size_t frames_total = scene.frames * scene.queries.size();
  for (const SceneQuery& query : scene.queries) {
    QueryMeasurement m;
    m.backend = label;
    m.scene = scene.name;
    m.query = query.name;
    m.kind = query.request.kind;
    m.protocol = timingProtocolName(options.protocol);
    if (!builds_meshes) {
      m.status = MeasurementStatus::skipped(
          label + " builds no triangle meshes (the scene's objects are meshes)");
      report.measurements.push_back(m);
      continue;
    }
    if (!caps.queries.contains(query.request.kind)) {
      m.status = MeasurementStatus::skipped(label + " does not answer " +
                                            queryKindName(query.request.kind) + " queries");
      report.measurements.push_back(m);
      continue;
    }
    const std::vector<std::size_t> objects = query.objects();
    const auto deforms = [&](std::size_t i) { return scene.objects[i].deformation != nullptr; };
    if (!caps.update && std::any_of(objects.begin(), objects.end(), deforms)) {
      m.status = MeasurementStatus::skipped(
          label + " does not update models (the scene deforms an object)");
      report.measurements.push_back(m);
      continue;
    }
    std::string build_error;
    for (std::size_t i : objects) {
      for (const BuiltModel& model : models[i]) {
        if (build_error.empty() && !model.error.empty()) build_error = model.error;
      }
    }
    if (!build_error.empty()) {
      m.status = MeasurementStatus::failed("build: " + build_error);
      report.measurements.push_back(m);
      continue;
    }
    std::optional<std::size_t> heap_bytes = 0;
    std::optional<std::size_t> heap_peak_bytes = 0;
    std::optional<std::uint64_t> heap_allocations = 0;
    for (std::size_t index : objects) {
      m.triangles += scene.objects[index].mesh->triangleCount();
      for (const BuiltModel& model : models[index]) {
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
    say(options, label + ": " + scene.name + " / " + query.name + " (" +
                     std::to_string(scene.frames) + " frames)");

    std::optional<BroadPhase> broad_phase;
    std::optional<BroadPhase> finest_broad_phase;
    std::optional<BroadPhase> truth_broad_phase;
    if (query.isGroup()) {
      broad_phase.emplace(scene, query);
      if (finest_oracle != nullptr) finest_broad_phase.emplace(finest_oracle->scene(), query);
      if (truth_oracle) truth_broad_phase.emplace(truth_scene, query);
    }
    QueryResult result;
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> frame_candidates;
    for (std::size_t frame = 0; frame < scene.frames && m.ok(); ++frame) {
      const std::vector<std::pair<std::size_t, std::size_t>> candidates =
          objectPairsAt(broad_phase, query, frame);
      FrameRecord record;
      record.frame = frame;
      record.object_pairs = candidates.size();
      // This frame's shapes: the active state's model, its movable nodes updated (timed).
      std::map<std::size_t, std::shared_ptr<const TriangleMesh>> shapes;
      const auto modelAt = [&](std::size_t i) {
        return models[i][scene.objects[i].stateAt(frame)].handle;
      };
      for (std::size_t i : objects) {
        shapes[i] = scene.objects[i].shapeAt(frame);
        if (!deforms(i)) continue;
        const Clock::time_point start = Clock::now();
        UpdateCounters work;
        const Status s = backend.update(modelAt(i), shapes[i]->vertices, &work);
        const Clock::time_point stop = Clock::now();
        if (!s.ok()) {
          m.status = MeasurementStatus::failed("frame " + std::to_string(frame) + ": update " +
                                               scene.objects[i].name + ": " + s.toString());
          break;
        }
        record.update_us = record.update_us.value_or(0.0) + microseconds(stop - start);
        if (work.counted) {
          record.update_work.counted = true;
          record.update_work.nodes_refit += work.nodes_refit;
          record.update_work.rebuilds += work.rebuilds;
          record.update_work.nodes_rebuilt += work.nodes_rebuilt;
        }
      }
      if (!m.ok()) break;
      const auto ask = [&](std::size_t ia, std::size_t ib) {
        return backend.query(modelAt(ia), scene.objects[ia].poseAt(frame), modelAt(ib),
                             scene.objects[ib].poseAt(frame), query.request, result);
      };
      std::vector<WorldTrianglePair> true_pairs;
      for (const auto& [ia, ib] : candidates) {
        if (Status s = ask(ia, ib); !s.ok()) {
          m.status =
              MeasurementStatus::failed("frame " + std::to_string(frame) + ": " + s.toString());
          break;
        }
        const SceneObject& a = scene.objects[ia];
        const SceneObject& b = scene.objects[ib];
        FrameRecord one;
        const OracleAnswer& truth =
            oracle.get(ia, ib, frame, query.request.kind == QueryKind::kDistance);
        const TriangleMesh& shape_a = *shapes[ia];
        const TriangleMesh& shape_b = *shapes[ib];
        compareWithOracle(shape_a, a.poseAt(frame), shape_b, b.poseAt(frame), query.request, result,
                          truth, one);
        if (query.request.kind == QueryKind::kAllPairs)
          appendWorldPairs(shape_a, a.poseAt(frame), shape_b, b.poseAt(frame), truth.pairs,
                           true_pairs);
        addAnswer(one, record);
        if (options.keep_answers) {
          PairAnswers kept{ia, ib, result, truth.intersecting, truth.pairs, std::nullopt};
          if (truth.distance) {
            DistanceResult exact;
            exact.distance = truth.distance->distance;
            exact.point_a = truth.distance->point_a;
            exact.point_b = truth.distance->point_b;
            exact.triangle_a = truth.distance->pair.a;
            exact.triangle_b = truth.distance->pair.b;
            kept.oracle_distance = exact;
          }
          record.answers.push_back(std::move(kept));
        }
        record.bv_tests += result.counters.bv_tests;
        record.primitive_tests += result.counters.primitive_tests;
        m.counts_bv_tests = result.counters.counts_bv_tests;
        m.counts_primitive_tests = result.counters.counts_primitive_tests;
      }
      if (!m.ok()) break;
      if (finest_oracle != nullptr) {
        record.finest_intersecting = otherIntersecting(
            *finest_oracle, query, finest_broad_phase ? &*finest_broad_phase : nullptr, frame);
      }
      if (truth_oracle) {
        record.truth_intersecting = otherIntersecting(
            *truth_oracle, query, truth_broad_phase ? &*truth_broad_phase : nullptr, frame);
        possibleContact(scene, candidates, shapes, frame, options.tracking_sigmas, record);
      }

      std::vector<double> frame_times;
      const int repetitions =
          options.protocol == TimingProtocol::kRepeated ? options.repetitions : 0;
      for (int rep = 0; rep < repetitions && m.ok(); ++rep) {
        const Result<double> took = timeFrameCall(candidates, ask);
        if (!took.ok()) {
          m.status = MeasurementStatus::failed("frame " + std::to_string(frame) + ": " +
                                               took.status().toString());
          break;
        }
        frame_times.push_back(took.value());
      }
      record.median_us = quantile(frame_times, 0.5);
      if (query.request.kind == QueryKind::kAllPairs && m.ok())
        record.floor_us = floorMicroseconds(true_pairs, options.repetitions);
      m.times_us.insert(m.times_us.end(), frame_times.begin(), frame_times.end());
      m.frames.push_back(record);
      frame_candidates.push_back(candidates);
      if (options.frame_progress) options.frame_progress(++frames_done, frames_total);
    }
    if (options.protocol == TimingProtocol::kCycled && m.ok()) {
      timeCycled(scene, query, objects, models, backend, frame_candidates, options.repetitions, m);
    }
    summariseMeasurement(m);
    report.measurements.push_back(std::move(m));
  }
  for (const auto& [index, states] : models) {
    for (const BuiltModel& model : states) {
      if (model.error.empty()) (void)backend.release(model.handle);
    }
  }
}

}  // namespace

namespace {

// The distance answer against the exact one: within rounding below, within tolerance and
// rounding above; points the reported distance apart and on their triangles; a certified
// interval that holds the exact distance.
void compareDistance(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                     const Pose& pose_b, const QueryRequest& request, const DistanceResult& d,
                     const MeshDistance& truth, FrameRecord& record) {
  const double magnitude = std::max((pose_a * a.vertices).cwiseAbs().maxCoeff(),
                                    (pose_b * b.vertices).cwiseAbs().maxCoeff());
  const double rounding = 1e-10 * magnitude;
  record.oracle_distance = truth.distance;
  record.reported_distance = d.distance;
  record.distance_below = rounding;
  record.distance_above =
      rounding + std::max(request.abs_tolerance, request.rel_tolerance * truth.distance);
  record.oracle_intersecting = truth.distance == 0.0;
  // Contact is a distance of exactly 0 (or a negative, penetration-signed one): a tiny positive
  // distance says the meshes are apart, however close to rounding it is.
  record.reported_intersecting = d.distance <= 0.0;
  bool invalid = std::abs((d.point_b - d.point_a).norm() - d.distance) > rounding;
  // Decided exactly (the point as a zero-area triangle against the posed one): a double
  // closest point on a sliver can be off by far more than the rounding allowed here.
  const auto off_triangle = [&](const TriangleMesh& mesh, const Pose& pose, std::int32_t t,
                                const Eigen::Vector3d& p) {
    if (t < 0) return false;
    if (static_cast<std::size_t>(t) >= mesh.triangleCount()) return true;
    std::array<Eigen::Vector3d, 3> corners;
    for (int k = 0; k < 3; ++k)
      corners[static_cast<std::size_t>(k)] = mesh.corner(static_cast<std::size_t>(t), k);
    const double squared =
        exactPosedClosestPoints({p, p, p}, Pose::Identity(), corners, pose).squared_distance.lower;
    return std::sqrt(squared) > rounding;
  };
  invalid = invalid || off_triangle(a, pose_a, d.triangle_a, d.point_a) ||
            off_triangle(b, pose_b, d.triangle_b, d.point_b);
  if (d.lower && d.upper) {
    invalid =
        invalid || *d.lower > truth.distance + rounding || *d.upper < truth.distance - rounding;
  }
  record.invalid_distance_witness = invalid;
}

}  // namespace

void compareWithOracle(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                       const Pose& pose_b, const QueryRequest& request, const QueryResult& result,
                       const OracleAnswer& truth, FrameRecord& record) {
  const QueryKind kind = request.kind;
  record.oracle_intersecting = truth.intersecting;
  record.reported_intersecting = result.intersecting;
  record.truncated = result.truncated;
  const auto in_range = [&](const TrianglePair& p) {
    return p.a >= 0 && static_cast<std::size_t>(p.a) < a.triangleCount() && p.b >= 0 &&
           static_cast<std::size_t>(p.b) < b.triangleCount();
  };
  std::vector<TrianglePair> reported;
  for (const TrianglePair& p : result.pairs) {
    if (in_range(p)) {
      reported.push_back(p);
    } else {
      ++record.invalid_pairs;
    }
  }
  if (kind == QueryKind::kDistance) {
    if (truth.distance) {
      compareDistance(a, pose_a, b, pose_b, request, result.distance, *truth.distance, record);
    }
    return;
  }
  std::sort(reported.begin(), reported.end());
  const std::size_t before_dedupe = reported.size();
  reported.erase(std::unique(reported.begin(), reported.end()), reported.end());
  record.invalid_pairs += before_dedupe - reported.size();

  if (kind == QueryKind::kContacts) {
    record.oracle_pairs = truth.pairs.size();
    record.contact = scoreContacts(a, pose_a, b, pose_b, truth.pairs, result.contacts);
    return;
  }
  if (kind == QueryKind::kBoolean) {
    // A witness, when given, must really intersect.
    for (const TrianglePair& p : reported) {
      if (!exactPairIntersects(a, pose_a, b, pose_b, p)) {
        ++record.invalid_pairs;
      }
    }
    return;
  }
  record.oracle_pairs = truth.pairs.size();
  record.reported_pairs = reported.size();
  std::vector<TrianglePair> matched;
  std::set_intersection(reported.begin(), reported.end(), truth.pairs.begin(), truth.pairs.end(),
                        std::back_inserter(matched));
  record.matched_pairs = matched.size();
}

bool FrameRecord::disagrees(QueryKind kind) const {
  if (kind == QueryKind::kDistance) {
    if (!oracle_distance || !reported_distance) return true;
    return invalid_distance_witness || *reported_distance < *oracle_distance - distance_below ||
           *reported_distance > *oracle_distance + distance_above;
  }
  if (oracle_intersecting != reported_intersecting || invalid_pairs != 0) return true;
  if (kind == QueryKind::kContacts) return contact && contact->anyWrong();
  if (kind != QueryKind::kAllPairs) return false;
  // A truncated answer is right when every pair it gives is real and some were left out.
  if (truncated) return matched_pairs != reported_pairs || reported_pairs >= oracle_pairs;
  return matched_pairs != oracle_pairs || matched_pairs != reported_pairs;
}

const char* timingProtocolName(TimingProtocol protocol) {
  return protocol == TimingProtocol::kCycled ? "cycled" : "repeated";
}

std::optional<TimingProtocol> parseTimingProtocol(const std::string& name) {
  if (name == "repeated") return TimingProtocol::kRepeated;
  if (name == "cycled") return TimingProtocol::kCycled;
  return std::nullopt;
}

void precomputeOracleAnswers(OracleCache& oracle, bool distances) {
  const Scene& scene = oracle.scene();
  for (const SceneQuery& query : scene.queries) {
    std::optional<BroadPhase> broad_phase;
    if (query.isGroup()) broad_phase.emplace(scene, query);
    const bool distance = distances && query.request.kind == QueryKind::kDistance;
    for (std::size_t frame = 0; frame < scene.frames; ++frame) {
      const std::vector<std::pair<std::size_t, std::size_t>> candidates =
          objectPairsAt(broad_phase, query, frame);
      for (const auto& [ia, ib] : candidates)
        (void)oracle.get(ia, ib, frame, distance);
    }
  }
}

RunReport runScenes(const std::vector<Scene>& scenes, const std::vector<BackendSpec>& backends,
                    const RunOptions& options) {
  RunReport report;
  for (const Scene& scene : scenes) {
    OracleCache oracle(scene);
    runSceneOnBackends(scene, backends, options, oracle, report);
  }
  return report;
}

void runSceneOnBackends(const Scene& scene, const std::vector<BackendSpec>& backends,
                        const RunOptions& options, OracleCache& oracle, RunReport& report) {
  for (const BackendSpec& spec : backends) {
    runSceneOnBackend(scene, spec, oracle, nullptr, options, report);
  }
}

RunReport runScene(const Scene& scene, const BackendSpec& backend, const RunOptions& options,
                   OracleCache& oracle, OracleCache* finest_oracle) {
  RunReport report;
  runSceneOnBackend(scene, backend, oracle, finest_oracle, options, report);
  return report;
}

RunReport runScene(const Scene& scene, const BackendSpec& backend, const RunOptions& options,
                   const Scene* finest) {
  RunReport report;
  OracleCache oracle(scene);
  std::optional<OracleCache> finest_oracle;
  if (finest != nullptr) finest_oracle.emplace(*finest, /*witness_only=*/true);
  runSceneOnBackend(scene, backend, oracle, finest_oracle ? &*finest_oracle : nullptr, options,
                    report);
  return report;
}

}  // namespace collido
