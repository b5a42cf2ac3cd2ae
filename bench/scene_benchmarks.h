#pragma once

#include <string>

namespace collido::bench {

/// Registers, for every statically linked backend variant and every scene file in
/// `scenes_directory`: build/<backend>/<scene>/<object> and query/<backend>/<scene>/<query>.
/// Returns the number of benchmarks registered.
int registerSceneBenchmarks(const std::string& scenes_directory);

}  // namespace collido::bench
