#include <algorithm>
#include <set>
#include <sstream>

#include <collido/runner/runner.h>

namespace collido {

std::string BackendSpec::label() const {
  if (options.empty()) return variant;
  std::string text = variant + "[";
  bool first = true;
  for (const auto& [key, value] : options) {
    if (!first) text += ";";
    text += key;
    text += "=";
    text += value;
    first = false;
  }
  return text + "]";
}

Result<std::pair<std::string, std::map<std::string, std::string>>> parseBackendText(
    const std::string& text) {
  const auto bad = [&](const std::string& why) {
    return Status(StatusCode::kInvalidArgument,
                  "backend '" + text + "': " + why + " (expected NAME or NAME[key=value;...])");
  };
  const std::size_t open = text.find('[');
  std::pair<std::string, std::map<std::string, std::string>> out;
  out.first = text.substr(0, open);
  if (out.first.empty()) return bad("no name");
  if (open == std::string::npos) return out;
  if (text.back() != ']') return bad("missing ']'");
  std::stringstream list(text.substr(open + 1, text.size() - open - 2));
  std::string item;
  while (std::getline(list, item, ';')) {
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0)
      return bad("option '" + item + "' is not key=value");
    if (!out.second.emplace(item.substr(0, equals), item.substr(equals + 1)).second) {
      return bad("option '" + item.substr(0, equals) + "' given twice");
    }
  }
  return out;
}

Status unknownBackend(const std::string& variant, const std::vector<std::string>& known) {
  std::string list;
  for (const std::string& name : known)
    list += (list.empty() ? "" : ", ") + name;
  return Status(
      StatusCode::kInvalidArgument,
      "no plugin offers backend '" + variant + "' (found: " + (list.empty() ? "none" : list) + ")");
}

Result<std::vector<BackendSpec>> resolveBackends(
    const std::vector<std::string>& texts,
    const std::vector<std::shared_ptr<PluginLibrary>>& plugins) {
  std::vector<BackendSpec> specs;
  for (const std::string& text : texts) {
    auto parsed = parseBackendText(text);
    if (!parsed.ok()) return parsed.status();
    const std::string& variant = parsed.value().first;
    const std::map<std::string, std::string>& options = parsed.value().second;
    const auto found = std::find_if(plugins.begin(), plugins.end(), [&](const auto& plugin) {
      return plugin->hasVariant(variant);
    });
    if (found == plugins.end()) {
      std::vector<std::string> known;
      for (const auto& plugin : plugins) {
        for (const VariantInfo& v : plugin->variants())
          known.push_back(v.name);
      }
      return unknownBackend(variant, known);
    }
    specs.push_back(BackendSpec{*found, variant, options});
  }
  return specs;
}

}  // namespace collido
