// Reading and writing the project's own files: whole text and JSON files read with errors that
// name the file, and writes that a crash cannot leave half done. Below the runner, so every
// command, the study and the viewer share one reader and one writer.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include <collido/status.h>

namespace collido::io {

/// The bytes of the file at `path`; when it cannot be opened, an error "<path>: <missing>".
Result<std::string> readTextFile(const std::string& path,
                                 const std::string& missing = "cannot be read");

/// The JSON in the file at `path`, or an error naming the file: "<path>: <missing>" when it cannot
/// be opened, "<path>: not valid JSON: <the parser's message>" when it is not JSON.
Result<nlohmann::json> readJsonFile(const std::string& path,
                                    const std::string& missing = "cannot be read");

/// Writes `text` to a temporary file beside `path` ("<path>.partial.<host>.<pid>.<n>"), flushes
/// it to disk, then renames it over `path`: a reader, a study killed mid-write or a machine that
/// loses power sees the previous file or the new one, never half a file. On failure the
/// temporary is removed and the message names the file and the system's reason.
Status writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace collido::io
