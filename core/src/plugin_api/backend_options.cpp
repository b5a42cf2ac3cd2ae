#include <collido/backend_options.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace collido {
namespace {

Status badValue(const std::string& key, const std::string& value, const std::string& expected) {
  return {StatusCode::kInvalidArgument,
          "option " + key + " = '" + value + "': expected " + expected};
}

}  // namespace

Result<std::int64_t> BackendOptions::getInt(const std::string& key, std::int64_t fallback,
                                            std::int64_t min_value, std::int64_t max_value) {
  consumed_.insert(key);
  const auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const std::string& text = it->second;
  const std::string range =
      "an integer in [" + std::to_string(min_value) + ", " + std::to_string(max_value) + "]";
  errno = 0;
  char* end = nullptr;
  const long long parsed = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || parsed < min_value || parsed > max_value) {
    return badValue(key, text, range);
  }
  return static_cast<std::int64_t>(parsed);
}

Result<double> BackendOptions::getDouble(const std::string& key, double fallback, double min_value,
                                         double max_value) {
  consumed_.insert(key);
  const auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const std::string& text = it->second;
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(parsed) || parsed < min_value ||
      parsed > max_value) {
    return badValue(
        key, text,
        "a number in [" + std::to_string(min_value) + ", " + std::to_string(max_value) + "]");
  }
  return parsed;
}

Result<bool> BackendOptions::getBool(const std::string& key, bool fallback) {
  consumed_.insert(key);
  const auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  if (it->second == "true" || it->second == "1") return true;
  if (it->second == "false" || it->second == "0") return false;
  return badValue(key, it->second, "true or false");
}

Status BackendOptions::rejectUnknown(const std::string& backend_name) const {
  std::string unknown;
  for (const auto& [key, value] : values_) {
    if (consumed_.count(key) != 0) continue;
    if (!unknown.empty()) unknown += ", ";
    unknown += key;
  }
  if (unknown.empty()) return {};
  // The keys some getter asked for are exactly the options this backend understands.
  std::string known;
  for (const std::string& key : consumed_)
    known += (known.empty() ? "" : ", ") + key;
  return {StatusCode::kInvalidArgument,
          backend_name + ": unknown option(s): " + unknown +
              (known.empty() ? " (it takes no options)" : " (known: " + known + ")")};
}

}  // namespace collido
