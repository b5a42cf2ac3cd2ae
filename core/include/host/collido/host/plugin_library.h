#pragma once

#include <memory>
#include <string>
#include <vector>

#include <collido/backend.h>
#include <collido/plugin_api.h>
#include <collido/status.h>

namespace collido {

/// A plugin whose table passed the checks, and the library that keeps it in memory.
class PluginLibrary {
 public:
  /// Loads a plugin shared library (dlopen) and checks its table. Errors name the file: not
  /// found, not a shared library, no entry point, another interface version, a broken table.
  static Result<std::shared_ptr<PluginLibrary>> open(const std::string& path);
  /// Wraps a table linked into this program (tests call the entry function by name).
  static Result<std::shared_ptr<PluginLibrary>> fromTable(const CollidoPluginTable* table,
                                                          const std::string& label);

  PluginLibrary(const PluginLibrary&) = delete;
  PluginLibrary& operator=(const PluginLibrary&) = delete;
  ~PluginLibrary();

  /// The file it came from, or the label of a linked-in table.
  const std::string& path() const { return path_; }
  const CollidoPluginTable& table() const { return *table_; }
  std::string name() const { return table_->plugin_name; }
  std::vector<VariantInfo> variants() const;
  bool hasVariant(const std::string& variant) const;

 private:
  PluginLibrary(std::string path, void* handle, const CollidoPluginTable* table)
      : path_(std::move(path)), handle_(handle), table_(table) {}

  std::string path_;
  void* handle_ = nullptr;  // from dlopen; null for linked-in tables
  const CollidoPluginTable* table_ = nullptr;
};

/// Checks a table before anything else is read from it: the interface version first (refused
/// with both versions named), then its size, names and function pointers.
Status checkPluginTable(const CollidoPluginTable* table, const std::string& label);

/// The folder of the running executable ("" when it cannot be read from /proc/self/exe).
std::string executableDirectory();

/// Where plugins are looked for, in order: the `plugins` folder beside the running executable
/// (the build tree), `../lib/collido/plugins` relative to it (an install), then each folder of
/// the COLLIDO_PLUGIN_PATH environment variable (colon-separated).
std::vector<std::string> defaultPluginDirectories();

/// The plugin files to consider, in order, without loading any: each file of `paths` (a folder
/// gives its `libcollido_plugin_*.so` files, sorted), then, if `use_defaults`, those of
/// defaultPluginDirectories(); a file seen twice counts once. A missing explicit path is a
/// problem.
struct PluginCandidates {
  std::vector<std::string> files;
  std::vector<std::string> problems;
};
PluginCandidates pluginCandidates(const std::vector<std::string>& paths, bool use_defaults = true);

/// The problem recorded when `file` offers a variant an earlier plugin already gave.
std::string shadowedVariantProblem(const std::string& file, const std::string& variant);

/// The plugins found, and what went wrong on the way (each problem names its file).
struct PluginDiscovery {
  std::vector<std::shared_ptr<PluginLibrary>> plugins;
  std::vector<std::string> problems;
};

/// Loads every plugin in `paths` (files are loaded whatever their name; folders contribute their
/// `libcollido_plugin_*.so` files) and then, if `use_defaults`, in defaultPluginDirectories().
/// A variant offered by an earlier plugin shadows a later one of the same name (a problem is
/// recorded), so an explicit path overrides the build tree.
PluginDiscovery discoverPlugins(const std::vector<std::string>& paths, bool use_defaults = true);

}  // namespace collido
