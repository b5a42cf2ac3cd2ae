// What the HTML pages (the study's dashboard, the 3D view) are made with: parts read and
// inlined safely into a template, and pictures as base64.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <collido/status.h>

namespace collido::io {

/// Standard base64 (RFC 4648, padded) of `bytes`: pictures inlined as data URIs.
std::string base64(const std::string& bytes);

/// A script made safe to inline in a <script> element ("</script" cannot close it early).
std::string scriptSafe(const std::string& text);

/// JSON made safe to inline in a <script> element (no "</" nor "<!--" survives).
std::string dataSafe(const std::string& json);

/// Text for an HTML element: '&' and '<' escaped.
std::string htmlText(std::string text);

/// A file a page inlines at `marker`; scripts are made safe to inline (scriptSafe).
struct PagePart {
  std::string marker;
  std::filesystem::path file;
  bool script = true;
};

/// Reads every part into `values`, by marker. A missing file from the npm registry (under
/// `web`/node_modules) is named with how to install the front-end into `web`.
Status readPageParts(const std::filesystem::path& web, const std::vector<PagePart>& parts,
                     std::map<std::string, std::string>& values);

/// Fills "@NAME@" markers of a page template in one pass over the template only (inserted text
/// is never taken for a marker); every value must have its marker.
Result<std::string> fillTemplate(const std::string& page,
                                 const std::map<std::string, std::string>& values);

}  // namespace collido::io
