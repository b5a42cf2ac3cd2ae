#include <collido/study/sweep.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include <collido/mesh/input_file.h>
#include <collido/runner/runner.h>
#include <collido/scene/json_document.h>

namespace collido::study {
namespace {

// Ordered: options keep the order the file gives them (SweepBackend::settings() follows it).
using OrderedJson = nlohmann::ordered_json;

struct SweepError {
  std::string message;
};

class Checker {
 public:
  explicit Checker(std::string label) : label_(std::move(label)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw SweepError{label_ + ": " + (where.empty() ? "/" : where) + ": " + problem};
  }

  void allowKeys(const OrderedJson& node, const std::string& where,
                 const std::set<std::string>& allowed) const {
    if (!node.is_object()) fail(where, std::string("expected an object, got ") + node.type_name());
    for (const auto& item : node.items()) {
      if (item.key() == "comment" || allowed.count(item.key()) != 0) continue;
      std::string list;
      for (const std::string& key : allowed)
        list += (list.empty() ? "" : ", ") + key;
      fail(where, "unknown key '" + item.key() + "' (allowed: " + list + ")");
    }
  }

  const OrderedJson& nonEmptyArray(const OrderedJson& node, const std::string& where) const {
    if (!node.is_array()) fail(where, std::string("expected an array, got ") + node.type_name());
    if (node.empty()) fail(where, "expected at least one entry");
    return node;
  }

 private:
  std::string label_;
};

std::string at(const std::string& where, const std::string& key) {
  return where + "/" + key;
}
std::string at(const std::string& where, std::size_t index) {
  return where + "/" + std::to_string(index);
}

// Option values are passed to plugins as text; numbers keep the shortest form people wrote.
std::string optionText(const Checker& c, const OrderedJson& value, const std::string& where) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  // nlohmann writes the shortest text that reads back as the same number: 0.1, not
  // 0.10000000000000001.
  if (value.is_number()) return value.dump();
  c.fail(where, std::string("expected a number, string or boolean, got ") + value.type_name());
}

SweepBackend readBackend(const Checker& c, const OrderedJson& node, const std::string& where) {
  if (node.is_string()) return SweepBackend{node.get<std::string>(), {}, {}};
  c.allowKeys(node, where, {"variant", "options", "scenes", "optional"});
  if (!node.contains("variant") || !node.at("variant").is_string()) {
    c.fail(where, "missing 'variant' (a backend name such as \"fcl:obb\")");
  }
  SweepBackend backend{node.at("variant").get<std::string>(), {}, {}};
  if (backend.variant.empty()) c.fail(at(where, "variant"), "must not be empty");
  if (node.contains("options")) {
    const std::string options_at = at(where, "options");
    const OrderedJson& options = node.at("options");
    if (!options.is_object()) c.fail(options_at, "expected an object of option: [values]");
    for (const auto& item : options.items()) {
      const std::string option_at = at(options_at, item.key());
      std::vector<std::string> values;
      if (item.value().is_array()) {
        c.nonEmptyArray(item.value(), option_at);
        for (std::size_t i = 0; i < item.value().size(); ++i)
          values.push_back(optionText(c, item.value()[i], at(option_at, i)));
      } else {
        values.push_back(optionText(c, item.value(), option_at));
      }
      backend.options.emplace_back(item.key(), values);
    }
  }
  if (node.contains("optional")) {
    if (!node.at("optional").is_boolean()) c.fail(at(where, "optional"), "expected true or false");
    backend.optional = node.at("optional").get<bool>();
  }
  if (node.contains("scenes")) {
    const std::string scenes_at = at(where, "scenes");
    const OrderedJson& scenes = c.nonEmptyArray(node.at("scenes"), scenes_at);
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      if (!scenes[i].is_string() || scenes[i].get<std::string>().empty())
        c.fail(at(scenes_at, i), "expected a scene name");
      backend.scenes.push_back(scenes[i].get<std::string>());
    }
  }
  return backend;
}

std::vector<double> readResolutions(const Checker& c, const OrderedJson& node,
                                    const std::string& where) {
  const OrderedJson& list = c.nonEmptyArray(node, where);
  std::vector<double> resolutions;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i].is_number() || !(list[i].get<double>() > 0.0) ||
        !std::isfinite(list[i].get<double>())) {
      c.fail(at(where, i), "expected a positive number (1 = as the scene says)");
    }
    resolutions.push_back(list[i].get<double>());
  }
  return resolutions;
}

