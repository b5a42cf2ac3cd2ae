#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/query.h>
#include <collido/runner/runner.h>
#include <collido/status.h>
#include <collido/study/not_applicable.h>
#include <collido/study/sweep.h>

namespace collido::study {

/// What a combination measures, and so what its worker runs: a mesh scene (runScene), a NURBS
/// surface file (runSurfaces) or an FRep file (runFrep).
enum class InputKind { kScene, kSurfaces, kFrep };

/// "scene", "surfaces" or "frep".
const char* inputKindName(InputKind kind);
std::optional<InputKind> parseInputKind(const std::string& name);

/// The backend text of a surface or FRep file's own seed method (no plugin).
inline constexpr const char* kSeedMethod = "seed";

/// One unit of a study: one scene at one resolution on one backend setting, run by one worker.
struct Combination {
  std::string id;  ///< stable, file-name safe, unique within a plan
  InputKind kind = InputKind::kScene;
  /// Surfaces: the tessellations (segments per side); FRep: the polygonization resolutions.
  std::vector<int> grid = {};
  std::string scene_path;
  std::string scene_name;
  double resolution = 1.0;
  std::string backend;  ///< backend text: "variant" or "variant[key=value;...]"
  NeedsMode needs = NeedsMode::kDeclared;
  std::uint64_t limit = 0;  ///< max_pairs / max_contacts cap; 0 = the scene's own
  /// The scene's robustness category (Scene::category; empty for ordinary scenes), kept with the
  /// combination so the robustness matrix can place even a worker that crashed. Not part of the
  /// id: it follows from the scene file.
  std::string category = {};
  /// What the answers depend on beyond the settings above, part of the id when set (the study
  /// driver sets them; see withInputs): a digest of every file the scene was read from, the
  /// plugin's identity ("obbtree 0.4, engine ..."), and the timed calls per frame. A changed
  /// input then gives another id, so a resumed study never mixes old and new answers.
  std::string scene_digest = {};
  std::string plugin_identity = {};
  int repetitions = 0;
  /// The timing protocol (repeated for studies made before there was a choice).
  TimingProtocol protocol = TimingProtocol::kRepeated;
  /// Which of the study's timing rounds this is: each round of a mesh combination is a worker
  /// process of its own that runs it whole, and the results join their timed calls into round
  /// 0's (rounds.h). Part of the id when not 0; not of the label, which names the combination.
  int round = 0;

  /// "bunny_vs_bunny · obbtree[max_leaf_triangles=4] · every needs · r=0.5 · limit 16", only the
  /// parts that differ from the defaults.
  std::string label() const;
  /// The setting beyond the backend text: "", or e.g. "needs=every r=0.5 limit=16".
  std::string settingText() const;
  /// The grid sizes as their commands take them: "8,32,128" ("" without a grid).
  std::string gridText() const;
};

/// `c` with its inputs set and its id made again from them.
Combination withInputs(Combination c, const std::string& scene_digest,
                       const std::string& plugin_identity, int repetitions,
                       TimingProtocol protocol = TimingProtocol::kRepeated);

/// `c` as timing round `round` (Combination::round), its id made again.
Combination inRound(Combination c, int round);

/// A scene as the planner sees it.
struct PlannedScene {
  std::string path;
  std::string name;
  bool has_generated_shapes = false;  ///< resolutions other than 1 apply only to these
  std::string category = {};          ///< Scene::category: a stress category, or empty
  QueryKindSet queries = {};          ///< the kinds its queries ask; empty: not known
};

/// Whether `backend` can answer something of `scene`: it builds triangle meshes and answers
/// one of the kinds the scene asks. Unknown abilities (a setting missing from `abilities`, a
/// scene whose kinds are not known) apply.
bool applies(const PlannedScene& scene, const std::string& backend,
             const SettingAbilities& abilities);

/// Every combination of scenes × resolutions × backend settings × needs × limits, in that
/// nesting order. Resolutions other than 1 are planned only for scenes with generated shapes; a
/// setting named in `only_scenes` runs only on the scenes listed for it (SweepBackend::scenes);
/// a setting that does not apply to a scene (applies()) is not planned on it.
std::vector<Combination> planStudy(
    const std::vector<PlannedScene>& scenes, const std::vector<std::string>& backends,
    const Sweep& sweep, const std::map<std::string, std::set<std::string>>& only_scenes = {},
    const SettingAbilities& abilities = {});

/// The (setting, scene) pairs planStudy left out because the setting does not apply, once each,
/// scenes in the outer order as planStudy nests them; pairs `only_scenes` rules out are not
/// listed.
std::vector<NotApplicable> notApplicable(
    const std::vector<PlannedScene>& scenes, const std::vector<std::string>& backends,
    const std::map<std::string, std::set<std::string>>& only_scenes,
    const SettingAbilities& abilities);

/// A surface or FRep file's combinations: its seed method (kSeedMethod), then each backend
/// setting, each with the grid sizes the backend's meshes are made at.
std::vector<Combination> planComparisons(const std::vector<PlannedScene>& files, InputKind kind,
                                         const std::vector<std::string>& backends,
                                         const std::vector<int>& grid);

/// Whether a backend setting ("name[key=value;...]") runs its queries on one thread: no
/// `threads` option, or 0 or 1 (a text that does not parse counts as one thread).
bool runsOnOneThread(const std::string& backend);

/// Whether a backend setting answers queries over a step by the runner's discrete sub-steps
/// (its `substeps` option, BackendSpec::substeps) rather than by its own continuous answer.
bool answersBySubsteps(const std::string& backend);

/// The part of a plan that shard `index` of `count` runs (every count-th combination from
/// `index`, so each shard gets a fair mix of cheap and dear ones).
std::vector<Combination> shardOf(const std::vector<Combination>& plan, std::size_t index,
                                 std::size_t count);

/// How a study orders its work (docs/STUDY.md, "Rounds and their order").
struct RunOrder {
  /// Timing rounds of every mesh combination: each a worker process of its own.
  int rounds = 1;
  /// The seed of the order: the same seed and plan give the same order on any machine.
  std::uint64_t seed = 20261129;
};

/// `plan` with each mesh combination followed by its rounds 1 .. rounds - 1 (surface and FRep
/// files run once).
std::vector<Combination> inRounds(const std::vector<Combination>& plan, int rounds);

/// The order to run `count` planned combinations in: 0 .. count - 1 shuffled by `seed`
/// (Fisher-Yates on a 64-bit Mersenne twister), so that no setting's calls all fall in one
/// stretch of the study's time and drift spreads over every setting alike.
std::vector<std::size_t> runOrder(std::size_t count, std::uint64_t seed);

/// Reads "I/N" (0 <= I < N), as a Slurm array passes $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT.
Result<std::pair<std::size_t, std::size_t>> parseShard(const std::string& text);

nlohmann::json combinationToJson(const Combination& combination);
Result<Combination> combinationFromJson(const nlohmann::json& json);

}  // namespace collido::study
