// Stress scenes: a top-level "stress" block that stands for a scene's objects, queries and frame.
#pragma once

#include <string>

#include <collido/scene/scene.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// A top-level "stress" block stands for every object and query: the cases of one robustness
/// category (collido/stress/stress_cases.h) at the listed severities, each case two objects at
/// fixed poses, asked all_pairs and boolean, in one frame. The scene holds exactly what
/// generateStressCases gives, so a study and the stress tests see the same cases.
void readStress(const Reader& r, const Node& root, const std::string& base_directory,
                const SceneLoadOptions& options, Scene& scene);

}  // namespace collido::scene_reading
