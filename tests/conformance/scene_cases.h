#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <collido/runner/runner.h>
#include <collido/scene/scene.h>
#include <collido/status.h>

namespace collido::conformance {

/// A scene every plugin is run on. Only its name is read before GoogleTest registers the tests;
/// the scene and its oracle are made the first time a test needs them (loadSceneCase), so that a
/// listing, or a run of the interface tests alone, loads no mesh.
struct SceneCase {
  std::string name;                    ///< the scene's name, used in expectation keys
  std::string test_name;               ///< as a GoogleTest name
  std::string path;                    ///< the scene file; empty for the kit's own generated scenes
  std::string text;                    ///< the kit's own scene's JSON; empty for scene files
  std::shared_ptr<const Scene> scene;  ///< once loaded
  /// The oracle's answers on `scene`, shared by every variant the kit tests (computed once), once
  /// loaded.
  std::shared_ptr<OracleCache> oracle;
  std::optional<Status> loaded;  ///< the outcome of the load, once tried
};

/// The cases, filled by main() before GoogleTest registers the tests.
std::vector<SceneCase>& sceneCases();

/// Lists every *.json in `directory` (the bundled scenes) but those whose file stem is in
/// `skipped`, and the kit's own adversarial scenes: linked tori touching exactly, coplanar
/// overlapping sheets, tori at random poses, a sphere against a gear, and a torus thrown past
/// another over steps (first contact). Reads each file's name
/// only; fails on a file that is not a JSON object, and on a skipped name that is no file of
/// `directory`. A scene that does not load fails its own tests (loadSceneCase). Loading solves
/// placements with `placement_store`, and reads the answers stored in `oracle_answers` for that
/// very scene (study/oracle_store.h: a file per scene fingerprint); each is left out when empty,
/// and the answers when that folder is not there (yet).
Status loadSceneCases(const std::string& directory, const std::set<std::string>& skipped,
                      const std::string& placement_store, const std::string& oracle_answers);

/// Loads `c`'s scene and makes its oracle, with the stored answers; once: later calls give the
/// first outcome. A file of stored answers that does not read is reported on stderr and ignored.
Status loadSceneCase(SceneCase& c);

/// Writes the oracle answers of every case that was loaded to `directory`, replacing what is there.
Status storeOracleAnswers(const std::string& directory);

}  // namespace collido::conformance
