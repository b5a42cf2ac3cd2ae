#pragma once

#include <string>

#include <collido/scene/scene.h>
#include <collido/status.h>

namespace collido {

/// The text of the scene file at `path` with its constraints' solution written in: each object
/// the solve moved gets its placed `pose` (or keyframes, or linear ends), and each variable of
/// the block its solved value; everything else is kept. Loading the result solves again with no
/// change. Fails as loadScene does, and for a scene without a `constraints` block.
Result<std::string> placedSceneText(const std::string& path, const SceneLoadOptions& options = {});

}  // namespace collido
