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

/// A cache's link to its store for one run: the answers stored for its scene are added when it
/// is made, and what the run computed beyond them is written back by keepNew(). A store that
/// cannot be read or written costs time, never an answer: it is noted on stderr and the answers
/// are computed afresh. An empty directory: no store, nothing read or written.
class StoredOracle {
 public:
  StoredOracle(const std::string& directory, OracleCache& cache);
  /// Writes the cache to the store when it computed anything since it was read.
  void keepNew() const;

 private:
  OracleCache& cache_;
  std::string path_;
  std::size_t known_ = 0;
};

}  // namespace collido::study
