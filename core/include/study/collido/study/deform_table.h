#pragma once

#include <string>
#include <vector>

#include <collido/study/result_store.h>

namespace collido::study {

/// "Deforming scenes": per (combination, query) of the scenes whose objects deform (frames with
/// an update time), the update cost per frame (median, and mean), the query's median, update
/// plus query per frame (mean), and the frames whose answer differed from the oracle's — an
/// answer from stale boxes shows here. Empty when no scene deformed.
std::string deformTable(const std::vector<CombinationResult>& results);

}  // namespace collido::study
