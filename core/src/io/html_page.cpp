#include <collido/io/html_page.h>

#include <collido/io/files.h>

#include <algorithm>
#include <cctype>
#include <set>

namespace collido::io {

// A script inlined in the page must not close its <script> element early: only "</script"
// (any case) does, and "<\/script" means the same inside the strings and regular expressions
// where it can occur in code.
std::string scriptSafe(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/' && i + 8 <= text.size()) {
      std::string word = text.substr(i + 2, 6);
      for (char& c : word)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (word == "script") {
        out += "<\\/";
        ++i;
        continue;
      }
    }
    out += text[i];
  }
  return out;
}

// JSON inlined as data: "<\/" is an escape JSON allows, so no "</" (nor "<!--") survives.
std::string dataSafe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    if (json[i] == '<' && i + 1 < json.size() && (json[i + 1] == '/' || json[i + 1] == '!')) {
      out += "\\u003c";
      continue;
    }
    out += json[i];
  }
  return out;
}

// Fills "@NAME@" markers in one left-to-right pass over the template only, so text inside the
// inserted libraries is never taken for a marker.
Result<std::string> fillTemplate(const std::string& page,
                                 const std::map<std::string, std::string>& values) {
  std::string out;
  std::size_t at = 0;
  std::set<std::string> used;
  while (at < page.size()) {
    const std::size_t open = page.find('@', at);
    const std::size_t close = open == std::string::npos ? open : page.find('@', open + 1);
    if (close == std::string::npos) break;
    const std::string marker = page.substr(open, close - open + 1);
    const auto found = values.find(marker);
    if (found == values.end()) {
      out += page.substr(at, close - at);
      at = close;
      continue;
    }
    out += page.substr(at, open - at) + found->second;
    used.insert(marker);
    at = close + 1;
  }
  out += page.substr(std::min(at, page.size()));
  for (const auto& [marker, value] : values) {
    if (used.count(marker) == 0) {
      return Status(StatusCode::kInvalidArgument, "the page template has no " + marker);
    }
  }
  return out;
}

std::string htmlText(std::string text) {
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"&", "&amp;"}, {"<", "&lt;"}}) {
    for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size())
      text.replace(at, from.size(), to);
  }
  return text;
}

Status readPageParts(const std::filesystem::path& web, const std::vector<PagePart>& parts,
                     std::map<std::string, std::string>& values) {
  const std::string npm_hint = "install the front-end with `npm ci --prefix " + web.string() +
                               "` (tools/study.sh does), or point --web / COLLIDO_WEB_DIR at it";
  for (const PagePart& part : parts) {
    const bool from_npm = part.file.string().find("node_modules") != std::string::npos;
    Result<std::string> text =
        readTextFile(part.file.string(), from_npm ? "not found: " + npm_hint : "not found");
    if (!text.ok()) return text.status();
    values[part.marker] = part.script ? scriptSafe(text.value()) : std::move(text).value();
  }
  return Status();
}

}  // namespace collido::io
