#include <iostream>

#include <collido/host/backend_instance.h>
#include <collido/host/plugin_library.h>

#include "commands.h"

namespace collido::cli {
namespace {

int listBackends(const PluginOptions& options) {
  const PluginDiscovery found = discoverPlugins(options.paths, !options.no_defaults);
  if (found.plugins.empty()) std::cout << "No plugins found.\n";
  for (const auto& plugin : found.plugins) {
    const CollidoPluginTable& t = plugin->table();
    std::cout << plugin->name() << " " << t.plugin_version << " (" << t.engine_name << " "
              << t.engine_version << ")\n  file: " << plugin->path() << "\n";
    for (const VariantInfo& variant : plugin->variants()) {
      std::cout << "  " << variant.name << ": " << variant.summary << "\n";
      Result<std::unique_ptr<BackendInstance>> instance =
          BackendInstance::create(plugin, variant.name);
      if (!instance.ok()) {
        std::cout << "    cannot create: " << instance.status().message() << "\n";
        continue;
      }
      const Capabilities& caps = instance.value()->capabilities();
      std::cout << "    queries: " << queryKindsText(caps.queries)
                << "; update: " << (caps.update ? "yes" : "no")
                << "; counts box tests: " << (caps.counts_bv_tests ? "yes" : "no")
                << "; counts triangle tests: " << (caps.counts_primitive_tests ? "yes" : "no")
                << "; max contacts: "
                << (caps.max_contacts == 0 ? std::string("no limit")
                                           : std::to_string(caps.max_contacts))
                << "\n";
      if (!caps.notes.empty()) std::cout << "    notes: " << caps.notes << "\n";
    }
  }
  for (const std::string& problem : found.problems)
    std::cout << "problem: " << problem << "\n";
  return found.plugins.empty() ? 1 : 0;
}

}  // namespace

void addBackendsCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code) {
  CLI::App* command = app.add_subcommand(
      "backends", "List the backend plugins found, their variants, versions and capabilities");
  command->callback([&plugins, &exit_code] { exit_code = listBackends(plugins); });
}

}  // namespace collido::cli
