#pragma once

#include <memory>
#include <vector>

#include <collido/scene/scene.h>

#include "bench_variant.h"

namespace collido::bench {

/// For a scene whose objects change shape, per variant that updates models and per two-object
/// query, cycling through the frames (each frame: every deforming object's model gets the
/// frame's positions, then the query):
///   deform/<v>/<scene>/<query>         update + query, timed together;
///   deform_update/<v>/<scene>/<query>  the updates alone;
///   deform_query/<v>/<scene>/<query>   the query alone, on the updated models (updates paused);
///   deform_fresh/<v>/<scene>/<query>   the query on models freshly built on each frame's shape
///                                      (what an update's query time is compared with).
/// Returns the number registered (none for a scene that does not deform).
int registerDeformBenchmarks(const std::shared_ptr<const Scene>& scene,
                             const std::vector<Variant>& variants);

}  // namespace collido::bench
