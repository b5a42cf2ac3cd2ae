// An object's "pose" and "motion" in a scene file: its poses in every frame, relative to its
// parent when it has one (scenes/README.md, "Motion" and "Hierarchy").
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <collido/scene/scene.h>

#include "constraint_reader.h"
#include "scene_reader.h"

namespace collido::scene_reading {

/// Reads the object's "pose" and "motion" (poses, random, jitter, linear, keyframes, joint)
/// into object.poses, and records the motion's kind in sources[object_index]. `index_of` holds
/// the objects read so far (a random motion is placed against one of them). Errors name the
/// JSON path.
void readMotion(const Reader& r, const Node& node, const Scene& scene,
                const std::map<std::string, std::size_t>& index_of,
                std::vector<ObjectMotionSource>& sources, std::size_t object_index,
                SceneObject& object);

}  // namespace collido::scene_reading
