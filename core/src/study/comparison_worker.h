#pragma once

#include <collido/status.h>
#include <collido/study/result_store.h>
#include <collido/study/worker.h>

namespace collido::study {

/// Runs a surface or FRep file's combination in this process: the seed method alone (every
/// bound with and without its descent; for FRep, with a preview picture inline), or one backend
/// on the combination's grid against the seed's certified answers, computed untimed. The
/// run goes in CombinationResult::surfaces or ::frep; a seed whose answers differ from the file's
/// expected ones, or that certified nothing, adds a problem.
Result<CombinationResult> runComparisonCombination(const WorkerRequest& request);

}  // namespace collido::study
