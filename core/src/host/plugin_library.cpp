#include <collido/host/plugin_library.h>

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <set>
#include <sstream>

namespace collido {
namespace {

namespace fs = std::filesystem;

Status tableError(const std::string& label, const std::string& problem) {
  return {StatusCode::kInvalidArgument, "plugin " + label + ": " + problem};
}

bool isPluginFileName(const fs::path& file) {
  const std::string name = file.filename().string();
  return name.rfind("libcollido_plugin_", 0) == 0 && file.extension() == ".so";
}

}  // namespace

Status checkPluginTable(const CollidoPluginTable* table, const std::string& label) {
  if (table == nullptr) return tableError(label, "the entry point returned no table");
  if (table->abi_version != COLLIDO_PLUGIN_ABI_VERSION) {
    return tableError(label, "built for plugin interface version " +
                                 std::to_string(table->abi_version) +
                                 ", but this Collidoscope uses version " +
                                 std::to_string(COLLIDO_PLUGIN_ABI_VERSION) +
                                 "; rebuild the plugin against this Collidoscope");
  }
  if (table->struct_size < sizeof(CollidoPluginTable)) {
    return tableError(label, "table is " + std::to_string(table->struct_size) +
                                 " bytes, expected " + std::to_string(sizeof(CollidoPluginTable)));
  }
  if (table->plugin_name == nullptr || *table->plugin_name == '\0') {
    return tableError(label, "the table has no plugin name");
  }
  if (table->variant_count == 0 || table->variants == nullptr) {
    return tableError(label, "the table lists no variants");
  }
  for (std::uint32_t i = 0; i < table->variant_count; ++i) {
    if (table->variants[i].name == nullptr || *table->variants[i].name == '\0') {
      return tableError(label, "variant " + std::to_string(i) + " has no name");
    }
  }
  if (table->create == nullptr || table->destroy == nullptr || table->capabilities == nullptr ||
      table->build == nullptr || table->update == nullptr || table->query == nullptr ||
      table->memory == nullptr || table->release == nullptr) {
    return tableError(label, "the table is missing a function");
  }
  return {};
}

Result<std::shared_ptr<PluginLibrary>> PluginLibrary::open(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return tableError(path, "file not found");
  dlerror();
  // RTLD_NODELETE: a plugin stays mapped after dlclose. Engines keep process-wide state (ODE's
  // dInitODE2 data, per-thread caches) that no one may free while another instance could still
  // use it; unmapping their code and globals under it would turn that state into dangling
  // memory (and leak reports), for no gain in a process that loads a handful of plugins.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (handle == nullptr) {
    const char* why = dlerror();
    return tableError(path, std::string("cannot load it as a shared library: ") +
                                (why != nullptr ? why : "unknown reason"));
  }
  void* symbol = dlsym(handle, COLLIDO_PLUGIN_ENTRY_SYMBOL);
  if (symbol == nullptr) {
    dlclose(handle);
    return tableError(path, std::string("not a Collidoscope plugin: no '") +
                                COLLIDO_PLUGIN_ENTRY_SYMBOL + "' entry point");
  }
  CollidoPluginEntry entry = nullptr;
  static_assert(sizeof(entry) == sizeof(symbol), "function and object pointers differ in size");
  std::memcpy(&entry, &symbol, sizeof(entry));  // dlsym returns void*; POSIX guarantees this
  const CollidoPluginTable* table = entry();
  if (Status s = checkPluginTable(table, path); !s.ok()) {
    dlclose(handle);
    return s;
  }
  return std::shared_ptr<PluginLibrary>(new PluginLibrary(path, handle, table));
}

Result<std::shared_ptr<PluginLibrary>> PluginLibrary::fromTable(const CollidoPluginTable* table,
                                                                const std::string& label) {
  if (Status s = checkPluginTable(table, label); !s.ok()) return s;
  return std::shared_ptr<PluginLibrary>(new PluginLibrary(label, nullptr, table));
}

