// The "frames" key of objects and queries: the frames an object exists in or a query is asked
// in, as [first, last] ranges.
#pragma once

#include <cstddef>

#include <collido/scene/scene.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// Reads a non-empty array of [first, last] frame ranges, each within the scene's `frames`,
/// ascending and apart.
FrameRanges readFrameRanges(const Reader& r, const Node& node, std::size_t frames);

/// Refuses a two-object query asked in a frame where one of its objects does not exist
/// (`queries`: the scene's "queries" array, for the message's place).
void checkQueryFrames(const Reader& r, const Node& queries, const Scene& scene);

}  // namespace collido::scene_reading
