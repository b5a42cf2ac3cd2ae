#pragma once

// What the stress tests share: the meshes with defects the mesh_defects category poses (the
// bundled copies of the shared test meshes), and readable names for parameterised tests.
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <collido/mesh/mesh_io.h>
#include <collido/stress/stress_cases.h>

#include "support/test_paths.h"

namespace collido::stress::test {

/// truck_nonmanifold, teapot_newell and lilium_open_thin from scenes/meshes, loaded once.
inline const StressInputs& defectInputs() {
  static const StressInputs inputs = [] {
    StressInputs loaded;
    for (const char* name : {"truck_nonmanifold", "teapot_newell", "lilium_open_thin"}) {
      Result<TriangleMesh> mesh =
          loadMesh(collido::test::sourcePath(std::string("scenes/meshes/") + name + ".obj"));
      if (!mesh.ok()) {
        ADD_FAILURE() << mesh.status().message();
        continue;
      }
      loaded.defect_meshes.push_back(
          {name, std::make_shared<const TriangleMesh>(std::move(mesh).value())});
    }
    return loaded;
  }();
  return inputs;
}

/// The cases of `category` at its default severities, `per_severity` of each, seed `seed`.
inline std::vector<StressCase> defaultCases(Category category, std::size_t per_severity,
                                            std::uint64_t seed) {
  std::vector<StressCase> all;
  for (const int severity : defaultSeverities(category)) {
    Result<std::vector<StressCase>> cases =
        generateStressCases(category, severity, per_severity, seed, defectInputs());
    if (!cases.ok()) {
      ADD_FAILURE() << cases.status().message();
      continue;
    }
    for (StressCase& c : cases.value())
      all.push_back(std::move(c));
  }
  return all;
}

}  // namespace collido::stress::test

namespace collido::stress {

/// A category in gtest's messages: its name.
inline void PrintTo(Category category, std::ostream* out) {
  *out << categoryName(category);
}

}  // namespace collido::stress

namespace collido::stress::test {

/// Test-name text for a category parameter ("near_touching").
struct CategoryName {
  std::string operator()(const ::testing::TestParamInfo<Category>& info) const {
    return categoryName(info.param);
  }
};

}  // namespace collido::stress::test