PluginLibrary::~PluginLibrary() {
  if (handle_ != nullptr) dlclose(handle_);
}

std::vector<VariantInfo> PluginLibrary::variants() const {
  std::vector<VariantInfo> out;
  for (std::uint32_t i = 0; i < table_->variant_count; ++i) {
    const CollidoVariantInfo& v = table_->variants[i];
    out.push_back(VariantInfo{v.name, v.summary != nullptr ? v.summary : ""});
  }
  return out;
}

bool PluginLibrary::hasVariant(const std::string& variant) const {
  for (std::uint32_t i = 0; i < table_->variant_count; ++i) {
    if (variant == table_->variants[i].name) return true;
  }
  return false;
}

std::string executableDirectory() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : exe.parent_path().string();
}

std::vector<std::string> defaultPluginDirectories() {
  std::vector<std::string> dirs;
  const std::string exe_dir = executableDirectory();
  if (!exe_dir.empty()) {
    dirs.push_back(exe_dir + "/plugins");
    // The install's plugins, named without ".." so that listings show the real path.
    dirs.push_back((fs::path(exe_dir).parent_path() / "lib" / "collido" / "plugins").string());
  }
  if (const char* env = std::getenv("COLLIDO_PLUGIN_PATH"); env != nullptr) {
    std::stringstream list(env);
    std::string dir;
    while (std::getline(list, dir, ':')) {
      if (!dir.empty()) dirs.push_back(dir);
    }
  }
  return dirs;
}

PluginCandidates pluginCandidates(const std::vector<std::string>& paths, bool use_defaults) {
  PluginCandidates found;
  std::set<std::string> files_seen;
  const auto consider = [&](const std::string& file) {
    std::error_code ec;
    const std::string canonical = fs::weakly_canonical(file, ec).string();
    if (files_seen.insert(ec ? file : canonical).second) found.files.push_back(file);
  };
  const auto scan = [&](const std::string& path, bool explicit_path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      std::vector<std::string> files;
      for (const fs::directory_entry& entry : fs::directory_iterator(path, ec)) {
        if (entry.is_regular_file(ec) && isPluginFileName(entry.path())) {
          files.push_back(entry.path().string());
        }
      }
      std::sort(files.begin(), files.end());
      for (const std::string& file : files)
        consider(file);
    } else if (fs::exists(path, ec)) {
      consider(path);
    } else if (explicit_path) {
      found.problems.push_back("plugin " + path + ": file not found");
    }
  };
  for (const std::string& path : paths)
    scan(path, true);
  if (use_defaults) {
    for (const std::string& dir : defaultPluginDirectories())
      scan(dir, false);
  }
  return found;
}

std::string shadowedVariantProblem(const std::string& file, const std::string& variant) {
  return "plugin " + file + ": variant '" + variant +
         "' is already provided by an earlier plugin; this one is ignored";
}

PluginDiscovery discoverPlugins(const std::vector<std::string>& paths, bool use_defaults) {
  const PluginCandidates candidates = pluginCandidates(paths, use_defaults);
  PluginDiscovery found;
  found.problems = candidates.problems;
  std::set<std::string> variants_seen;
  for (const std::string& file : candidates.files) {
    Result<std::shared_ptr<PluginLibrary>> plugin = PluginLibrary::open(file);
    if (!plugin.ok()) {
      found.problems.push_back(plugin.status().message());
      continue;
    }
    bool fresh = true;
    for (const VariantInfo& v : plugin.value()->variants()) {
      if (variants_seen.count(v.name) != 0) {
        found.problems.push_back(shadowedVariantProblem(file, v.name));
        fresh = false;
      }
    }
    if (!fresh) continue;
    for (const VariantInfo& v : plugin.value()->variants())
      variants_seen.insert(v.name);
    found.plugins.push_back(std::move(plugin).value());
  }
  return found;
}

}  // namespace collido
