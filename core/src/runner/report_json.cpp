#include <collido/runner/measurement_json.h>

#include <stdexcept>

namespace collido {
namespace {

using Json = nlohmann::json;

// A required field that is missing or null: its name is the message.
struct MissingField : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads the fields a list of record_fields.h visits from a JSON object; nlohmann's exceptions
// name a mistyped field's value, MissingField a missing one.
class JsonFieldReader {
 public:
  explicit JsonFieldReader(const Json& in) : in_(in) {}

  template <typename T>
  void operator()(const char* name, T& member, Absent absent) const {
    if (const Json* value = find(name, absent)) read(*value, member);
  }
  void operator()(const char* /*name*/, UpdateCounters& work, Absent /*absent*/) const {
    const Json* refit = find("update_nodes_refit", Absent::kKeep);
    if (refit == nullptr) return;
    work.counted = true;
    work.nodes_refit = refit->get<std::uint64_t>();
    if (const Json* rebuilds = find("update_rebuilds", Absent::kKeep))
      work.rebuilds = rebuilds->get<std::uint64_t>();
    if (const Json* rebuilt = find("update_nodes_rebuilt", Absent::kKeep))
      work.nodes_rebuilt = rebuilt->get<std::uint64_t>();
  }
  template <typename Count>
  void operator()(const char* name, CountedField<Count> field, Absent absent) const {
    if (const Json* value = find(name, absent)) field.value = value->get<Count>();
  }
  template <typename Values>
  void operator()(const char* name, CheckValueField<Values> field, Absent absent) const {
    if (const Json* value = find(name, absent)) field.values[field.name] = value->get<double>();
  }

 private:
  const Json* find(const char* name, Absent absent) const {
    const auto found = in_.find(name);
    if (found != in_.end() && !found->is_null()) return &*found;
    if (absent == Absent::kError) throw MissingField(std::string("missing field '") + name + "'");
    return nullptr;
  }
  template <typename T>
  static void read(const Json& value, T& member) {
    member = value.get<T>();
  }
  template <typename T>
  static void read(const Json& value, std::optional<T>& member) {
    T inner{};
    read(value, inner);
    member = std::move(inner);
  }
  static void read(const Json& value, ContactScore& score) {
    visitContactScoreFields(score, JsonFieldReader(value));
  }
  static void read(const Json& value, QueryKind& kind) {
    const std::string name = value.get<std::string>();
    const std::optional<QueryKind> parsed = parseQueryKind(name);
    if (!parsed) throw MissingField("unknown query kind '" + name + "'");
    kind = *parsed;
  }
  static void read(const Json& value, TimingProtocol& protocol) {
    const std::string name = value.get<std::string>();
    const std::optional<TimingProtocol> parsed = parseTimingProtocol(name);
    if (!parsed) throw MissingField("unknown timing protocol '" + name + "'");
    protocol = *parsed;
  }
  static void read(const Json& value, MeasurementStatus& status) {
    status = MeasurementStatus::fromText(value.get<std::string>());
  }

  const Json& in_;
};

}  // namespace

Json measurementToJson(const QueryMeasurement& m) {
  Json out = Json::object();
  const JsonFieldWriter<Json> write(out);
  visitMeasurementFields(m, write);
  visitMeasurementSummary(m, [&write](const char* name, const auto& value) { write(name, value); });
  Json frames = Json::array();
  for (const FrameRecord& f : m.frames)
    frames.push_back(frameRecordJson<Json>(f, m));
  out["frames"] = std::move(frames);
  return out;
}

Result<QueryMeasurement> measurementFromJson(const Json& j) {
  try {
    QueryMeasurement m;
    visitMeasurementFields(m, JsonFieldReader(j));
    if (!j.contains("frames")) throw MissingField("missing field 'frames'");
    for (const Json& frame : j.at("frames")) {
      FrameRecord f;
      visitFrameFields(f, m.counts_bv_tests, m.counts_primitive_tests, JsonFieldReader(frame));
      m.frames.push_back(std::move(f));
    }
    // Derived figures are recomputed, so a stored file cannot contradict its own records.
    summariseMeasurement(m);
    return m;
  } catch (const MissingField& e) {
    return Status(StatusCode::kInvalidArgument, std::string("measurement record: ") + e.what());
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
