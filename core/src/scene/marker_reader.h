// The scene key "markers" of an object: its marker layout, where the observations come from
// (a tracks file, or generated from the object's motion), and the fit.
#pragma once

#include <string>

#include <collido/scene/scene.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// Reads `markers` (the object's "markers" node) once the object's shape and motion are read:
/// keeps the motion as the true poses and replaces object.poses with the poses recovered from
/// the markers, frame by frame. Errors name the JSON path (or the tracks file and line).
void readMarkers(const Reader& r, const Node& markers, const std::string& base_directory,
                 std::size_t frames, SceneObject& object);

}  // namespace collido::scene_reading
