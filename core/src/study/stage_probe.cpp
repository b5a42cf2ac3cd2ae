// The study's second stage: which backend settings run, found by child processes that load the
// plugins, so that a plugin that crashes while loading costs its settings, not the study.
#include <unistd.h>

#include <filesystem>
#include <set>

#include "stages.h"

namespace collido::study {
namespace {

// The backend settings to run: the sweep's (restricted to the variants --backends names, plus
// any --backends entry the sweep does not mention), else --backends, else every variant found.
// An optional sweep entry that no plugin offers is left out with a warning (the GPL-only cgal
// comparator in a default build).
std::vector<std::string> backendSettings(const StudyRequest& args, const Sweep& sweep,
                                         const PluginProbe& found, std::ostream& err) {
  std::vector<std::string> settings;
  std::set<std::string> named;
  for (const std::string& text : args.backends) {
    Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
        parseBackendText(text);
    named.insert(parsed.ok() ? parsed.value().first : text);
  }
  std::set<std::string> swept;
  for (const SweepBackend& backend : sweep.backends) {
    swept.insert(backend.variant);
    if (!named.empty() && named.count(backend.variant) == 0) continue;
    if (backend.optional && found.offering(backend.variant) == nullptr) {
      err << "warning: sweep: no plugin offers the optional '" << backend.variant
          << "'; left out\n";
      continue;
    }
    for (const std::string& setting : backend.settings())
      settings.push_back(setting);
  }
  for (const std::string& text : args.backends) {
    Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
        parseBackendText(text);
    if (!parsed.ok() || swept.count(parsed.value().first) == 0) settings.push_back(text);
  }
  if (settings.empty() && args.backends.empty() && sweep.backends.empty())
    settings = found.variantNames();
  return settings;
}

// The settings a kind of comparison runs: its sweep entry's, else the mesh settings; a setting
// no plugin offers is left out with a warning (OpenCASCADE is optional, and a sweep may name it).
std::vector<std::string> comparisonSettings(const SweepComparison& sweep,
                                            const std::vector<std::string>& mesh_settings,
                                            const PluginProbe& found, const char* what,
                                            std::ostream& err) {
  std::vector<std::string> settings;
  for (const std::string& text : sweep.backends.empty() ? mesh_settings : sweep.backends) {
    Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
        parseBackendText(text);
    if (parsed.ok() && found.offering(parsed.value().first) != nullptr) {
      settings.push_back(text);
    } else {
      err << "warning: " << what << ": no plugin offers '" << text << "'; left out\n";
    }
  }
  return settings;
}

// A scratch folder for the probe children's answers, removed with it.
class ProbeScratch {
 public:
  ProbeScratch() {
    std::error_code ec;
    path_ =
        (std::filesystem::temp_directory_path(ec) / ("collido_plugins_" + std::to_string(getpid())))
            .string();
    std::filesystem::create_directories(path_, ec);
  }
  ProbeScratch(const ProbeScratch&) = delete;
  ProbeScratch& operator=(const ProbeScratch&) = delete;
  ~ProbeScratch() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// The plugins, each looked at by a child process, so that none is loaded into the driver.
PluginProbe probeInChildren(const StudyRequest& request) {
  const PluginCandidates candidates =
      pluginCandidates(request.plugin_paths, request.default_plugins);
  const ProbeScratch scratch;
  return probePlugins(request.executable, candidates, request.plugin_timeout_s, scratch.path());
}

// What each mesh setting answers, so the plan leaves out those a scene cannot use.
SettingAbilities abilitiesInChildren(const StudyRequest& request,
                                     const std::vector<std::string>& settings,
                                     const std::map<std::string, std::string>& plugin_file_of,
                                     std::ostream& err) {
  const ProbeScratch scratch;
  std::vector<std::string> problems;
  SettingAbilities abilities = probeSettings(request.executable, settings, plugin_file_of,
                                             request.plugin_timeout_s, scratch.path(), problems);
  for (const std::string& problem : problems)
    err << "warning: " << problem << "\n";
  return abilities;
}

}  // namespace

Result<StudyBackends> probeBackends(const StudyRequest& request, const StudyInputs& inputs,
                                    std::ostream& err) {
  StudyBackends out;
  out.found = probeInChildren(request);
  for (const std::string& problem : out.found.problems)
    err << "warning: " << problem << "\n";
  const Sweep& sweep = inputs.sweep;
  out.settings = backendSettings(request, sweep, out.found, err);
  if (!inputs.surface_files.empty()) {
    out.surface_settings =
        comparisonSettings(sweep.surfaces, out.settings, out.found, "surfaces", err);
  }
  if (!inputs.frep_files.empty())
    out.frep_settings = comparisonSettings(sweep.frep, out.settings, out.found, "frep", err);
  std::vector<std::string> every_setting = out.settings;
  every_setting.insert(every_setting.end(), out.surface_settings.begin(),
                       out.surface_settings.end());
  every_setting.insert(every_setting.end(), out.frep_settings.begin(), out.frep_settings.end());
  Result<std::vector<std::string>> plugin_files = pluginFilesOf(every_setting, out.found);
  if (!plugin_files.ok()) return plugin_files.status();
  for (std::size_t i = 0; i < every_setting.size(); ++i)
    out.plugin_file_of[every_setting[i]] = plugin_files.value()[i];
  if (out.settings.empty()) {
    return Status(StatusCode::kInvalidArgument,
                  "no backends to run (build the plugins or pass --plugin)");
  }
  out.abilities = abilitiesInChildren(request, out.settings, out.plugin_file_of, err);
  return out;
}

}  // namespace collido::study
