// collido report: the dashboard of a study folder as one self-contained HTML page.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/io/html_page.h>
#include <collido/study/report_html.h>
#include <collido/study/result_store.h>

#include "commands.h"

namespace collido::cli {
namespace {

struct ReportArguments {
  std::string directory;
  std::string output;
  std::string baseline;
  std::string web;
  std::string title;
  std::vector<std::string> pose_error;        ///< collido pose-error --json files
  std::vector<std::string> surface_distance;  ///< collido surface-distance --json files
  std::vector<std::string> frep;              ///< collido frep --json files
};

// A results file written by another command's --json (`marker` is its format key, `array` a
// field that must be an array), checked enough to draw.
Result<nlohmann::json> readResultsFile(const std::string& path, const char* marker,
                                       const char* array, const char* how) {
  Result<nlohmann::json> json = io::readJsonFile(path, "file not found");
  if (!json.ok()) return json.status();
  const nlohmann::json& root = json.value();
  if (!root.is_object() || root.value(marker, 0) != 1 || !root.contains(array) ||
      !root.at(array).is_array()) {
    return Status(StatusCode::kInvalidArgument, path + ": not a file of " + how);
  }
  return json;
}

// The FRep file's preview picture (named relative to the JSON file) inlined as a data URI, so
// that the dashboard stays one file that opens offline.
Result<nlohmann::json> withInlinePreview(nlohmann::json comparison, const std::string& json_path) {
  if (!comparison.contains("preview")) return comparison;
  if (!comparison["preview"].is_string())
    return Status(StatusCode::kInvalidArgument, json_path + ": /preview: expected a file name");
  const std::filesystem::path picture =
      std::filesystem::path(json_path).parent_path() / comparison["preview"].get<std::string>();
  std::ifstream in(picture, std::ios::binary);
  if (!in) {
    return Status(StatusCode::kInvalidArgument,
                  json_path + ": /preview: " + picture.string() + " not found");
  }
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  comparison["preview_png"] = "data:image/png;base64," + io::base64(bytes);
  return comparison;
}

// The files of `folder` with `extension` (".html"), in name order; none when it does not exist.
std::vector<std::string> filesIn(const std::filesystem::path& folder, const char* extension) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    if (entry.path().extension() == extension) files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The scenes' 3D views beside the study (<study>/views/<scene>.html, made by collido view; see
// tools/study.sh), linked relative to the report so the pair can be moved together.
nlohmann::json sceneViews(const std::string& directory, const std::string& output) {
  nlohmann::json views = nlohmann::json::array();
  const std::filesystem::path from =
      std::filesystem::absolute(std::filesystem::path(output)).parent_path();
  std::error_code ec;
  for (const std::filesystem::path page :
       filesIn(std::filesystem::path(directory) / "views", ".html")) {
    views.push_back(
        {{"scene", page.stem().string()},
         {"href",
          std::filesystem::relative(std::filesystem::absolute(page), from, ec).generic_string()}});
  }
  return views;
}

int runReport(ReportArguments args) {
  // Without explicit files, the comparisons the study wrote beside its results (collido study
  // --surfaces / --frep).
  const std::filesystem::path study(args.directory);
  if (args.surface_distance.empty()) args.surface_distance = filesIn(study / "surfaces", ".json");
  if (args.frep.empty()) args.frep = filesIn(study / "frep", ".json");
  Result<std::vector<study::CombinationResult>> results = readStudy(args.directory);
  if (!results.ok()) {
    std::cerr << "error: " << results.status().message() << "\n";
    return 2;
  }
  std::vector<study::CombinationResult> baseline;
  if (!args.baseline.empty()) {
    Result<std::vector<study::CombinationResult>> before = readStudy(args.baseline);
    if (!before.ok()) {
      std::cerr << "error: " << before.status().message() << "\n";
      return 2;
    }
    baseline = std::move(before).value();
  }
  const std::string title =
      args.title.empty()
          ? std::filesystem::absolute(args.directory).lexically_normal().filename().string()
          : args.title;
  const std::string output = args.output.empty()
                                 ? (std::filesystem::path(args.directory) / "report.html").string()
                                 : args.output;
  Result<std::vector<study::NotApplicable>> not_applicable =
      study::ResultStore(args.directory).readNotApplicable();
  if (!not_applicable.ok()) {
    std::cerr << "error: " << not_applicable.status().message() << "\n";
    return 2;
  }
  nlohmann::json data = study::reportData(results.value(), baseline, title, not_applicable.value());
  data["pose_error"] = nlohmann::json::array();
  for (const std::string& path : args.pose_error) {
    Result<nlohmann::json> sweep =
        readResultsFile(path, "collidoscope_pose_error", "rows", "collido pose-error --json");
    if (!sweep.ok()) {
      std::cerr << "error: --pose-error: " << sweep.status().message() << "\n";
      return 2;
    }
    data["pose_error"].push_back(std::move(sweep).value());
  }
  data["surfaces"] = nlohmann::json::array();
  for (const std::string& path : args.surface_distance) {
    Result<nlohmann::json> comparison = readResultsFile(
        path, "collidoscope_surface_distance", "backends", "collido surface-distance --json");
    if (!comparison.ok()) {
      std::cerr << "error: --surface-distance: " << comparison.status().message() << "\n";
      return 2;
    }
    data["surfaces"].push_back(std::move(comparison).value());
  }
  data["frep"] = nlohmann::json::array();
  for (const std::string& path : args.frep) {
    Result<nlohmann::json> comparison =
        readResultsFile(path, "collidoscope_frep", "comparators", "collido frep --json");
    if (comparison.ok()) comparison = withInlinePreview(std::move(comparison).value(), path);
    if (!comparison.ok()) {
      std::cerr << "error: --frep: " << comparison.status().message() << "\n";
      return 2;
    }
    data["frep"].push_back(std::move(comparison).value());
  }
  data["views"] = sceneViews(args.directory, output);
  Result<std::string> html = study::renderReport(data, study::webDirectory(args.web));
  if (!html.ok()) {
    std::cerr << "error: " << html.status().message() << "\n";
    return 2;
  }
  if (Status s = io::writeFileAtomically(output, html.value()); !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }
  std::cerr << "report: " << output << " (" << results.value().size() << " combinations"
            << (baseline.empty() ? "" : ", against " + args.baseline) << ")\n";
  return 0;
}

}  // namespace

Result<std::vector<study::CombinationResult>> readStudy(const std::string& directory) {
  std::error_code ec;
  if (!std::filesystem::is_directory(std::filesystem::path(directory) / "results", ec)) {
    return Status(StatusCode::kInvalidArgument,
                  directory + ": not a study folder (no results/; make one with collido study)");
  }
  return study::ResultStore(directory).readAll();
}

void addReportCommand(CLI::App& app, int& exit_code) {
  CLI::App* command = app.add_subcommand(
      "report",
      "Write a study's dashboard: one HTML file that opens offline, with time against error, "
      "time distributions, memory, scaling, failures, needs, and a comparison with a baseline");
  auto args = std::make_shared<ReportArguments>();
  command->add_option("directory", args->directory, "study folder (collido study --out)")
      ->required();
  command->add_option("-o,--output", args->output,
                      "the HTML file (default: DIRECTORY/report.html)");
  command->add_option("--baseline", args->baseline,
                      "an earlier study folder to compare with (before/after)");
  command->add_option("--web", args->web,
                      "the front-end folder (default: $COLLIDO_WEB_DIR, else the "
                      "install's share/collido/web, else the source web/)");
  command->add_option("--title", args->title, "the page's title (default: the folder's name)");
  command->add_option("--pose-error", args->pose_error,
                      "pose-error sweeps to show (collido pose-error --json files; repeatable)");
  command->add_option("--surface-distance", args->surface_distance,
                      "NURBS distance comparisons to show (collido surface-distance --json "
                      "files; repeatable; default: the study's own, DIRECTORY/surfaces/*.json)");
  command->add_option("--frep", args->frep,
                      "FRep comparisons to show (collido frep --json files, with their --preview "
                      "pictures; repeatable; default: the study's own, DIRECTORY/frep/*.json)");
  command->callback([args, &exit_code] { exit_code = runReport(*args); });
}

}  // namespace collido::cli
