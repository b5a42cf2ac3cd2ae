// Plugins are looked at from child processes: dlopen runs a plugin's static constructors, and a
// plugin that crashes or hangs there would otherwise take the whole study down with it.
#include <collido/study/plugin_probe.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <collido/host/backend_instance.h>
#include <collido/runner/runner.h>
#include <collido/study/worker_process.h>

namespace collido::study {
namespace {

// What an instance answers, as the probe child writes it.
nlohmann::json abilityJson(const Capabilities& caps) {
  return {{"query_kinds", caps.queries.bits()},
          {"builds_meshes", caps.buildsShape(ShapeKind::kTriangleMesh)}};
}

SettingAbility abilityFromJson(const nlohmann::json& json) {
  return {QueryKindSet(json.at("query_kinds").get<std::uint32_t>()),
          json.at("builds_meshes").get<bool>()};
}

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
    for (const nlohmann::json& setting : json.value("settings", nlohmann::json::array()))
      plugin.abilities[setting.at("backend").get<std::string>()] =
          abilityFromJson(setting.at("answers"));
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

// What a probe child does, for its problems: "loading" a plugin, or "creating its settings";
// and what follows when it fails ("skipped").
struct ChildTask {
  const char* doing;
  const char* then;
};
constexpr ChildTask kLoading{"loading", "skipped"};
constexpr ChildTask kCreating{"creating its settings",
                              "its settings are planned on every scene, since what they answer "
                              "is not known"};

// Loads `file` in a child (`plugin-info FILE --out F [--setting S]...`) and reads its answer; a
// child that hangs, crashes or refuses the plugin gives a problem naming the file.
Result<ProbedPlugin> probeInChild(const std::string& executable, const std::string& file,
                                  const std::vector<std::string>& settings, double timeout_s,
                                  const std::string& scratch_stem, const ChildTask& task) {
  const std::string answer = scratch_stem + ".json";
  WorkerLaunch launch;
  launch.executable = executable;
  launch.arguments = {"plugin-info", file, "--out", answer};
  for (const std::string& setting : settings) {
    launch.arguments.push_back("--setting");
    launch.arguments.push_back(setting);
  }
  launch.log_path = scratch_stem + ".log";
  launch.timeout_s = timeout_s;
  const WorkerOutcome outcome = runWorkerProcess(launch);
  const std::string doing = task.doing;
  const std::string then = task.then;
  const auto read = [&]() -> Result<ProbedPlugin> {
    if (outcome.status == WorkerStatus::kTimeout) {
      return Status(StatusCode::kEngineFailure, "plugin " + file + ": still " + doing + " after " +
                                                    std::to_string(static_cast<int>(timeout_s)) +
                                                    " s (hangs while " + doing + "); " + then);
    }
    if (outcome.status == WorkerStatus::kCrashed) {
      return Status(StatusCode::kEngineFailure, "plugin " + file + ": crashed while " + doing +
                                                    " (" + outcome.signal_name + "); " + then);
    }
    if (!outcome.ok()) {
      const std::string reason = lastLine(outcome.log_tail);
      return Status(StatusCode::kInvalidArgument,
                    reason.empty() ? "plugin " + file + ": cannot be loaded (exit " +
                                         std::to_string(outcome.exit_code) + ")"
                                   : reason);
    }
    return probedFromJson(readAll(answer), file);
  };
  Result<ProbedPlugin> plugin = read();
  std::error_code ec;
  std::filesystem::remove(answer, ec);
  std::filesystem::remove(launch.log_path, ec);
  return plugin;
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

nlohmann::json pluginInfoJson(const std::shared_ptr<PluginLibrary>& plugin,
                              const std::vector<std::string>& settings) {
  // What an instance of `variant` with `options` answers; null when it cannot be created.
  // With the runner's sub-steps, a setting answers every kind over a step from its booleans.
  const auto answers = [&plugin](const std::string& variant,
                                 const std::map<std::string, std::string>& options) {
    const BackendSpec spec{plugin, variant, options};
    Result<std::unique_ptr<BackendInstance>> instance =
        BackendInstance::create(plugin, variant, spec.pluginOptions());
    if (!instance.ok()) return nlohmann::json();
    Capabilities caps = instance.value()->capabilities();
    if (spec.substeps() > 0 && caps.queries.contains(QueryKind::kBoolean)) {
      for (const QueryKindInfo& kind : kQueryKinds)
        if (kind.over_a_step) caps.queries |= kind.kind;
    }
    return abilityJson(caps);
  };
  const CollidoPluginTable& table = plugin->table();
  nlohmann::json variants = nlohmann::json::array();
  for (const VariantInfo& v : plugin->variants())
    variants.push_back({{"name", v.name}, {"summary", v.summary}});
  nlohmann::json probed = nlohmann::json::array();
  for (const std::string& setting : settings) {
    Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
        parseBackendText(setting);
    if (!parsed.ok() || !plugin->hasVariant(parsed.value().first)) continue;
    if (nlohmann::json a = answers(parsed.value().first, parsed.value().second); !a.is_null())
      probed.push_back({{"backend", setting}, {"answers", std::move(a)}});
  }
  const auto text = [](const char* s) { return std::string(s != nullptr ? s : ""); };
  return {{"name", plugin->name()},
          {"version", text(table.plugin_version)},
          {"engine_name", text(table.engine_name)},
          {"engine_version", text(table.engine_version)},
          {"variants", std::move(variants)},
          {"settings", std::move(probed)}};
}

PluginProbe probePlugins(const std::string& executable, const PluginCandidates& candidates,
                         double timeout_s, const std::string& scratch) {
  PluginProbe probe;
  probe.problems = candidates.problems;
  std::set<std::string> variants_seen;
  for (std::size_t i = 0; i < candidates.files.size(); ++i) {
    const std::string& file = candidates.files[i];
    Result<ProbedPlugin> plugin = probeInChild(executable, file, {}, timeout_s,
                                               scratch + "/plugin_" + std::to_string(i), kLoading);
    if (!plugin.ok()) {
      probe.problems.push_back(plugin.status().message());
      continue;
    }
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
  return probe;
}

SettingAbilities probeSettings(const std::string& executable,
                               const std::vector<std::string>& settings,
                               const std::map<std::string, std::string>& plugin_file_of,
                               double timeout_s, const std::string& scratch,
                               std::vector<std::string>& problems) {
  SettingAbilities abilities;
  std::map<std::string, std::vector<std::string>> by_file;
  for (const std::string& setting : settings) {
    if (const auto file = plugin_file_of.find(setting); file != plugin_file_of.end())
      by_file[file->second].push_back(setting);
  }
  std::size_t child = 0;
  for (const auto& [file, texts] : by_file) {
    Result<ProbedPlugin> plugin =
        probeInChild(executable, file, texts, timeout_s,
                     scratch + "/setting_" + std::to_string(child++), kCreating);
    if (!plugin.ok()) {
      problems.push_back(plugin.status().message());
      continue;
    }
    for (const std::string& text : texts) {
      if (const auto known = plugin.value().abilities.find(text);
          known != plugin.value().abilities.end())
        abilities[text] = known->second;
    }
  }
  return abilities;
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
