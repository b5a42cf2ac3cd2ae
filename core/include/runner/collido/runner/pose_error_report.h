#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/pose/error_sweep.h>

namespace collido {

/// A pose-error sweep's rows as a text table with its legend, and the first refused fit's
/// reason (what `collido pose-error` prints).
std::string errorSweepText(const std::vector<pose::ErrorSweepRow>& rows);

/// A pose-error sweep's rows as JSON, one object a row; figures a row has none of are null.
nlohmann::json errorSweepRowsJson(const std::vector<pose::ErrorSweepRow>& rows);

}  // namespace collido
