#include <collido/study/result_store.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include <collido/io/files.h>
#include <collido/runner/measurement_json.h>
#include <collido/study/rounds.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

}  // namespace

namespace {

constexpr std::pair<WorkerStatus, const char*> kWorkerStatusNames[] = {
    {WorkerStatus::kOk, "ok"},
    {WorkerStatus::kFailed, "failed"},
    {WorkerStatus::kCrashed, "crashed"},
    {WorkerStatus::kTimeout, "timeout"},
    {WorkerStatus::kInterrupted, "interrupted"},
    {WorkerStatus::kUnfinished, "unfinished"},
};

}  // namespace

const char* workerStatusName(WorkerStatus status) {
  for (const auto& [value, name] : kWorkerStatusNames) {
    if (value == status) return name;
  }
  return "unknown";
}

std::optional<WorkerStatus> parseWorkerStatus(const std::string& name) {
  for (const auto& [value, spelled] : kWorkerStatusNames) {
    if (name == spelled) return value;
  }
  return std::nullopt;
}

std::string WorkerOutcome::text() const {
  std::string text = workerStatusName(status);
  if (!signal_name.empty()) text += " (" + signal_name + ")";
  if (status == WorkerStatus::kFailed) text += " (exit " + std::to_string(exit_code) + ")";
  return text;
}

Json resultToJson(const CombinationResult& r) {
  Json measurements = Json::array();
  for (const QueryMeasurement& m : r.measurements)
    measurements.push_back(measurementToJson(m));
  Json json = {{"collidoscope_combination", 1},
               {"combination", combinationToJson(r.combination)},
               {"outcome",
                {{"status", workerStatusName(r.outcome.status)},
                 {"exit_code", r.outcome.exit_code},
                 {"signal", r.outcome.signal},
                 {"signal_name", r.outcome.signal_name},
                 {"wall_s", r.outcome.wall_s},
                 {"peak_rss_bytes", r.outcome.peak_rss_bytes},
                 {"log_tail", r.outcome.log_tail}}},
               {"measurements", measurements},
               {"problems", r.problems},
               {"backend_rss_bytes", r.backend_rss_bytes ? Json(*r.backend_rss_bytes) : Json()}};
  if (r.surfaces) json["comparison"] = surfaceRunJson(*r.surfaces);
  if (r.frep) json["comparison"] = frepRunJson(*r.frep);
  return json;
}

Result<CombinationResult> resultFromJson(const Json& json, const std::string& label) {
  const auto bad = [&label](const std::string& problem) {
    return Status(StatusCode::kInvalidArgument, label + ": " + problem);
  };
  try {
    if (json.value("collidoscope_combination", 0) != 1) {
      return bad("not a Collidoscope combination result (collidoscope_combination != 1)");
    }
    CombinationResult r;
    Result<Combination> combination = combinationFromJson(json.at("combination"));
    if (!combination.ok()) return bad(combination.status().message());
    r.combination = std::move(combination).value();
    const Json& o = json.at("outcome");
    const std::string status = o.at("status").get<std::string>();
    const std::optional<WorkerStatus> parsed = parseWorkerStatus(status);
    if (!parsed) return bad("/outcome/status: unknown worker status \"" + status + "\"");
    r.outcome.status = *parsed;
    r.outcome.exit_code = o.at("exit_code").get<int>();
    r.outcome.signal = o.at("signal").get<int>();
    r.outcome.signal_name = o.at("signal_name").get<std::string>();
    r.outcome.wall_s = o.at("wall_s").get<double>();
    r.outcome.peak_rss_bytes = o.at("peak_rss_bytes").get<std::size_t>();
    r.outcome.log_tail = o.at("log_tail").get<std::string>();
    for (const Json& m : json.at("measurements")) {
      Result<QueryMeasurement> measurement = measurementFromJson(m);
      if (!measurement.ok()) return bad(measurement.status().message());
      r.measurements.push_back(std::move(measurement).value());
    }
    r.problems = json.at("problems").get<std::vector<std::string>>();
    // Absent from results stored before backends' memory was measured apart.
    if (json.contains("backend_rss_bytes") && !json.at("backend_rss_bytes").is_null())
      r.backend_rss_bytes = json.at("backend_rss_bytes").get<std::size_t>();
    if (json.contains("comparison") && r.combination.kind == InputKind::kSurfaces) {
      Result<SurfaceRun> run = surfaceRunFromJson(json.at("comparison"));
      if (!run.ok()) return bad("/comparison: " + run.status().message());
      r.surfaces = std::move(run).value();
    }
    if (json.contains("comparison") && r.combination.kind == InputKind::kFrep) {
      Result<FrepRun> run = frepRunFromJson(json.at("comparison"));
      if (!run.ok()) return bad("/comparison: " + run.status().message());
      r.frep = std::move(run).value();
    }
    return r;
  } catch (const Json::exception& e) {
    return bad(e.what());
  }
}

