#pragma once

#include <vector>

#include <collido/runner/runner.h>
#include <collido/status.h>
#include <collido/study/result_store.h>
#include <collido/study/worker.h>

namespace collido::study {

/// Runs a surface or FRep file's combination in this process: the seed method alone (no
/// `backends`: every bound with and without its descent; for FRep, with a preview picture
/// inline), or its one backend on the combination's grid against the seed's certified answers,
/// computed untimed. The run goes in CombinationResult::surfaces or ::frep; a seed whose answers
/// differ from the file's expected ones, or that certified nothing, adds a problem
/// (failsItsWorker).
Result<CombinationResult> runComparisonCombination(const WorkerRequest& request,
                                                   std::vector<BackendSpec> backends);

}  // namespace collido::study
