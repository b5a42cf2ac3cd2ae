#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <collido/backend.h>
#include <collido/host/plugin_library.h>

namespace collido {

/// A plugin's variant as `collido backends` lists it: its name and summary, and what an instance
/// of it reports it can do, or why no instance could be created.
struct VariantDescription {
  VariantInfo info;
  std::optional<Capabilities> capabilities;  ///< absent when it cannot be created
  std::string problem;                       ///< why it cannot be created
};

/// Creates one instance of each of the plugin's variants, with default options, and describes it.
std::vector<VariantDescription> describeVariants(const std::shared_ptr<PluginLibrary>& plugin);

}  // namespace collido