// Write-to-temporary, flush to disk, rename over the target: a reader, a study killed mid-write
// or a machine that loses power sees the previous file or the new one whole, never a mix. The
// temporary's name is unique to the process and the call, so two writers of one path never share
// it (one's rename would publish the other's half-written text), also from processes on other
// machines that share the folder (the shards of a study on a cluster); a failed write removes it.
Status ResultStore::prepare() const {
  std::error_code ec;
  for (const char* sub : {"results", "logs", "scratch"}) {
    fs::create_directories(fs::path(directory_) / sub, ec);
    if (ec) {
      return Status(StatusCode::kInvalidArgument,
                    (fs::path(directory_) / sub).string() + ": cannot be created: " + ec.message());
    }
  }
  return Status();
}

std::string ResultStore::resultPath(const std::string& id) const {
  return (fs::path(directory_) / "results" / (id + ".json")).string();
}
std::string ResultStore::logPath(const std::string& id) const {
  return (fs::path(directory_) / "logs" / (id + ".log")).string();
}
std::string ResultStore::scratchPath(const std::string& id) const {
  return (fs::path(directory_) / "scratch" / (id + ".json")).string();
}

bool ResultStore::has(const std::string& id) const {
  std::error_code ec;
  return fs::is_regular_file(resultPath(id), ec);
}

Status ResultStore::write(const CombinationResult& result) const {
  return io::writeFileAtomically(
      resultPath(result.combination.id),
      resultToJson(result).dump(1, ' ', false, Json::error_handler_t::replace));
}

