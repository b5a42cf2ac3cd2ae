#pragma once

#include <string>
#include <vector>

#include <collido/study/result_store.h>

namespace collido::study {

/// What a scene's needs save (docs/STUDY.md, "needs"): per backend setting, scene and query that
/// ran with needs "every" and with "declared" or "changed" (the same setting, resolution and
/// limit), the bytes per triangle and build time of each, what declaring saved, the median times,
/// and the frames "changed" answered without asking the backend; empty when no such pair ran.
std::string needsTable(const std::vector<CombinationResult>& results);

}  // namespace collido::study
