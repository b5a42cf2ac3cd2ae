#include <iostream>
#include <string>
#include <vector>

#include <collido/host/plugin_library.h>
#include <collido/host/variant_description.h>

#include "commands.h"

namespace collido::cli {
namespace {

// Lists what loaded on stdout and every problem on stderr: a plugin that did not load, or a
// variant that cannot be created, makes the exit code 1 (a script or CI notices).
int listBackends(const PluginOptions& options) {
  const PluginDiscovery found = discoverPlugins(options.paths, !options.no_defaults);
  std::vector<std::string> problems = found.problems;
  if (found.plugins.empty()) problems.push_back("no plugins found");
  for (const auto& plugin : found.plugins) {
    const CollidoPluginTable& t = plugin->table();
    std::cout << plugin->name() << " " << t.plugin_version << " (" << t.engine_name << " "
              << t.engine_version << ")\n  file: " << plugin->path() << "\n";
    for (const VariantDescription& variant : describeVariants(plugin)) {
      std::cout << "  " << variant.info.name << ": " << variant.info.summary << "\n";
      if (!variant.capabilities) {
        std::cout << "    cannot create: " << variant.problem << "\n";
        problems.push_back(variant.info.name + ": cannot create: " + variant.problem);
        continue;
      }
      const Capabilities& caps = *variant.capabilities;
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
  for (const std::string& problem : problems)
    std::cerr << "problem: " << problem << "\n";
  return problems.empty() ? 0 : 1;
}

}  // namespace

void addBackendsCommand(CLI::App& app, const PluginOptions& plugins, int& exit_code) {
  CLI::App* command = app.add_subcommand(
      "backends",
      "List the backend plugins found, their variants, versions and capabilities. Exit code 1, "
      "with the problems on stderr, when a plugin could not be loaded or a variant created");
  command->callback([&plugins, &exit_code] { exit_code = listBackends(plugins); });
}

}  // namespace collido::cli