Result<std::vector<CombinationResult>> ResultStore::readAll() const {
  std::vector<std::string> files;
  std::error_code ec;
  const fs::path folder = fs::path(directory_) / "results";
  if (fs::is_directory(folder, ec)) {
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
      if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<CombinationResult> results;
  // In plan order, so tables follow the study's nesting; results outside the plan go last.
  std::map<std::string, std::size_t> rank;
  if (Result<std::vector<Combination>> plan = readPlan(); plan.ok()) {
    for (std::size_t i = 0; i < plan.value().size(); ++i)
      rank.emplace(plan.value()[i].id, i);
  }
  for (const std::string& file : files) {
    Result<Json> json = io::readJsonFile(file);
    if (!json.ok()) return json.status();
    Result<CombinationResult> result = resultFromJson(json.value(), file);
    if (!result.ok()) return result.status();
    results.push_back(std::move(result).value());
  }
  std::stable_sort(results.begin(), results.end(),
                   [&rank](const CombinationResult& a, const CombinationResult& b) {
                     const auto order = [&rank](const CombinationResult& r) {
                       const auto found = rank.find(r.combination.id);
                       return found == rank.end() ? rank.size() : found->second;
                     };
                     return order(a) < order(b);
                   });
  return joinRounds(std::move(results));
}

std::string ResultStore::planPath() const {
  return (fs::path(directory_) / "plan.json").string();
}

Status ResultStore::writePlan(const std::vector<Combination>& plan,
                              const std::vector<NotApplicable>& not_applicable,
                              const std::optional<RunOrder>& order, const FieldSides& field) const {
  Json list = Json::array();
  for (const Combination& c : plan)
    list.push_back(combinationToJson(c));
  Json json{{"collidoscope_plan", 1},
            {"combinations", list},
            {"not_applicable", notApplicableToJson(not_applicable)},
            {"field", {{"ours", field.ours}, {"peer", field.peer}}}};
  if (order) json["order"] = Json{{"rounds", order->rounds}, {"seed", order->seed}};
  return io::writeFileAtomically(planPath(), json.dump(1));
}

Result<std::optional<RunOrder>> ResultStore::readRunOrder() const {
  Result<std::optional<Json>> json = readPlanJson();
  if (!json.ok()) return json.status();
  const std::optional<Json>& plan = json.value();
  if (!plan || !plan->is_object() || !plan->contains("order")) return std::optional<RunOrder>();
  const Json& order = plan->at("order");
  const bool valid = order.is_object() && order.contains("rounds") &&
                     order.at("rounds").is_number_integer() && order.at("rounds").get<int>() >= 1 &&
                     order.contains("seed") && order.at("seed").is_number_unsigned();
  if (!valid) {
    return Status(StatusCode::kInvalidArgument,
                  planPath() + ": /order: expected {\"rounds\": a count of at least 1, " +
                      "\"seed\": an unsigned integer}");
  }
  return std::optional<RunOrder>(
      RunOrder{order.at("rounds").get<int>(), order.at("seed").get<std::uint64_t>()});
}

Result<std::optional<Json>> ResultStore::readPlanJson() const {
  const std::string path = planPath();
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::optional<Json>();
  Result<Json> json = io::readJsonFile(path);
  if (!json.ok()) return json.status();
  return std::optional<Json>(std::move(json).value());
}

Result<FieldSides> ResultStore::readFieldSides() const {
  Result<std::optional<Json>> json = readPlanJson();
  if (!json.ok()) return json.status();
  const std::optional<Json>& plan = json.value();
  FieldSides sides;
  if (!plan || !plan->is_object() || !plan->contains("field")) return sides;
  const Json& field = plan->at("field");
  for (auto [key, side] :
       {std::make_pair("ours", &sides.ours), std::make_pair("peer", &sides.peer)}) {
    if (!field.is_object() || !field.contains(key) || !field.at(key).is_string()) {
      return Status(StatusCode::kInvalidArgument,
                    planPath() + ": /field/" + key + ": expected a backend name");
    }
    *side = field.at(key).get<std::string>();
  }
  return sides;
}

Result<std::vector<NotApplicable>> ResultStore::readNotApplicable() const {
  Result<std::optional<Json>> json = readPlanJson();
  if (!json.ok()) return json.status();
  const std::optional<Json>& plan = json.value();
  // Plans written before studies left settings out have no such key.
  if (!plan || !plan->is_object() || !plan->contains("not_applicable"))
    return std::vector<NotApplicable>{};
  return notApplicableFromJson(plan->at("not_applicable"), planPath());
}

Result<std::vector<Combination>> ResultStore::readPlan() const {
  const std::string path = planPath();
  Result<std::optional<Json>> json = readPlanJson();
  if (!json.ok()) return json.status();
  std::vector<Combination> plan;
  if (!json.value()) return plan;
  try {
    for (const Json& c : json.value()->at("combinations")) {
      Result<Combination> combination = combinationFromJson(c);
      if (!combination.ok()) {
        return Status(StatusCode::kInvalidArgument, path + ": " + combination.status().message());
      }
      plan.push_back(std::move(combination).value());
    }
  } catch (const Json::exception& e) {
    return Status(StatusCode::kInvalidArgument, path + ": " + e.what());
  }
  return plan;
}

}  // namespace collido::study
