// Reading the deformable parts of a scene object: movable nodes ("deform") and the schedule of
// active states ("schedule"); format in scenes/README.md.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <functional>

#include <collido/scene/deformation.h>
#include <collido/scene/scene.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// What a rule may need from the rest of the scene.
struct DeformContext {
  const SceneObject* object = nullptr;  ///< the object deformed, shapes and poses read
  /// The object of that name defined before this one, or null.
  std::function<const SceneObject*(const std::string&)> earlier;
};

/// The object's "deform" block: selection, recording (a file relative to `base_directory`) and
/// rules, for a scene of `frames` frames.
std::shared_ptr<const Deformation> readDeformation(const Reader& r, const Node& node,
                                                   const std::string& base_directory,
                                                   std::size_t frames,
                                                   const DeformContext& context);

/// The state active in each frame: a list of `frames` state indices, or {"hold": n} (each
/// state active for n frames in turn, cycling); without a node, the states share the frames
/// evenly in order.
std::vector<std::size_t> readSchedule(const Reader& r, const Node* node, std::size_t states,
                                      std::size_t frames);

}  // namespace collido::scene_reading
