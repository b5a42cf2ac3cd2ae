#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/status.h>
#include <collido/study/result_store.h>

namespace collido::study {

/// A study's NURBS surface and FRep comparisons, one document per file in the format its command
/// writes with --json (collido surface-distance, collido frep), joined from that file's
/// combinations: the seed method's rows from the seed combination, each backend's rows from its
/// own worker, and for a worker that crashed, timed out or failed without an answer one row
/// naming the backend and how the worker ended. Keyed by "surfaces/<stem>" and "frep/<stem>".
std::map<std::string, nlohmann::json> comparisonDocuments(
    const std::vector<CombinationResult>& results);

/// Writes comparisonDocuments as <directory>/surfaces/<stem>.json and <directory>/frep/<stem>.json
/// (what collido report shows in its surface and FRep sections).
Status writeComparisonFiles(const std::string& directory,
                            const std::vector<CombinationResult>& results);

}  // namespace collido::study
