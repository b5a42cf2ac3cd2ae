#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/status.h>
#include <collido/study/result_store.h>

namespace collido::study {

/// The data the dashboard draws: one row per (combination, query) with its figures, every
/// timed call, the failures (crashes, timeouts, wrong answers, unsupported queries), the
/// robustness matrix of the stress scenes (study/robustness.h), the baseline's rows when
/// comparing two result sets, and the settings the plan left out as not applicable.
nlohmann::json reportData(const std::vector<CombinationResult>& results,
                          const std::vector<CombinationResult>& baseline, const std::string& title,
                          const std::vector<NotApplicable>& not_applicable = {});

/// Where the dashboard's front-end lives: `explicit_directory` if given, else $COLLIDO_WEB_DIR,
/// else an install's share/collido/web, else the source tree's web/ folder this build came from.
std::string webDirectory(const std::string& explicit_directory);

/// One self-contained HTML page (opens offline): the template, style, Vega, Vega-Lite,
/// vega-embed and the report script from `web_directory`, and `data`, all inline. Errors name
/// the missing file and how to get it.
Result<std::string> renderReport(const nlohmann::json& data, const std::string& web_directory);

}  // namespace collido::study