std::vector<NeedsMode> readNeedsModes(const Checker& c, const OrderedJson& node,
                                      const std::string& where) {
  const OrderedJson& list = c.nonEmptyArray(node, where);
  std::vector<NeedsMode> modes;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::optional<NeedsMode> mode =
        list[i].is_string() ? parseNeedsMode(list[i].get<std::string>()) : std::nullopt;
    if (!mode) c.fail(at(where, i), "expected \"declared\", \"changed\" or \"every\"");
    modes.push_back(*mode);
  }
  return modes;
}

// {"backends": ["obbtree", ...], "<grid_key>": [8, 32]}: a SweepComparison; `grid_key` names the
// grid sizes ("tessellations", "resolutions"), each a whole number from `low` to 1024.
void readComparison(const Checker& c, const OrderedJson& node, const std::string& where,
                    const char* grid_key, int low, SweepComparison& comparison) {
  c.allowKeys(node, where, {"backends", grid_key});
  if (node.contains("backends")) {
    const std::string backends_at = at(where, "backends");
    const OrderedJson& list = c.nonEmptyArray(node.at("backends"), backends_at);
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (!list[i].is_string() || list[i].get<std::string>().empty())
        c.fail(at(backends_at, i), "expected a backend setting such as \"obbtree\"");
      comparison.backends.push_back(list[i].get<std::string>());
    }
  }
  if (node.contains(grid_key)) {
    const std::string grid_at = at(where, grid_key);
    const OrderedJson& list = c.nonEmptyArray(node.at(grid_key), grid_at);
    comparison.grid.clear();
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (!list[i].is_number_integer() || list[i].get<long long>() < low ||
          list[i].get<long long>() > 1024) {
        c.fail(at(grid_at, i), "expected a whole number from " + std::to_string(low) + " to 1024");
      }
      comparison.grid.push_back(list[i].get<int>());
    }
  }
}

// A list for every scene, or {"scene name": [..], "*": [..]}: per scene, "*" for the others.
template <typename T, typename Read>
void readPerScene(const OrderedJson& node, const std::string& where, Read read, const Checker& c,
                  std::vector<T>& every_scene, std::map<std::string, std::vector<T>>& per_scene) {
  if (!node.is_object()) {
    every_scene = read(c, node, where);
    return;
  }
  for (const auto& item : node.items()) {
    std::vector<T> list = read(c, item.value(), where + "/" + item.key());
    if (item.key() == "*") {
      every_scene = std::move(list);
    } else {
      per_scene[item.key()] = std::move(list);
    }
  }
}

Sweep readSweep(const Checker& c, const OrderedJson& root) {
  c.allowKeys(root, "",
              {"backends", "resolutions", "needs", "limits", "repetitions", "rounds", "adaptive_s",
               "timeout_s", "protocol", "surfaces", "frep", "field"});
  Sweep sweep;
  if (root.contains("surfaces"))
    readComparison(c, root.at("surfaces"), "/surfaces", "tessellations", 1, sweep.surfaces);
  if (root.contains("frep"))
    readComparison(c, root.at("frep"), "/frep", "resolutions", 2, sweep.frep);
  if (root.contains("backends")) {
    const OrderedJson& list = c.nonEmptyArray(root.at("backends"), "/backends");
    for (std::size_t i = 0; i < list.size(); ++i)
      sweep.backends.push_back(readBackend(c, list[i], at("/backends", i)));
  }
  if (root.contains("resolutions")) {
    readPerScene(root.at("resolutions"), "/resolutions", readResolutions, c, sweep.resolutions,
                 sweep.scene_resolutions);
  }
  if (root.contains("needs"))
    readPerScene(root.at("needs"), "/needs", readNeedsModes, c, sweep.needs, sweep.scene_needs);
  if (root.contains("limits")) {
    sweep.limits.clear();
    const OrderedJson& list = c.nonEmptyArray(root.at("limits"), "/limits");
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (!list[i].is_number_unsigned() && !(list[i].is_number_integer() && list[i] >= 0)) {
        c.fail(at("/limits", i), "expected a whole number >= 0 (0 = the scene's own limit)");
      }
      sweep.limits.push_back(list[i].get<std::uint64_t>());
    }
  }
  if (root.contains("repetitions")) {
    const OrderedJson& value = root.at("repetitions");
    if (!value.is_number_integer() || value.get<long long>() < 1 ||
        value.get<long long>() > 1000000) {
      c.fail("/repetitions", "expected a whole number from 1 to 1000000");
    }
    sweep.repetitions = value.get<int>();
  }
  if (root.contains("rounds")) {
    const OrderedJson& value = root.at("rounds");
    if (!value.is_number_integer() || value.get<long long>() < 1 || value.get<long long>() > 100)
      c.fail("/rounds", "expected a whole number from 1 to 100");
    sweep.rounds = value.get<int>();
  }
  if (root.contains("adaptive_s")) {
    const OrderedJson& value = root.at("adaptive_s");
    if (!value.is_number() || !(value.get<double>() >= 0.0))
      c.fail("/adaptive_s", "expected a number of seconds >= 0");
    sweep.adaptive_s = value.get<double>();
  }
  if (root.contains("protocol")) {
    const OrderedJson& value = root.at("protocol");
    if (!value.is_string() || !parseTimingProtocol(value.get<std::string>())) {
      c.fail("/protocol", R"(expected "repeated" or "cycled")");
    }
    sweep.protocol = value.get<std::string>();
  }
  if (root.contains("field")) {
    const OrderedJson& field = root.at("field");
    c.allowKeys(field, "/field", {"ours", "peer"});
    for (auto [key, side] :
         {std::make_pair("ours", &sweep.field.ours), std::make_pair("peer", &sweep.field.peer)}) {
      if (!field.contains(key)) continue;
      const OrderedJson& value = field.at(key);
      if (!value.is_string() || value.get<std::string>().empty())
        c.fail(std::string("/field/") + key, "expected a backend name");
      *side = value.get<std::string>();
    }
  }
  if (root.contains("timeout_s")) {
    const OrderedJson& value = root.at("timeout_s");
    if (!value.is_number() || !(value.get<double>() > 0.0)) {
      c.fail("/timeout_s", "expected a positive number of seconds");
    }
    sweep.timeout_s = value.get<double>();
  }
  return sweep;
}

}  // namespace

