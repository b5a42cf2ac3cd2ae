// Expected study time, from the wall times of an earlier run: a user sees before the first
// combination how long the study will take.
#include <collido/study/expected_time.h>

#include <filesystem>
#include <numeric>
#include <sstream>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/study/progress.h>

namespace collido::study {
namespace {

constexpr int kTimesVersion = 1;

Result<CombinationTimes> timesFromResults(const std::string& directory) {
  Result<std::vector<CombinationResult>> results = ResultStore(directory).readAll();
  if (!results.ok()) return results.status();
  CombinationTimes times;
  for (const CombinationResult& r : results.value())
    if (r.outcome.ok()) times.seconds[r.combination.label()] = r.outcome.wall_s;
  return times;
}

}  // namespace

std::string timesJson(const std::vector<CombinationResult>& results) {
  nlohmann::ordered_json combinations = nlohmann::ordered_json::object();
  for (const CombinationResult& r : results)
    if (r.outcome.ok()) combinations[r.combination.label()] = r.outcome.wall_s;
  nlohmann::ordered_json root;
  root["collidoscope_times"] = kTimesVersion;
  root["combinations"] = std::move(combinations);
  return root.dump(1) + "\n";
}

Result<CombinationTimes> loadCombinationTimes(const std::string& path) {
  std::error_code ec;
  std::string file = path;
  if (std::filesystem::is_directory(path, ec)) {
    file = (std::filesystem::path(path) / "times.json").string();
    if (!std::filesystem::exists(file, ec)) return timesFromResults(path);
  }
  const Result<nlohmann::json> read = io::readJsonFile(file, "times file not found");
  if (!read.ok()) return read.status();
  const nlohmann::json& root = read.value();
  const auto fail = [&file](const std::string& problem) -> Result<CombinationTimes> {
    return Status(StatusCode::kInvalidArgument, file + ": " + problem);
  };
  if (!root.is_object() || root.value("collidoscope_times", 0) != kTimesVersion)
    return fail("not a times file (expected \"collidoscope_times\": 1)");
  if (!root.contains("combinations") || !root["combinations"].is_object())
    return fail("/combinations: expected an object of label: seconds");
  CombinationTimes times;
  for (const auto& [label, seconds] : root["combinations"].items()) {
    if (!seconds.is_number() || seconds.get<double>() < 0.0)
      return fail("/combinations/" + label + ": expected a number of seconds >= 0");
    times.seconds[label] = seconds.get<double>();
  }
  return times;
}

double TimeEstimate::total() const {
  return std::accumulate(seconds.begin(), seconds.end(), 0.0) + extra_rounds_s;
}

TimeEstimate estimateTimes(const std::vector<const Combination*>& combinations,
                           const CombinationTimes& times) {
  // Per scene, the mean of its known combinations; labels start with "scene · ".
  std::map<std::string, std::pair<double, std::size_t>> per_scene;
  double sum = 0.0;
  for (const auto& [label, seconds] : times.seconds) {
    auto& [scene_sum, count] = per_scene[label.substr(0, label.find(" · "))];
    scene_sum += seconds;
    ++count;
    sum += seconds;
  }
  const double overall =
      times.seconds.empty() ? 0.0 : sum / static_cast<double>(times.seconds.size());
  TimeEstimate estimate;
  for (const Combination* c : combinations) {
    if (const auto known = times.seconds.find(c->label()); known != times.seconds.end()) {
      estimate.seconds.push_back(known->second);
      ++estimate.measured;
    } else if (const auto scene = per_scene.find(c->scene_name); scene != per_scene.end()) {
      estimate.seconds.push_back(scene->second.first / static_cast<double>(scene->second.second));
      ++estimate.from_scene;
    } else {
      estimate.seconds.push_back(overall);
      ++estimate.unknown;
    }
  }
  return estimate;
}

std::string startLine(std::size_t planned, std::size_t to_run, const TimeEstimate& estimate,
                      const std::string& shard, const std::string& out) {
  std::ostringstream line;
  line << "study: " << planned << " combinations" << (shard.empty() ? "" : " in shard " + shard)
       << ", " << to_run << " to run, ";
  const std::size_t count = estimate.seconds.size();
  if (count == 0) {
    line << "nothing left";
  } else if (estimate.measured + estimate.from_scene == 0 && estimate.total() == 0.0) {
    line << "expected time unknown (no earlier timings: --expected-times)";
  } else {
    line << "expected about " << formatDuration(estimate.total());
    std::vector<std::string> how;
    if (estimate.measured != count) {
      how.push_back(std::to_string(estimate.measured) + " timed before, " +
                    std::to_string(estimate.from_scene) + " from their scene's other settings, " +
                    std::to_string(estimate.unknown) + " guessed");
    }
    if (estimate.extra_rounds_s > 0.0)
      how.push_back("up to " + formatDuration(estimate.extra_rounds_s) + " of extra rounds");
    for (std::size_t k = 0; k < how.size(); ++k)
      line << (k == 0 ? " (" : "; ") << how[k] << (k + 1 == how.size() ? ")" : "");
  }
  line << ", results in " << out;
  return line.str();
}

}  // namespace collido::study
