// collido_bench: Google Benchmark suites over every backend and bundled scene.
// Extra flag: --scenes=DIR (default: the source tree's scenes/).
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "scene_benchmarks.h"

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::string scenes = COLLIDO_DEFAULT_SCENES_DIR;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--scenes=", 9) == 0) {
      scenes = argv[i] + 9;
    } else {
      std::cerr << "collido_bench: unknown argument " << argv[i] << "\n";
      return 2;
    }
  }
  if (collido::bench::registerSceneBenchmarks(scenes) == 0) {
    std::cerr << "collido_bench: no scenes in " << scenes << "\n";
    return 2;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
