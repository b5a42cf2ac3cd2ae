// Plugins are looked at from child processes: dlopen runs a plugin's static constructors, and a
// plugin that crashes or hangs there would otherwise take the whole study down with it.
#include <collido/study/plugin_probe.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <collido/runner/runner.h>
#include <collido/study/worker_process.h>

namespace collido::study {
namespace {

Result<ProbedPlugin> probedFromJson(const std::string& text, const std::string& file) {
  try {
    const nlohmann::json json = nlohmann::json::parse(text);
    ProbedPlugin plugin;
    plugin.path = file;
    plugin.name = json.at("name").get<std::string>();
    plugin.version = json.at("version").get<std::string>();
    plugin.engine_name = json.at("engine_name").get<std::string>();
    plugin.engine_version = json.at("engine_version").get<std::string>();
    for (const nlohmann::json& v : json.at("variants"))
      plugin.variants.push_back(
          {v.at("name").get<std::string>(), v.at("summary").get<std::string>()});
    return plugin;
  } catch (const nlohmann::json::exception& e) {
    return Status(StatusCode::kInternal,
                  "plugin " + file + ": its probe's answer cannot be read: " + e.what());
  }
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The log's last line: the child's error message, when it refused the plugin.
std::string lastLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
    text.pop_back();
  const std::size_t newline = text.rfind('\n');
  text = newline == std::string::npos ? text : text.substr(newline + 1);
  if (text.rfind("error: ", 0) == 0) text.erase(0, 7);
  return text;
}

}  // namespace

const ProbedPlugin* PluginProbe::offering(const std::string& variant) const {
  for (const ProbedPlugin& plugin : plugins)
    for (const VariantInfo& v : plugin.variants)
      if (v.name == variant) return &plugin;
  return nullptr;
}

std::vector<std::string> PluginProbe::variantNames() const {
  std::vector<std::string> names;
  for (const ProbedPlugin& plugin : plugins)
    for (const VariantInfo& v : plugin.variants)
      names.push_back(v.name);
  return names;
}

nlohmann::json pluginInfoJson(const PluginLibrary& plugin) {
  const CollidoPluginTable& table = plugin.table();
  nlohmann::json variants = nlohmann::json::array();
  for (const VariantInfo& v : plugin.variants())
    variants.push_back({{"name", v.name}, {"summary", v.summary}});
  const auto text = [](const char* s) { return std::string(s != nullptr ? s : ""); };
  return {{"name", plugin.name()},
          {"version", text(table.plugin_version)},
          {"engine_name", text(table.engine_name)},
          {"engine_version", text(table.engine_version)},
          {"variants", std::move(variants)}};
}

PluginProbe probePlugins(const std::string& executable, const PluginCandidates& candidates,
                         double timeout_s, const std::string& scratch) {
  PluginProbe probe;
  probe.problems = candidates.problems;
  std::set<std::string> variants_seen;
  for (std::size_t i = 0; i < candidates.files.size(); ++i) {
    const std::string& file = candidates.files[i];
    const std::string answer = scratch + "/plugin_" + std::to_string(i) + ".json";
    WorkerLaunch launch;
    launch.executable = executable;
    launch.arguments = {"plugin-info", file, "--out", answer};
    launch.log_path = scratch + "/plugin_" + std::to_string(i) + ".log";
    launch.timeout_s = timeout_s;
    const WorkerOutcome outcome = runWorkerProcess(launch);
    std::error_code ec;
    if (outcome.status == "timeout") {
      probe.problems.push_back("plugin " + file + ": still loading after " +
                               std::to_string(static_cast<int>(timeout_s)) +
                               " s (hangs while loading); skipped");
    } else if (outcome.status == "crashed") {
      probe.problems.push_back("plugin " + file + ": crashed while loading (" +
                               outcome.signal_name + "); skipped");
    } else if (!outcome.ok()) {
      const std::string reason = lastLine(outcome.log_tail);
      probe.problems.push_back(reason.empty() ? "plugin " + file + ": cannot be loaded (exit " +
                                                    std::to_string(outcome.exit_code) + ")"
                                              : reason);
    } else if (Result<ProbedPlugin> plugin = probedFromJson(readAll(answer), file); !plugin.ok()) {
      probe.problems.push_back(plugin.status().message());
    } else {
      bool fresh = true;
      for (const VariantInfo& v : plugin.value().variants) {
        if (variants_seen.count(v.name) != 0) {
          probe.problems.push_back(shadowedVariantProblem(file, v.name));
          fresh = false;
        }
      }
      if (fresh) {
        for (const VariantInfo& v : plugin.value().variants)
          variants_seen.insert(v.name);
        probe.plugins.push_back(std::move(plugin).value());
      }
    }
    std::filesystem::remove(answer, ec);
    std::filesystem::remove(launch.log_path, ec);
  }
  return probe;
}

Result<std::vector<std::string>> pluginFilesOf(const std::vector<std::string>& backends,
                                               const PluginProbe& probe) {
  std::vector<std::string> files;
  for (const std::string& text : backends) {
    Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
        parseBackendText(text);
    if (!parsed.ok()) return parsed.status();
    const ProbedPlugin* plugin = probe.offering(parsed.value().first);
    if (plugin == nullptr) return unknownBackend(parsed.value().first, probe.variantNames());
    files.push_back(plugin->path);
  }
  return files;
}

}  // namespace collido::study
