// Parsing scene and surface files: repeated keys refused, errors naming the file.
#include <memory>
#include <set>
#include <vector>

#include <collido/scene/json_document.h>

#include "scene_reader.h"

namespace collido::scene_reading {

// nlohmann::json keeps the last of two equal keys in an object; a scene with "frames" twice must
// not silently mean the second. The parser's callback sees every key; a stack of the open
// containers (the key or index being read in each) gives the JSON pointer of a repeated key.
Json::parser_callback_t duplicateKeyCheck(const std::string& label) {
  struct Open {
    bool array = false;
    std::size_t index = 0;  // arrays: the element being read
    std::string key;        // objects: the key being read
    std::set<std::string> keys;
  };
  auto open = std::make_shared<std::vector<Open>>();
  return [open, label](int /*depth*/, Json::parse_event_t event, Json& parsed) {
    const auto escaped = [](const std::string& key) {  // RFC 6901: '~' -> "~0", '/' -> "~1"
      std::string out;
      for (char c : key)
        out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
      return out;
    };
    switch (event) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start:
        open->push_back(Open{event == Json::parse_event_t::array_start, 0, "", {}});
        break;
      case Json::parse_event_t::key: {
        Open& object = open->back();
        object.key = parsed.get<std::string>();
        if (!object.keys.insert(object.key).second) {
          std::string pointer;
          for (const Open& o : *open) {
            pointer += "/" + (o.array ? std::to_string(o.index) : escaped(o.key));
          }
          throw SceneError(label + ": " + pointer + ": duplicate key '" + object.key +
                           "' (only one of them would count)");
        }
        break;
      }
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        open->pop_back();
        if (!open->empty() && open->back().array) ++open->back().index;
        break;
      case Json::parse_event_t::value:
        if (!open->empty() && open->back().array) ++open->back().index;
        break;
    }
    return true;
  };
}

Result<Json> parseDocument(const std::string& text, const std::string& label) {
  try {
    return Json::parse(text, duplicateKeyCheck(label));
  } catch (const Json::parse_error& e) {
    return Status(StatusCode::kInvalidArgument,
                  label + ": not valid JSON (byte " + std::to_string(e.byte) + "): " + e.what());
  } catch (const SceneError& e) {
    return Status(StatusCode::kInvalidArgument, e.what());
  } catch (const Json::exception& e) {
    // E.g. out_of_range.406: a number literal beyond the double range ("1e400").
    return Status(StatusCode::kInvalidArgument, label + ": not valid JSON: " + e.what());
  }
}

}  // namespace collido::scene_reading

namespace collido {

Result<nlohmann::json> parseJsonDocument(const std::string& text, const std::string& label) {
  return scene_reading::parseDocument(text, label);
}

}  // namespace collido
