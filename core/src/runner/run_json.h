#pragma once
// What the surface and FRep run documents (surface_run_json.cpp, frep_run_json.cpp) read and
// write alike.
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include <collido/runner/measurement_status.h>

namespace collido::detail {

/// A number of a run's document: JSON writes a non-finite double as null, which reads back as
/// NaN, so a stored run with an infinite or missing figure stays readable.
inline double numberAt(const nlohmann::json& object, const char* key) {
  const nlohmann::json& value = object.at(key);
  return value.is_null() ? std::numeric_limits<double>::quiet_NaN() : value.get<double>();
}

/// A backend row's "status": "ok" (MeasurementStatus's text) where it answered, else why not.
inline std::string rowStatus(const std::string& failure) {
  return failure.empty() ? MeasurementStatus().text() : failure;
}

/// Why a backend row failed, read from its "status"; empty where it answered.
inline std::string rowFailure(const nlohmann::json& row) {
  const MeasurementStatus status = MeasurementStatus::fromText(row.at("status").get<std::string>());
  return status.ok() ? std::string() : status.reason();
}

}  // namespace collido::detail
