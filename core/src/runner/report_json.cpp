#include <nlohmann/json.hpp>

#include <collido/runner/runner.h>

namespace collido {

std::string runReportJson(const RunReport& report) {
  using Json = nlohmann::json;
  Json measurements = Json::array();
  for (const QueryMeasurement& m : report.measurements) {
    Json frames = Json::array();
    for (const FrameRecord& f : m.frames) {
      frames.push_back(
          {{"frame", f.frame},
           {"oracle_intersecting", f.oracle_intersecting},
           {"reported_intersecting", f.reported_intersecting},
           {"oracle_pairs", f.oracle_pairs},
           {"reported_pairs", f.reported_pairs},
           {"matched_pairs", f.matched_pairs},
           {"invalid_pairs", f.invalid_pairs},
           {"truncated", f.truncated},
           {"disagrees", f.disagrees(m.kind)},
           {"median_us", f.median_us},
           {"bv_tests", m.counts_bv_tests ? Json(f.bv_tests) : Json()},
           {"primitive_tests", m.counts_primitive_tests ? Json(f.primitive_tests) : Json()}});
    }
    measurements.push_back({{"backend", m.backend},
                            {"scene", m.scene},
                            {"query", m.query},
                            {"kind", queryKindName(m.kind)},
                            {"status", m.status},
                            {"median_us", m.median_us},
                            {"p90_us", m.p90_us},
                            {"timed_calls", m.times_us.size()},
                            {"false_negatives", m.false_negatives},
                            {"false_positives", m.false_positives},
                            {"disagreements", m.disagreements},
                            {"recall", m.recall},
                            {"precision", m.precision},
                            {"build_ms", m.build_ms},
                            {"triangles", m.triangles},
                            {"memory_bytes", m.memory_bytes},
                            {"heap_bytes", m.heap_bytes ? Json(*m.heap_bytes) : Json()},
                            {"frames", frames}});
  }
  const Json document = {
      {"collidoscope_run", 1}, {"measurements", measurements}, {"problems", report.problems}};
  return document.dump(2);
}

}  // namespace collido
