#pragma once

#include <memory>
#include <set>
#include <string>
#include <vector>

#include <collido/runner/runner.h>
#include <collido/scene/scene.h>
#include <collido/status.h>

namespace collido::conformance {

/// A scene every plugin is run on.
struct SceneCase {
  std::string name;       ///< the scene's name, used in expectation keys
  std::string test_name;  ///< as a GoogleTest name
  std::string path;       ///< the scene file; empty for the kit's own generated scenes
  std::shared_ptr<const Scene> scene;
  /// The oracle's answers on `scene`, shared by every variant the kit tests (computed once).
  std::shared_ptr<OracleCache> oracle;
};

/// The cases, filled by main() before GoogleTest registers the tests.
std::vector<SceneCase>& sceneCases();

/// Loads every *.json in `directory` (the bundled scenes) but those whose file stem is in
/// `skipped`, and the kit's own adversarial scenes: linked tori touching exactly, coplanar
/// overlapping sheets, tori at random poses, and a sphere against a gear. Fails on the first
/// scene that does not load, and on a skipped name that is no file of `directory`.
Status loadSceneCases(const std::string& directory, const std::set<std::string>& skipped,
                      const std::string& placement_store);

/// Adds to every case's oracle the answers stored in `directory` for that very scene
/// (study/oracle_store.h: a file per scene fingerprint); a case without a file computes its own.
/// A file that does not read is reported on stderr and ignored.
void readStoredOracleAnswers(const std::string& directory);

/// Writes every case's oracle answers to `directory`, replacing what is there.
Status storeOracleAnswers(const std::string& directory);

}  // namespace collido::conformance
