#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include <collido/status.h>

namespace collido {

/// Parses the JSON text of an input file (scene, surface, FRep or sweep file) strictly: a key
/// repeated in one object is an error naming `label` (the file) and the JSON pointer, since
/// nlohmann::json would keep the last one silently; a syntax error names the byte.
Result<nlohmann::json> parseJsonDocument(const std::string& text, const std::string& label);

}  // namespace collido
