// Generated shapes in scene files ({"generator": "torus", ...}): one table maps each generator's
// keys onto its parameter struct in collido/mesh/procedural.h, whose generator validates them.
#pragma once

#include <functional>
#include <string>

#include <collido/mesh/triangle_mesh.h>
#include <collido/status.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// A generator's shape as the scene asks for it, read but not yet made.
struct PlannedShape {
  std::string description;  ///< "torus R=1 r=0.25 48x24": the mesh report's source
  double triangles = 0.0;   ///< what `make` will build, for the scene's triangle limit
  std::function<Result<TriangleMesh>()> make;  ///< fails with the generator's own message
};

/// Reads the shape at `node` ("generator" and that generator's parameters, each optional, sample
/// counts scaled by the load's resolution). Fails naming an unknown generator or key, or a value
/// of the wrong type; the generator itself judges the values when `make` runs.
PlannedShape readGenerator(const Reader& r, const Node& node);

}  // namespace collido::scene_reading
