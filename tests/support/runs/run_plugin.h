#pragma once

// One scene run on one plugin of this build, for the tests that check the runner end to end.
#include <map>
#include <string>

#include <collido/runner/runner.h>
#include <collido/scene/scene.h>

namespace collido::test {

/// `scene` on `variant` (with `backend_options`) of the build's plugin
/// libcollido_plugin_<plugin>.so, under `options`. A plugin that does not open fails the test and
/// gives an empty report.
RunReport runPlugin(const Scene& scene, const std::string& plugin, const std::string& variant,
                    const RunOptions& options,
                    const std::map<std::string, std::string>& backend_options = {});

/// RunOptions with `repetitions` timed calls per frame, everything else as default.
RunOptions repeated(int repetitions);

}  // namespace collido::test
