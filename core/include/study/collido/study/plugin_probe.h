#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/backend.h>
#include <collido/host/plugin_library.h>
#include <collido/status.h>
#include <collido/study/not_applicable.h>

namespace collido::study {

/// What one plugin file offers, as read by a child process that loaded it.
struct ProbedPlugin {
  std::string path;  ///< the file
  std::string name;
  std::string version;  ///< of the plugin code
  std::string engine_name;
  std::string engine_version;
  std::vector<VariantInfo> variants;
  /// What each setting the probe was asked to create answers, by backend text; one that could
  /// not be created is missing.
  SettingAbilities abilities;
};

/// The plugins a study can use, none of them loaded into the driver.
struct PluginProbe {
  std::vector<ProbedPlugin> plugins;  ///< in discovery order; a shadowed plugin is left out
  std::vector<std::string> problems;  ///< each names its file: crashed, hung, refused, shadowed

  /// The plugin offering `variant`, or null.
  const ProbedPlugin* offering(const std::string& variant) const;
  /// Every variant name, in order.
  std::vector<std::string> variantNames() const;
};

/// The JSON a probe child writes about a plugin it loaded (collido plugin-info): its identity,
/// its variants, and what an instance of each of `settings` (backend texts of its variants,
/// options included) answers; a setting that cannot be created is left out.
nlohmann::json pluginInfoJson(const std::shared_ptr<PluginLibrary>& plugin,
                              const std::vector<std::string>& settings = {});

/// Loads each candidate in a child process of `executable` (`plugin-info FILE --out F`, at most
/// `timeout_s` seconds each), so that a plugin which crashes, aborts or hangs while loading is a
/// problem naming it, and the study goes on without it. The same variant in two plugins keeps
/// the first, as discoverPlugins does. `scratch` is a folder for the children's answers and logs.
PluginProbe probePlugins(const std::string& executable, const PluginCandidates& candidates,
                         double timeout_s, const std::string& scratch);

/// What each of `settings` answers (plan.h, applies()), options included (they may add query
/// kinds), from instances created in one child per plugin file (`plugin-info FILE --setting
/// S...`; the file each runs from is `plugin_file_of`, as pluginFilesOf gave it), apart from the
/// loading probe, so that an engine that crashes or hangs when created costs only this knowledge: a
/// setting whose child or instance failed is missing, and so planned everywhere, its worker then
/// saying what went wrong; a failed child is a problem added to `problems`.
SettingAbilities probeSettings(const std::string& executable,
                               const std::vector<std::string>& settings,
                               const std::map<std::string, std::string>& plugin_file_of,
                               double timeout_s, const std::string& scratch,
                               std::vector<std::string>& problems);

/// The plugin file each backend text ("variant" or "variant[k=v;...]") runs from, in order; an
/// unknown variant is an error listing the known ones.
Result<std::vector<std::string>> pluginFilesOf(const std::vector<std::string>& backends,
                                               const PluginProbe& probe);

}  // namespace collido::study
