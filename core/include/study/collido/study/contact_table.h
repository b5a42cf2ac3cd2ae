#pragma once

#include <string>
#include <vector>

#include <collido/study/result_store.h>

namespace collido::study {

/// The contacts queries of a study against the exact reference (docs/DESIGN.md, "Contact
/// geometry"): per backend setting, scene and query, the time and each contact error figure;
/// empty when no contacts query was measured.
std::string contactTable(const std::vector<CombinationResult>& results);

}  // namespace collido::study
