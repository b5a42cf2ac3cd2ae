// A plugin built for another interface version: its table says COLLIDO_PLUGIN_ABI_VERSION + 1.
// The host must refuse it after reading abi_version and nothing else, naming the file and both
// versions. Every other field is left zero on purpose: a host that read further would crash.
#include <collido/plugin_api.h>

extern "C" __attribute__((visibility("default"))) const CollidoPluginTable* collido_plugin_table(
    void) {
  static const CollidoPluginTable table = {COLLIDO_PLUGIN_ABI_VERSION + 1u,
                                           sizeof(CollidoPluginTable),
                                           nullptr,
                                           nullptr,
                                           nullptr,
                                           nullptr,
                                           0,
                                           0,
                                           nullptr,
                                           nullptr,
                                           nullptr,
                                           nullptr,
                                           nullptr,
                                           nullptr,
                                           nullptr,
                                           nullptr,
                                           nullptr};
  return &table;
}
