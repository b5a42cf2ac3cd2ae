#pragma once

#include <nlohmann/json.hpp>

#include <collido/runner/runner.h>
#include <collido/status.h>

namespace collido {

/// A measurement as JSON, per-frame records and every timed call included; the form study
/// results are stored in, and read back from, to merge and report.
nlohmann::json measurementToJson(const QueryMeasurement& measurement);

/// Reads what measurementToJson wrote; errors name the missing or mistyped field.
Result<QueryMeasurement> measurementFromJson(const nlohmann::json& json);

}  // namespace collido
