#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>

#include <collido/status.h>

namespace collido {

/// Key/value settings given to a backend at creation ("max_leaf_triangles" = "4").
/// Getters parse and range-check; keys no getter asked for are rejected by rejectUnknown(), so a
/// misspelt setting is an error instead of a silently ignored default.
class BackendOptions {
 public:
  void set(const std::string& key, const std::string& value) { values_[key] = value; }
  bool has(const std::string& key) const { return values_.count(key) != 0; }
  const std::map<std::string, std::string>& values() const { return values_; }

  /// The integer under `key`, or `fallback` when absent; an error when unparseable or outside
  /// [min_value, max_value].
  Result<std::int64_t> getInt(const std::string& key, std::int64_t fallback, std::int64_t min_value,
                              std::int64_t max_value);
  /// The finite number under `key`, or `fallback`; an error outside [min_value, max_value].
  Result<double> getDouble(const std::string& key, double fallback, double min_value,
                           double max_value);
  /// "true"/"false"/"1"/"0" under `key`, or `fallback`.
  Result<bool> getBool(const std::string& key, bool fallback);
  /// An error naming every key that no getter asked for, or ok.
  Status rejectUnknown(const std::string& backend_name) const;

 private:
  std::map<std::string, std::string> values_;
  std::set<std::string> consumed_;
};

}  // namespace collido
