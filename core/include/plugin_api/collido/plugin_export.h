#pragma once

#include <vector>

#include <collido/backend.h>
#include <collido/plugin_api.h>

namespace collido::detail {

/// The C table of a plugin and the variant array it points into; one static per plugin, so it
/// lives exactly as long as the library (no heap blocks left behind by dlclose).
struct PluginTableStorage {
  PluginTableStorage(const PluginInfo& info, decltype(CollidoPluginTable::create) create);
  std::vector<CollidoVariantInfo> variants;
  CollidoPluginTable table{};
};

/// The C create() shared by all plugins, parameterised by the plugin's description.
std::int32_t createInstance(const PluginInfo& info, const char* variant,
                            const CollidoOption* options, std::uint32_t option_count,
                            CollidoInstance** out, CollidoMessage* error);

/// One C table per description function, so each plugin gets its own create().
template <const PluginInfo& (*Describe)()>
const CollidoPluginTable* pluginTable() {
  struct Entry {
    static std::int32_t create(const char* variant, const CollidoOption* options,
                               std::uint32_t option_count, CollidoInstance** out,
                               CollidoMessage* error) {
      return createInstance(Describe(), variant, options, option_count, out, error);
    }
  };
  static const PluginTableStorage storage(Describe(), &Entry::create);
  return &storage.table;
}

}  // namespace collido::detail

/// Exports a plugin: `describe` is a function returning `const collido::PluginInfo&`. Defines
/// `collido_plugin_table_<id>()`, which static builds (tests) call by name; the shared-library
/// build adds the COLLIDO_PLUGIN_ENTRY_SYMBOL that forwards to it (cmake/CollidoBackend.cmake).
#define COLLIDO_DEFINE_PLUGIN(id, describe)                              \
  extern "C" const CollidoPluginTable* collido_plugin_table_##id(void) { \
    return ::collido::detail::pluginTable<&describe>(); /* NOLINT */     \
  }

/// For a plugin library built on its own (not through collido_add_plugin, e.g. outside this
/// source tree): COLLIDO_DEFINE_PLUGIN plus the exported COLLIDO_PLUGIN_ENTRY_SYMBOL. Use it in
/// exactly one file of the library.
#define COLLIDO_EXPORT_PLUGIN(id, describe)                                   \
  COLLIDO_DEFINE_PLUGIN(id, describe)                                         \
  extern "C" __attribute__((visibility("default"))) const CollidoPluginTable* \
  collido_plugin_table(void) {                                                \
    return collido_plugin_table_##id();                                       \
  }
