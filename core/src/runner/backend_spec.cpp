#include <algorithm>
#include <charconv>
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

namespace {

// The number of sub-steps "substeps=N" asks for, or why it is not one.
Result<int> parseSubsteps(const std::string& text) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || value < 1 || value > 4096) {
    return Status(StatusCode::kInvalidArgument, std::string(kSubstepsOption) + "=" + text +
                                                    ": sub-steps must be a whole number "
                                                    "from 1 to 4096");
  }
  return value;
}

}  // namespace

int BackendSpec::substeps() const {
  const auto found = options.find(kSubstepsOption);
  if (found == options.end()) return 0;
  const Result<int> value = parseSubsteps(found->second);
  return value.ok() ? value.value() : 0;
}

std::map<std::string, std::string> BackendSpec::pluginOptions() const {
  std::map<std::string, std::string> plugin = options;
  plugin.erase(kSubstepsOption);
  return plugin;
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
    if (const auto substeps = options.find(kSubstepsOption); substeps != options.end()) {
      if (Result<int> n = parseSubsteps(substeps->second); !n.ok()) {
        return Status(StatusCode::kInvalidArgument,
                      "backend '" + text + "': " + n.status().message());
      }
    }
    specs.push_back(BackendSpec{*found, variant, options});
  }
  return specs;
}

}  // namespace collido
