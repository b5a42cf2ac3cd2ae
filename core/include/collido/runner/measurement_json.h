#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include <collido/runner/runner.h>
#include <collido/status.h>

namespace collido {

/// A measurement as JSON, per-frame records and every timed call included; the form study
/// results are stored in, and read back from, to merge and report.
nlohmann::json measurementToJson(const QueryMeasurement& measurement);

/// Reads what measurementToJson wrote; errors name the missing or mistyped field.
Result<QueryMeasurement> measurementFromJson(const nlohmann::json& json);

/// A contact score as JSON (ContactScore's fields; unset figures null).
template <typename JsonT>
JsonT contactScoreJson(const ContactScore& c) {
  const auto optional = [](const auto& value) { return value ? JsonT(*value) : JsonT(); };
  return {{"contacts", c.contacts},
          {"false_pairs", c.false_pairs},
          {"bad_normals", c.bad_normals},
          {"bad_depths", c.bad_depths},
          {"off_set", c.off_set},
          {"position_error", optional(c.position_error)},
          {"surface_error", optional(c.surface_error)},
          {"normal_error_deg", optional(c.normal_error_deg)},
          {"depth_error", optional(c.depth_error)},
          {"coverage", optional(c.coverage)},
          {"covered_length", c.covered_length},
          {"total_length", c.total_length}};
}

/// One frame's record of measurement `m` as JSON: the fields of measurementToJson's "frames"
/// and of a study's records.jsonl lines, written once for both (JsonT: nlohmann::json or
/// nlohmann::ordered_json). Figures the backend or scene does not give are null.
template <typename JsonT>
JsonT frameRecordJson(const FrameRecord& f, const QueryMeasurement& m) {
  const auto optional = [](const auto& value) { return value ? JsonT(*value) : JsonT(); };
  const auto counted = [](bool flag, std::uint64_t value) { return flag ? JsonT(value) : JsonT(); };
  const UpdateCounters& work = f.update_work;
  return {{"frame", f.frame},
          {"oracle_intersecting", f.oracle_intersecting},
          {"reported_intersecting", f.reported_intersecting},
          {"finest_intersecting", optional(f.finest_intersecting)},
          {"truth_intersecting", optional(f.truth_intersecting)},
          {"possible_contact", optional(f.possible_contact)},
          {"tracking_margin", optional(f.tracking_margin)},
          {"oracle_pairs", f.oracle_pairs},
          {"reported_pairs", f.reported_pairs},
          {"matched_pairs", f.matched_pairs},
          {"invalid_pairs", f.invalid_pairs},
          {"truncated", f.truncated},
          {"object_pairs", f.object_pairs},
          {"oracle_distance", optional(f.oracle_distance)},
          {"reported_distance", optional(f.reported_distance)},
          {"distance_below", f.distance_below},
          {"distance_above", f.distance_above},
          {"invalid_distance_witness", f.invalid_distance_witness},
          {"contact", f.contact ? contactScoreJson<JsonT>(*f.contact) : JsonT()},
          {"disagrees", f.disagrees(m.kind)},
          {"median_us", f.median_us},
          {"floor_us", optional(f.floor_us)},
          {"update_us", optional(f.update_us)},
          {"update_nodes_refit", counted(work.counted, work.nodes_refit)},
          {"update_rebuilds", counted(work.counted, work.rebuilds)},
          {"update_nodes_rebuilt", counted(work.counted, work.nodes_rebuilt)},
          {"bv_tests", counted(m.counts_bv_tests, f.bv_tests)},
          {"primitive_tests", counted(m.counts_primitive_tests, f.primitive_tests)}};
}

}  // namespace collido