const char* needsModeName(NeedsMode mode) {
  switch (mode) {
    case NeedsMode::kDeclared:
      return "declared";
    case NeedsMode::kChanged:
      return "changed";
    case NeedsMode::kEvery:
      return "every";
  }
  return "declared";
}

std::optional<NeedsMode> parseNeedsMode(const std::string& name) {
  if (name == "declared") return NeedsMode::kDeclared;
  if (name == "changed") return NeedsMode::kChanged;
  if (name == "every") return NeedsMode::kEvery;
  return std::nullopt;
}

const std::vector<NeedsMode>& Sweep::needsOf(const std::string& scene) const {
  const auto found = scene_needs.find(scene);
  return found == scene_needs.end() ? needs : found->second;
}

const std::vector<double>& Sweep::resolutionsOf(const std::string& scene) const {
  const auto found = scene_resolutions.find(scene);
  return found == scene_resolutions.end() ? resolutions : found->second;
}

std::vector<std::string> SweepBackend::settings() const {
  std::vector<std::string> texts{""};
  for (const auto& [name, values] : options) {
    std::vector<std::string> next;
    for (const std::string& prefix : texts) {
      for (const std::string& value : values) {
        std::string setting = prefix;
        if (!setting.empty()) setting += ';';
        setting.append(name).append("=").append(value);
        next.push_back(std::move(setting));
      }
    }
    texts = std::move(next);
  }
  for (std::string& text : texts) {
    std::string full = variant;
    if (!text.empty()) full.append("[").append(text).append("]");
    text = std::move(full);
  }
  return texts;
}

Result<Sweep> parseSweep(const std::string& text, const std::string& label) {
  // Checked strictly first (a repeated key is an error, as in scene files); read again in key
  // order, which names the settings (obbtree[max_leaf_triangles=1;float_boxes=false]).
  if (Result<nlohmann::json> strict = parseJsonDocument(text, label); !strict.ok())
    return strict.status();
  try {
    const OrderedJson root = OrderedJson::parse(text);
    return readSweep(Checker(label), root);
  } catch (const OrderedJson::parse_error& e) {
    return Status(StatusCode::kInvalidArgument,
                  label + ": not valid JSON (byte " + std::to_string(e.byte) + "): " + e.what());
  } catch (const SweepError& e) {
    return Status(StatusCode::kInvalidArgument, e.message);
  }
}

Result<Sweep> loadSweep(const std::string& path) {
  Result<std::string> text = readInputFile(path, "sweep file");
  if (!text.ok()) return text.status();
  return parseSweep(text.value(), path);
}

}  // namespace collido::study
