#pragma once
// The stored fields of a measurement, its frame records and contact scores, each listed once:
// the JSON writer (study results, records.jsonl) and reader (measurement_json.h) both walk these
// lists, so a new field is one line here and one where it is computed.
//
// A list calls visit(name, member, absent) for each field in output order, with `member` a
// reference into the record (const when writing). `absent` says how a reader treats a key that is
// missing or null: Absent::kError for fields every stored record has, Absent::kKeep for fields
// added later (the reader leaves the record's default).

#include <string>
#include <type_traits>

#include <collido/runner/checks.h>
#include <collido/runner/runner.h>

namespace collido {

/// How a reader treats a field's key that is missing or null.
enum class Absent { kError, kKeep };

/// A work counter that is null in JSON where the backend does not count it.
template <typename Count>
struct CountedField {
  Count& value;
  bool counted;
};

template <typename Count>
CountedField<Count> countedField(Count& value, bool counted) {
  return {value, counted};
}

/// A registered check's per-frame value (runner/checks.h): `name` in FrameRecord::values, null in
/// JSON where the check did not measure the frame.
template <typename Values>
struct CheckValueField {
  Values& values;
  const std::string& name;

  std::optional<double> get() const {
    const auto found = values.find(name);
    return found == values.end() ? std::nullopt : std::optional<double>(found->second);
  }
};

template <typename Score, typename Visit>
void visitContactScoreFields(Score& c, Visit&& visit) {
  visit("contacts", c.contacts, Absent::kError);
  visit("false_pairs", c.false_pairs, Absent::kError);
  visit("bad_normals", c.bad_normals, Absent::kError);
  visit("bad_depths", c.bad_depths, Absent::kError);
  visit("off_set", c.off_set, Absent::kError);
  visit("position_error", c.position_error, Absent::kKeep);
  visit("surface_error", c.surface_error, Absent::kKeep);
  visit("normal_error_deg", c.normal_error_deg, Absent::kKeep);
  visit("depth_error", c.depth_error, Absent::kKeep);
  visit("coverage", c.coverage, Absent::kKeep);
  visit("covered_length", c.covered_length, Absent::kError);
  visit("total_length", c.total_length, Absent::kError);
}

/// A frame record's fields; `counts_bv_tests` and `counts_primitive_tests` are its measurement's
/// (the counters are null where the backend does not count them).
template <typename Frame, typename Visit>
void visitFrameFields(Frame& f, bool counts_bv_tests, bool counts_primitive_tests, Visit&& visit) {
  visit("frame", f.frame, Absent::kError);
  visit("oracle_intersecting", f.oracle_intersecting, Absent::kError);
  visit("reported_intersecting", f.reported_intersecting, Absent::kError);
  visit("finest_intersecting", f.finest_intersecting, Absent::kKeep);
  visit("truth_intersecting", f.truth_intersecting, Absent::kKeep);
  visit("possible_contact", f.possible_contact, Absent::kKeep);
  visit("tracking_margin", f.tracking_margin, Absent::kKeep);
  visit("oracle_pairs", f.oracle_pairs, Absent::kError);
  visit("reported_pairs", f.reported_pairs, Absent::kError);
  visit("matched_pairs", f.matched_pairs, Absent::kError);
  visit("invalid_pairs", f.invalid_pairs, Absent::kError);
  visit("truncated", f.truncated, Absent::kError);
  visit("object_pairs", f.object_pairs, Absent::kKeep);
  visit("reused_pairs", f.reused_pairs, Absent::kKeep);
  visit("skipped_pairs", f.skipped_pairs, Absent::kKeep);
  visit("oracle_distance", f.oracle_distance, Absent::kKeep);
  visit("reported_distance", f.reported_distance, Absent::kKeep);
  visit("distance_below", f.distance_below, Absent::kKeep);
  visit("distance_above", f.distance_above, Absent::kKeep);
  visit("invalid_distance_witness", f.invalid_distance_witness, Absent::kKeep);
  visit("contact", f.contact, Absent::kKeep);
  visit("oracle_touches", f.oracle_touches, Absent::kKeep);
  visit("oracle_t_lo", f.oracle_t_lo, Absent::kKeep);
  visit("oracle_t_hi", f.oracle_t_hi, Absent::kKeep);
  visit("reported_t_lo", f.reported_t_lo, Absent::kKeep);
  visit("reported_t_hi", f.reported_t_hi, Absent::kKeep);
  visit("first_contact_error", f.first_contact_error, Absent::kKeep);
  visit("bracket_width", f.bracket_width, Absent::kKeep);
  visit("invalid_first_contact", f.invalid_first_contact, Absent::kKeep);
  visit("median_us", f.median_us, Absent::kError);
  visit("floor_us", f.floor_us, Absent::kKeep);
  visit("update_us", f.update_us, Absent::kKeep);
  visit("update", f.update_work, Absent::kKeep);  // update_nodes_refit, _rebuilds, _nodes_rebuilt
  visit("bv_tests", countedField(f.bv_tests, counts_bv_tests), Absent::kKeep);
  visit("primitive_tests", countedField(f.primitive_tests, counts_primitive_tests), Absent::kKeep);
  for (const std::string& name : checkFrameValues())
    visit(name.c_str(),
          CheckValueField<std::remove_reference_t<decltype((f.values))>>{f.values, name},
          Absent::kKeep);
}

/// A measurement's stored fields (its frames apart): what it was, how it was built, every timed
/// call. The summary figures (median, errors, recall, ...) are derived from these and the frames
/// (summariseMeasurement), so a stored result cannot contradict its own records.
template <typename Measurement, typename Visit>
void visitMeasurementFields(Measurement& m, Visit&& visit) {
  visit("backend", m.backend, Absent::kError);
  visit("scene", m.scene, Absent::kError);
  visit("query", m.query, Absent::kError);
  visit("kind", m.kind, Absent::kError);
  visit("status", m.status, Absent::kError);
  visit("counts_bv_tests", m.counts_bv_tests, Absent::kKeep);
  visit("counts_primitive_tests", m.counts_primitive_tests, Absent::kKeep);
  visit("build_ms", m.build_ms, Absent::kError);
  visit("triangles", m.triangles, Absent::kError);
  visit("memory_bytes", m.memory_bytes, Absent::kError);
  visit("heap_bytes", m.heap_bytes, Absent::kKeep);
  visit("heap_peak_bytes", m.heap_peak_bytes, Absent::kKeep);
  visit("heap_allocations", m.heap_allocations, Absent::kKeep);
  visit("heap_probe", m.heap_probe, Absent::kKeep);
  visit("protocol", m.protocol, Absent::kKeep);  // "repeated" before there was a choice
  visit("times_us", m.times_us, Absent::kError);
  visit("rounds", m.rounds, Absent::kKeep);  // 1 before a study joined rounds
  visit("repeated_us", m.repeated_us, Absent::kKeep);
}

/// A measurement's derived summary figures, written beside the stored fields for readers of the
/// JSON and recomputed on reading.
template <typename Visit>
void visitMeasurementSummary(const QueryMeasurement& m, Visit&& visit) {
  visit("median_us", m.median_us);
  visit("p90_us", m.p90_us);
  visit("p99_us", m.p99_us);
  visit("max_us", m.max_us);
  visit("timed_calls", m.times_us.size());
  visit("false_negatives", m.false_negatives);
  visit("false_positives", m.false_positives);
  visit("disagreements", m.disagreements);
  visit("finest_disagreements", m.finest_disagreements);
  visit("tracking_false_contacts", m.tracking_false_contacts);
  visit("tracking_missed_contacts", m.tracking_missed_contacts);
  visit("tracking_possible_contacts", m.tracking_possible_contacts);
  visit("tracking_missed_within_margin", m.tracking_missed_within_margin);
  visit("max_distance_error", m.max_distance_error);
  visit("max_relative_distance_error", m.max_relative_distance_error);
  visit("max_first_contact_error", m.max_first_contact_error);
  visit("contact", m.contact);
  visit("recall", m.recall);
  visit("precision", m.precision);
  visit("floor_ratio", m.floor_ratio);
  visit("reused_pairs", m.reused_pairs);
  visit("unasked_frames", m.unasked_frames);
  visit("skipped_pairs", m.skipped_pairs);
  visit("update_median_us", m.update_median_us);
  visit("update_rebuilds", m.update_rebuilds);
  for (const CheckFigure& figure : checkFigures())
    visit(figure.name.c_str(), figure.value(m));
}

}  // namespace collido
