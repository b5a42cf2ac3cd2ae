// A backend variant as the benchmarks run it, shared by the benchmark files.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <collido/host/backend_instance.h>
#include <collido/host/plugin_library.h>

namespace collido::bench {

/// A variant of a loaded plugin with its options.
struct Variant {
  std::shared_ptr<PluginLibrary> library;
  std::string name;
  std::map<std::string, std::string> options;
  std::string label;  // as in the study's tables: "variant" or "variant[key=value;...]"
};

/// An instance of the variant, or none after marking the benchmark skipped with the reason.
inline std::unique_ptr<BackendInstance> createOrSkip(const Variant& variant,
                                                     benchmark::State& state) {
  Result<std::unique_ptr<BackendInstance>> instance =
      BackendInstance::create(variant.library, variant.name, variant.options);
  if (!instance.ok()) {
    state.SkipWithError(instance.status().message().c_str());
    return nullptr;
  }
  return std::move(instance).value();
}

}  // namespace collido::bench
