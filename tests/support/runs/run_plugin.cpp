#include "support/runs/run_plugin.h"

#include <gtest/gtest.h>

#include <collido/host/plugin_library.h>

#include "support/test_paths.h"

namespace collido::test {

RunReport runPlugin(const Scene& scene, const std::string& plugin, const std::string& variant,
                    const RunOptions& options,
                    const std::map<std::string, std::string>& backend_options) {
  Result<std::shared_ptr<PluginLibrary>> library =
      PluginLibrary::open(pluginDirectory() + "/libcollido_plugin_" + plugin + ".so");
  EXPECT_TRUE(library.ok()) << library.status().toString();
  if (!library.ok()) return {};
  return runScene(scene, BackendSpec{library.value(), variant, backend_options}, options);
}

RunOptions repeated(int repetitions) {
  RunOptions options;
  options.repetitions = repetitions;
  return options;
}

}  // namespace collido::test
