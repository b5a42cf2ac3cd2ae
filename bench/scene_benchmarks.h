#pragma once

#include <string>
#include <vector>

#include <collido/status.h>

namespace collido::bench {

/// Registers, for every backend and every scene file in `scenes_directory`:
/// build/<backend>/<scene>/<object> and query/<backend>/<scene>/<query> (for a deforming scene,
/// the deform benchmarks of deform_benchmarks.h instead of query/). The backends are
/// `backends` in the study's syntax ("obbtree[max_leaf_triangles=4]"), or when empty every
/// statically linked variant with its default options. Returns the number registered, or why a
/// backend cannot be run.
Result<int> registerSceneBenchmarks(const std::string& scenes_directory,
                                    const std::vector<std::string>& backends);

}  // namespace collido::bench
