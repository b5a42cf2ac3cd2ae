#include <collido/study/result_store.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <collido/runner/measurement_json.h>
#include <collido/study/rounds.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

}  // namespace

Result<Json> readJsonFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status(StatusCode::kInvalidArgument, path + ": cannot be read");
  std::stringstream buffer;
  buffer << in.rdbuf();
  try {
    return Json::parse(buffer.str());
  } catch (const Json::parse_error& e) {
    return Status(StatusCode::kInvalidArgument, path + ": not valid JSON: " + e.what());
  }
}

std::string WorkerOutcome::text() const {
  std::string text = status;
  if (!signal_name.empty()) text += " (" + signal_name + ")";
  if (status == "failed") text += " (exit " + std::to_string(exit_code) + ")";
  return text;
}

Json resultToJson(const CombinationResult& r) {
  Json measurements = Json::array();
  for (const QueryMeasurement& m : r.measurements)
    measurements.push_back(measurementToJson(m));
  Json json = {{"collidoscope_combination", 1},
               {"combination", combinationToJson(r.combination)},
               {"outcome",
                {{"status", r.outcome.status},
                 {"exit_code", r.outcome.exit_code},
                 {"signal", r.outcome.signal},
                 {"signal_name", r.outcome.signal_name},
                 {"wall_s", r.outcome.wall_s},
                 {"peak_rss_bytes", r.outcome.peak_rss_bytes},
                 {"log_tail", r.outcome.log_tail}}},
               {"measurements", measurements},
               {"problems", r.problems},
               {"backend_rss_bytes", r.backend_rss_bytes ? Json(*r.backend_rss_bytes) : Json()}};
  if (!r.comparison.is_null()) json["comparison"] = r.comparison;
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
    r.outcome.status = o.at("status").get<std::string>();
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
    if (json.contains("comparison")) {
      r.comparison = json.at("comparison");
      if (!r.comparison.is_object()) return bad("/comparison: expected an object");
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
Status writeFileAtomically(const std::string& path, const std::string& text) {
  static std::atomic<unsigned long> serial{0};
  static const std::string host = [] {
    char name[256] = {};
    return ::gethostname(name, sizeof(name) - 1) == 0 ? std::string(name) : std::string("host");
  }();
  const std::string temporary = path + ".partial." + host + "." + std::to_string(::getpid()) + "." +
                                std::to_string(serial.fetch_add(1));
  const auto failed = [&](const std::string& what, int error) {
    ::unlink(temporary.c_str());
    return Status(StatusCode::kInvalidArgument, what + ": " + std::strerror(error));
  };
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    return Status(StatusCode::kInvalidArgument,
                  temporary + ": cannot be written: " + std::strerror(errno));
  }
  for (std::size_t done = 0; done < text.size();) {
    const ::ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      ::close(fd);
      return failed(temporary + ": cannot be written", error);
    }
    done += static_cast<std::size_t>(n);
  }
  // Without this, a crash of the machine soon after the rename could leave the new name on a
  // file whose data never reached the disk (an empty result that would stop --resume).
  if (::fdatasync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    return failed(temporary + ": cannot be flushed to disk", error);
  }
  if (::close(fd) != 0) return failed(temporary + ": cannot be written", errno);
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    return failed(path + ": cannot be replaced", errno);
  }
  return Status();
}

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
  return writeFileAtomically(
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
    Result<Json> json = readJsonFile(file);
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
                              const RunOrder& order) const {
  Json list = Json::array();
  for (const Combination& c : plan)
    list.push_back(combinationToJson(c));
  return writeFileAtomically(planPath(),
                             Json{{"collidoscope_plan", 1},
                                  {"order", {{"rounds", order.rounds}, {"seed", order.seed}}},
                                  {"combinations", list},
                                  {"not_applicable", notApplicableToJson(not_applicable)}}
                                 .dump(1));
}

Result<std::optional<Json>> ResultStore::readPlanJson() const {
  const std::string path = planPath();
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::optional<Json>();
  Result<Json> json = readJsonFile(path);
  if (!json.ok()) return json.status();
  return std::optional<Json>(std::move(json).value());
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
