// The scene's `constraints` block: read, solved at load by the least-change solver, and applied
// to the objects' motions (scenes/README.md, "Constraints").
#pragma once

#include <string>
#include <vector>

#include <collido/scene/scene.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// How an object's poses were given, which decides whether the solve may move it: a correction
/// applied to every frame keeps fixed, keyframed and linear motions what they were, not random
/// placements drawn against another object, jitter about a base pose or tracked poses.
struct ObjectMotionSource {
  /// "pose", or the motion: "poses", "keyframes", "joint", "linear", "jitter", "random"
  std::string kind = "pose";
  bool has_parent = false;    ///< mounted on another object (its poses follow the parent's)
  bool has_children = false;  ///< other objects are mounted on it
  bool tracked = false;       ///< poses recovered from markers
  bool referenced = false;    ///< another object's random motion is placed relative to it
  bool draped = false;        ///< it drapes onto another object (stops cast at load)
  bool drape_target = false;  ///< another object drapes onto it
};

/// Reads `block` (the scene's /constraints), solves it with the exact oracle's distances for
/// clearances, and moves the objects it changes; fills scene.placement. Errors (bad fields,
/// unknown objects, a constraint that cannot be met) name the file and JSON path. With a
/// `placement_store` folder, a solve stored there for the same block and bodies is reused, and
/// a new one is stored (SceneLoadOptions::placement_store).
void solveSceneConstraints(const Reader& r, const Node& block,
                           const std::vector<ObjectMotionSource>& sources,
                           const std::string& placement_store, Scene& scene);

}  // namespace collido::scene_reading
