#pragma once

#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>

#include <collido/runner/record_fields.h>
#include <collido/runner/runner.h>
#include <collido/runner/time_statistic.h>
#include <collido/status.h>

namespace collido {

/// A measurement as JSON, per-frame records and every timed call included; the form study
/// results are stored in, and read back from, to merge and report.
nlohmann::json measurementToJson(const QueryMeasurement& measurement);

/// Reads what measurementToJson wrote; errors name the missing or mistyped field.
Result<QueryMeasurement> measurementFromJson(const nlohmann::json& json);

/// [low, high]: an interval as summary.json and the study's outputs write it.
inline nlohmann::json intervalJson(const Interval& interval) {
  return nlohmann::json::array({interval.lo, interval.hi});
}

template <typename JsonT>
JsonT contactScoreJson(const ContactScore& c);

/// Writes the fields a list of record_fields.h visits into a JSON object (JsonT:
/// nlohmann::json or nlohmann::ordered_json): unset optionals and uncounted counters as null.
template <typename JsonT>
class JsonFieldWriter {
 public:
  explicit JsonFieldWriter(JsonT& out) : out_(out) {}

  template <typename T>
  void operator()(const char* name, const T& value, Absent /*absent*/ = Absent::kError) const {
    out_[name] = json(value);
  }
  void operator()(const char* /*name*/, const UpdateCounters& work, Absent /*absent*/) const {
    const auto counted = [&work](std::uint64_t value) {
      return work.counted ? JsonT(value) : JsonT();
    };
    out_["update_nodes_refit"] = counted(work.nodes_refit);
    out_["update_rebuilds"] = counted(work.rebuilds);
    out_["update_nodes_rebuilt"] = counted(work.nodes_rebuilt);
  }
  template <typename Count>
  void operator()(const char* name, const CountedField<Count>& field, Absent /*absent*/) const {
    out_[name] = field.counted ? JsonT(field.value) : JsonT();
  }
  template <typename Values>
  void operator()(const char* name, const CheckValueField<Values>& field, Absent /*absent*/) const {
    out_[name] = json(field.get());
  }

 private:
  template <typename T>
  static JsonT json(const T& value) {
    return JsonT(value);
  }
  template <typename T>
  static JsonT json(const std::optional<T>& value) {
    return value ? json(*value) : JsonT();
  }
  static JsonT json(const ContactScore& score) { return contactScoreJson<JsonT>(score); }
  static JsonT json(QueryKind kind) { return queryKindName(kind); }
  static JsonT json(TimingProtocol protocol) { return timingProtocolName(protocol); }
  static JsonT json(const MeasurementStatus& status) { return status.text(); }

  JsonT& out_;
};

/// A contact score as JSON (ContactScore's fields; unset figures null).
template <typename JsonT>
JsonT contactScoreJson(const ContactScore& c) {
  JsonT out = JsonT::object();
  visitContactScoreFields(c, JsonFieldWriter<JsonT>(out));
  return out;
}

/// One frame's record of measurement `m` as JSON: the fields of measurementToJson's "frames"
/// and of a study's records.jsonl lines (visitFrameFields), with whether the frame's answer
/// disagrees with the oracle's. Figures the backend or scene does not give are null.
template <typename JsonT>
JsonT frameRecordJson(const FrameRecord& f, const QueryMeasurement& m) {
  JsonT out = JsonT::object();
  visitFrameFields(f, m.counts_bv_tests, m.counts_primitive_tests, JsonFieldWriter<JsonT>(out));
  out["disagrees"] = f.disagrees(m.kind);
  return out;
}

}  // namespace collido
