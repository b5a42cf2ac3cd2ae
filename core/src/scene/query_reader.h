// The queries of a scene file: which objects are asked against which, and how.
#pragma once

#include <cstddef>
#include <map>
#include <string>

#include <collido/scene/scene.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// Reads the scene's "queries" (`queries`, the array) into scene.queries, against the objects
/// already read (`index_of`: name to index). Each query asks two objects or sides ("a", "b"),
/// or a group ("among"); names default from the sides and the kind and must be unique.
void readQueries(const Reader& r, const Node& queries,
                 const std::map<std::string, std::size_t>& index_of, Scene& scene);

}  // namespace collido::scene_reading
