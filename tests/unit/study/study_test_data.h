#pragma once

// Hand-made measurements and results for the study's unit tests, with figures simple enough to
// check by hand.
#include <csignal>
#include <string>

#include <collido/runner/checks.h>
#include <collido/runner/runner.h>
#include <collido/study/plan.h>
#include <collido/study/result_store.h>

namespace collido::study::testdata {

/// A combination of the scene "tori" on `backend`, with the id the planner gives it.
inline Combination combination(const std::string& backend, NeedsMode needs = NeedsMode::kDeclared,
                               double resolution = 1.0) {
  Sweep sweep;
  sweep.needs = {needs};
  sweep.resolutions = {resolution};
  return planStudy({{"/scenes/tori.json", "tori", true}}, {backend}, sweep).front();
}

/// A measurement of `backend` on `scene`'s query `query`, with nothing measured yet.
inline QueryMeasurement named(const std::string& backend, const std::string& scene,
                              const std::string& query, QueryKind kind) {
  QueryMeasurement m;
  m.backend = backend;
  m.scene = scene;
  m.query = query;
  m.kind = kind;
  return m;
}

/// An all-pairs measurement of three frames:
///   frame 0: intersecting, 6 exact pairs, all 6 reported        (agrees)
///   frame 1: intersecting, 4 exact pairs, reported disjoint     (disagrees, false negative)
///   frame 2: disjoint, reported disjoint, finest mesh intersects (agrees; coarse error)
/// Timed calls 10, 20, 40 us: median 20, max 40; recall 6/10, precision 1.
/// `hooks`: with the optional figures (heap counts, finest truth, work counters).
inline QueryMeasurement pairsMeasurement(const std::string& backend, bool hooks) {
  QueryMeasurement m = named(backend, "tori", "all_pairs", QueryKind::kAllPairs);
  m.times_us = {10.0, 20.0, 40.0};
  const bool oracle[3] = {true, true, false};
  const bool reported[3] = {true, false, false};
  const std::size_t exact[3] = {6, 4, 0};
  const std::size_t given[3] = {6, 0, 0};
  const bool finest[3] = {true, false, true};
  for (std::size_t i = 0; i < 3; ++i) {
    FrameRecord f;
    f.frame = i;
    f.oracle_intersecting = oracle[i];
    f.reported_intersecting = reported[i];
    f.oracle_pairs = exact[i];
    f.reported_pairs = given[i];
    f.matched_pairs = given[i];
    f.median_us = m.times_us[i];
    if (hooks) {
      f.finest_intersecting = finest[i];
      f.bv_tests = 100 + i;
      f.primitive_tests = 10 + i;
    }
    m.frames.push_back(f);
  }
  m.counts_bv_tests = hooks;
  m.counts_primitive_tests = hooks;
  m.build_ms = 1.25;
  m.triangles = 1000;
  m.memory_bytes = 300000;
  if (hooks) {
    m.heap_bytes = 310000;
    m.heap_peak_bytes = 450000;
    m.heap_allocations = 37;
    m.heap_probe = "hooks";
  } else {
    m.heap_probe = "none";
  }
  summariseMeasurement(m);
  return m;
}

/// A boolean measurement of two frames, both right.
inline QueryMeasurement booleanMeasurement(const std::string& backend) {
  QueryMeasurement m = named(backend, "tori", "boolean", QueryKind::kBoolean);
  m.times_us = {2.0, 3.0, 2.5, 3.5};
  for (std::size_t i = 0; i < 2; ++i) {
    FrameRecord f;
    f.frame = i;
    f.oracle_intersecting = i == 0;
    f.reported_intersecting = i == 0;
    f.median_us = 2.5 + static_cast<double>(i);
    m.frames.push_back(f);
  }
  m.build_ms = 0.5;
  m.triangles = 1000;
  m.memory_bytes = 64000;
  m.heap_bytes = 64000;
  m.heap_probe = "mallinfo2";
  summariseMeasurement(m);
  return m;
}

/// A contacts query whose frames carry every optional figure a run can record (tracking, distance,
/// first contact, contacts, floor, update work), timed under the cycled protocol in two rounds.
inline QueryMeasurement everyFieldMeasurement(const std::string& backend) {
  QueryMeasurement m = named(backend, "tracked_tori", "touch", QueryKind::kContacts);
  m.protocol = TimingProtocol::kCycled;
  m.rounds = 2;
  m.times_us = {4.0, 5.0, 6.0, 7.0};
  m.repeated_us = 3.5;
  for (std::size_t i = 0; i < 2; ++i) {
    FrameRecord f;
    f.frame = i;
    f.oracle_intersecting = true;
    f.reported_intersecting = true;
    f.truth_intersecting = i == 0;
    f.possible_contact = true;
    f.tracking_margin = 0.01 * static_cast<double>(i + 1);
    f.invalid_pairs = i;
    f.truncated = i == 1;
    f.object_pairs = 3;
    f.reused_pairs = i;
    f.skipped_pairs = 2;
    f.oracle_distance = 0.5;
    f.reported_distance = 0.5 + 1e-9;
    f.distance_below = 1e-12;
    f.distance_above = 2e-12;
    f.invalid_distance_witness = i == 1;
    f.oracle_touches = i == 0;
    f.oracle_t_lo = 0.25;
    f.oracle_t_hi = 0.25 + 1e-3;
    f.reported_t_lo = 0.2;
    f.reported_t_hi = 0.201;
    f.first_contact_error = 0.0505;
    f.bracket_width = 0.001;
    f.invalid_first_contact = i == 1;
    ContactScore contact;
    contact.contacts = 4;
    contact.false_pairs = 1;
    contact.bad_normals = 1;
    contact.bad_depths = 1;
    contact.off_set = 1;
    contact.position_error = 1e-9;
    contact.surface_error = 2e-9;
    contact.normal_error_deg = 0.5;
    contact.depth_error = 1e-6;
    contact.coverage = 0.75;
    contact.covered_length = 3.0;
    contact.total_length = 4.0;
    f.contact = contact;
    f.median_us = 4.5 + static_cast<double>(i);
    f.floor_us = 0.25;
    f.update_us = 12.0;
    f.update_work = {10, 1, 7, true};
    // Every registered check's values, whatever checks there are (runner/checks.h).
    for (const std::string& name : checkFrameValues())
      f.values[name] = 0.125 * static_cast<double>(i + 1);
    m.frames.push_back(f);
  }
  m.build_ms = 2.0;
  m.triangles = 500;
  m.memory_bytes = 32000;
  m.heap_probe = "hooks";
  summariseMeasurement(m);
  return m;
}

/// A query the backend does not answer.
inline QueryMeasurement skippedMeasurement(const std::string& backend) {
  QueryMeasurement m = named(backend, "tori", "all_pairs", QueryKind::kAllPairs);
  m.status = MeasurementStatus::skipped(backend + " does not answer all_pairs queries");
  summariseMeasurement(m);
  return m;
}

/// A worker that finished: an all-pairs, a boolean and a skipped measurement.
inline CombinationResult okResult(const Combination& c) {
  CombinationResult r;
  r.combination = c;
  r.outcome.wall_s = 0.75;
  r.outcome.peak_rss_bytes = 48u * 1024u * 1024u;
  r.measurements = {pairsMeasurement(c.backend, true), booleanMeasurement(c.backend),
                    skippedMeasurement(c.backend)};
  r.problems = {"a problem worth keeping"};
  return r;
}

/// A worker killed by SIGSEGV.
inline CombinationResult crashedResult(const Combination& c) {
  CombinationResult r;
  r.combination = c;
  r.outcome.status = WorkerStatus::kCrashed;
  r.outcome.signal = SIGSEGV;
  r.outcome.signal_name = "SIGSEGV";
  r.outcome.wall_s = 0.1;
  r.outcome.log_tail = "building torus_a\n";
  return r;
}

}  // namespace collido::study::testdata
