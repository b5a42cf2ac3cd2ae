// collido_bench: Google Benchmark suites over every backend and bundled scene, and the pose
// fits of core/pose (registered statically in pose_benchmarks.cpp).
// Extra flags: --scenes=DIR (default: the source tree's scenes/); --backends=A,B,... in the
// study's syntax, e.g. --backends='obbtree[max_leaf_triangles=4],fcl:obb' (default: every
// statically linked variant with its default options).
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "scene_benchmarks.h"

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::string scenes = COLLIDO_DEFAULT_SCENES_DIR;
  std::vector<std::string> backends;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--scenes=", 9) == 0) {
      scenes = argv[i] + 9;
    } else if (std::strncmp(argv[i], "--backends=", 11) == 0) {
      // Commas separate backends; options inside [...] use ';', so a plain split is enough.
      std::stringstream list(argv[i] + 11);
      std::string item;
      while (std::getline(list, item, ','))
        if (!item.empty()) backends.push_back(item);
    } else {
      std::cerr << "collido_bench: unknown argument " << argv[i] << "\n";
      return 2;
    }
  }
  const collido::Result<int> registered = collido::bench::registerSceneBenchmarks(scenes, backends);
  if (!registered.ok()) {
    std::cerr << "collido_bench: " << registered.status().message() << "\n";
    return 2;
  }
  if (registered.value() == 0) {
    std::cerr << "collido_bench: no scenes in " << scenes << "\n";
    return 2;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
