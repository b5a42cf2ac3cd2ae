#pragma once

#include <limits>

#include <nlohmann/json.hpp>

namespace collido::detail {

/// A number of a run's document: JSON writes a non-finite double as null, which reads back as
/// NaN, so a stored run with an infinite or missing figure stays readable.
inline double numberAt(const nlohmann::json& object, const char* key) {
  const nlohmann::json& value = object.at(key);
  return value.is_null() ? std::numeric_limits<double>::quiet_NaN() : value.get<double>();
}

}  // namespace collido::detail
