#pragma once

#include <string>

#include <collido/runner/runner.h>
#include <collido/status.h>

namespace collido::study {

/// The oracle's answers kept on disk between a study's worker processes, so each scene's exact
/// answers are computed once per study rather than once per backend setting. A file is named
/// by the cache's fingerprint (`<directory>/<fingerprint>.json`) and holds it: answers are only
/// ever reused for the identical scene (meshes, poses, queries).
std::string oracleStorePath(const std::string& directory, const OracleCache& cache);

/// Adds the answers stored at `path` to `cache`. A missing file adds nothing and is not an
/// error; a file that is unreadable, malformed or for another scene is an error naming it (the
/// caller then computes the answers afresh).
Status loadOracleAnswers(const std::string& path, OracleCache& cache);

/// Writes every answer of `cache` to `path` atomically.
Status saveOracleAnswers(const std::string& path, const OracleCache& cache);

}  // namespace collido::study
