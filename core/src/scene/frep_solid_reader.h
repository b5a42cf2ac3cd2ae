// Reads an FRep expression from scene JSON at a given time (animated parameters are evaluated
// there). Errors throw SceneError naming the file and the JSON path.
#pragma once

#include <collido/frep/solid.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// The solid described by `node` at `time` (seconds).
frep::SolidPtr readFrepSolid(const Reader& r, const Node& node, double time);

/// About how many node evaluations one evaluation of the solid at `node` costs (its nodes, with
/// sweeps and projections counted once per piece), for limits on work at load.
double frepEvaluationCost(const Json& node);

/// Whether any parameter under `node` changes with time.
bool frepIsAnimated(const Node& node);

}  // namespace collido::scene_reading
