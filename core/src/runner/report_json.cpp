#include <collido/runner/measurement_json.h>

namespace collido {
namespace {

using Json = nlohmann::json;

template <typename T>
Json optionalJson(const std::optional<T>& value) {
  return value ? Json(*value) : Json();
}

template <typename T>
std::optional<T> optionalFrom(const Json& json, const char* key) {
  const auto found = json.find(key);
  if (found == json.end() || found->is_null()) return std::nullopt;
  return found->get<T>();
}

std::optional<ContactScore> contactScoreFrom(const Json& j, const char* key) {
  const auto found = j.find(key);
  if (found == j.end() || found->is_null()) return std::nullopt;
  const Json& c = *found;
  ContactScore score;
  score.contacts = c.at("contacts").get<std::size_t>();
  score.false_pairs = c.at("false_pairs").get<std::size_t>();
  score.bad_normals = c.at("bad_normals").get<std::size_t>();
  score.bad_depths = c.at("bad_depths").get<std::size_t>();
  score.off_set = c.at("off_set").get<std::size_t>();
  score.position_error = optionalFrom<double>(c, "position_error");
  score.surface_error = optionalFrom<double>(c, "surface_error");
  score.normal_error_deg = optionalFrom<double>(c, "normal_error_deg");
  score.depth_error = optionalFrom<double>(c, "depth_error");
  score.coverage = optionalFrom<double>(c, "coverage");
  score.covered_length = c.at("covered_length").get<double>();
  score.total_length = c.at("total_length").get<double>();
  return score;
}

FrameRecord frameFrom(const Json& j) {
  FrameRecord f;
  f.frame = j.at("frame").get<std::size_t>();
  f.oracle_intersecting = j.at("oracle_intersecting").get<bool>();
  f.reported_intersecting = j.at("reported_intersecting").get<bool>();
  f.finest_intersecting = optionalFrom<bool>(j, "finest_intersecting");
  f.truth_intersecting = optionalFrom<bool>(j, "truth_intersecting");
  f.possible_contact = optionalFrom<bool>(j, "possible_contact");
  f.tracking_margin = optionalFrom<double>(j, "tracking_margin");
  f.oracle_pairs = j.at("oracle_pairs").get<std::size_t>();
  f.reported_pairs = j.at("reported_pairs").get<std::size_t>();
  f.matched_pairs = j.at("matched_pairs").get<std::size_t>();
  f.invalid_pairs = j.at("invalid_pairs").get<std::size_t>();
  f.truncated = j.at("truncated").get<bool>();
  f.object_pairs = optionalFrom<std::size_t>(j, "object_pairs").value_or(1);
  f.oracle_distance = optionalFrom<double>(j, "oracle_distance");
  f.reported_distance = optionalFrom<double>(j, "reported_distance");
  f.distance_below = optionalFrom<double>(j, "distance_below").value_or(0.0);
  f.distance_above = optionalFrom<double>(j, "distance_above").value_or(0.0);
  f.invalid_distance_witness = optionalFrom<bool>(j, "invalid_distance_witness").value_or(false);
  f.contact = contactScoreFrom(j, "contact");
  f.median_us = j.at("median_us").get<double>();
  f.floor_us = optionalFrom<double>(j, "floor_us");
  f.update_us = optionalFrom<double>(j, "update_us");
  if (const std::optional<std::uint64_t> refit =
          optionalFrom<std::uint64_t>(j, "update_nodes_refit")) {
    f.update_work.counted = true;
    f.update_work.nodes_refit = *refit;
    f.update_work.rebuilds = optionalFrom<std::uint64_t>(j, "update_rebuilds").value_or(0);
    f.update_work.nodes_rebuilt =
        optionalFrom<std::uint64_t>(j, "update_nodes_rebuilt").value_or(0);
  }
  f.bv_tests = optionalFrom<std::uint64_t>(j, "bv_tests").value_or(0);
  f.primitive_tests = optionalFrom<std::uint64_t>(j, "primitive_tests").value_or(0);
  return f;
}

}  // namespace

Json measurementToJson(const QueryMeasurement& m) {
  Json frames = Json::array();
  for (const FrameRecord& f : m.frames)
    frames.push_back(frameRecordJson<Json>(f, m));
  return {{"backend", m.backend},
          {"scene", m.scene},
          {"query", m.query},
          {"kind", queryKindName(m.kind)},
          {"status", m.status.text()},
          {"median_us", m.median_us},
          {"p90_us", m.p90_us},
          {"p99_us", m.p99_us},
          {"max_us", m.max_us},
          {"timed_calls", m.times_us.size()},
          {"false_negatives", m.false_negatives},
          {"false_positives", m.false_positives},
          {"disagreements", m.disagreements},
          {"finest_disagreements", optionalJson(m.finest_disagreements)},
          {"tracking_false_contacts", optionalJson(m.tracking_false_contacts)},
          {"tracking_missed_contacts", optionalJson(m.tracking_missed_contacts)},
          {"tracking_possible_contacts", optionalJson(m.tracking_possible_contacts)},
          {"tracking_missed_within_margin", optionalJson(m.tracking_missed_within_margin)},
          {"max_distance_error", optionalJson(m.max_distance_error)},
          {"max_relative_distance_error", optionalJson(m.max_relative_distance_error)},
          {"contact", m.contact ? contactScoreJson<Json>(*m.contact) : Json()},
          {"recall", m.recall},
          {"precision", m.precision},
          {"counts_bv_tests", m.counts_bv_tests},
          {"counts_primitive_tests", m.counts_primitive_tests},
          {"floor_ratio", optionalJson(m.floor_ratio)},
          {"update_median_us", optionalJson(m.update_median_us)},
          {"update_rebuilds", optionalJson(m.update_rebuilds)},
          {"build_ms", m.build_ms},
          {"triangles", m.triangles},
          {"memory_bytes", m.memory_bytes},
          {"heap_bytes", optionalJson(m.heap_bytes)},
          {"heap_peak_bytes", optionalJson(m.heap_peak_bytes)},
          {"heap_allocations", optionalJson(m.heap_allocations)},
          {"heap_probe", m.heap_probe},
          {"protocol", m.protocol},
          {"times_us", m.times_us},
          {"frames", frames}};
}

Result<QueryMeasurement> measurementFromJson(const Json& j) {
  try {
    QueryMeasurement m;
    m.backend = j.at("backend").get<std::string>();
    m.scene = j.at("scene").get<std::string>();
    m.query = j.at("query").get<std::string>();
    const std::string kind = j.at("kind").get<std::string>();
    const std::optional<QueryKind> parsed = parseQueryKind(kind);
    if (!parsed) return Status(StatusCode::kInvalidArgument, "unknown query kind '" + kind + "'");
    m.kind = *parsed;
    m.status = MeasurementStatus::fromText(j.at("status").get<std::string>());
    m.counts_bv_tests = j.value("counts_bv_tests", false);
    m.counts_primitive_tests = j.value("counts_primitive_tests", false);
    m.build_ms = j.at("build_ms").get<double>();
    m.triangles = j.at("triangles").get<std::size_t>();
    m.memory_bytes = j.at("memory_bytes").get<std::size_t>();
    m.heap_bytes = optionalFrom<std::size_t>(j, "heap_bytes");
    m.heap_peak_bytes = optionalFrom<std::size_t>(j, "heap_peak_bytes");
    m.heap_allocations = optionalFrom<std::uint64_t>(j, "heap_allocations");
    m.heap_probe = j.value("heap_probe", "");
    m.protocol = j.value("protocol", "repeated");  // before there was a choice
    m.times_us = j.at("times_us").get<std::vector<double>>();
    for (const Json& frame : j.at("frames"))
      m.frames.push_back(frameFrom(frame));
    // Derived figures are recomputed, so a stored file cannot contradict its own records.
    summariseMeasurement(m);
    return m;
  } catch (const Json::exception& e) {
    return Status(StatusCode::kInvalidArgument, std::string("measurement record: ") + e.what());
  }
}

std::string runReportJson(const RunReport& report) {
  Json measurements = Json::array();
  for (const QueryMeasurement& m : report.measurements)
    measurements.push_back(measurementToJson(m));
  const Json document = {
      {"collidoscope_run", 1}, {"measurements", measurements}, {"problems", report.problems}};
  return document.dump(2);
}

}  // namespace collido
