#pragma once

#include <string>
#include <vector>

#include <collido/study/result_store.h>

namespace collido::study {

/// "Poses from tracked markers": per (scene, query) whose objects are posed from tracked
/// markers, the frames in contact at the true poses and at the recovered ones, and the false
/// and missed contact frames of the exact answer on the recovered poses (the collision error
/// tracking causes; the same for every backend, taken from the first that ran), the frames
/// with a possible contact within tracking error and the true contacts outside it, then per
/// backend setting its own disagreements with the oracle on the recovered poses. Empty when no
/// scene is tracked.
std::string trackingTable(const std::vector<CombinationResult>& results);

}  // namespace collido::study
