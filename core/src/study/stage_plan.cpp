// The study's third stage: the combinations to run, from the inputs, the settings and the
// sweep. Nothing runs here.
#include <set>

#include "stages.h"

namespace collido::study {
namespace {

// Per setting from a sweep entry with "scenes", the scenes it runs on; a setting that an
// unrestricted entry also gives runs everywhere. Names matching no scene of the study are
// warned about (a typo would otherwise drop the setting silently).
std::map<std::string, std::set<std::string>> onlyScenes(const Sweep& sweep,
                                                        const std::vector<PlannedScene>& scenes,
                                                        std::ostream& err) {
  std::map<std::string, std::set<std::string>> only;
  std::set<std::string> everywhere;
  std::set<std::string> names;
  for (const PlannedScene& scene : scenes)
    names.insert(scene.name);
  for (const SweepBackend& backend : sweep.backends) {
    for (const std::string& setting : backend.settings()) {
      if (backend.scenes.empty()) {
        everywhere.insert(setting);
      } else {
        only[setting].insert(backend.scenes.begin(), backend.scenes.end());
      }
    }
    for (const std::string& scene : backend.scenes) {
      if (names.count(scene) == 0) {
        err << "warning: sweep: " << backend.variant << " names scene '" << scene
            << "', which is not among the scenes studied\n";
      }
    }
  }
  for (const std::string& setting : everywhere)
    only.erase(setting);
  return only;
}

// "obbtree 0.4, engine OBB tree 0.4": what a change of plugin or engine version shows in.
std::string pluginIdentity(const PluginProbe& found, const std::string& backend) {
  Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
      parseBackendText(backend);
  const ProbedPlugin* plugin = parsed.ok() ? found.offering(parsed.value().first) : nullptr;
  if (plugin == nullptr) return "";
  return plugin->name + " " + plugin->version + ", engine " + plugin->engine_name + " " +
         plugin->engine_version;
}

}  // namespace

StudyPlan planCombinations(const StudyRequest& request, const StudyInputs& inputs,
                           const StudyBackends& backends, std::ostream& err) {
  const Sweep& sweep = inputs.sweep;
  StudyPlan plan;
  plan.field = sweep.field;
  plan.repetitions = request.repetitions > 0 ? request.repetitions : sweep.repetitions.value_or(5);
  plan.timeout_s = request.timeout_s > 0 ? request.timeout_s : sweep.timeout_s.value_or(600.0);
  plan.adaptive_s = request.adaptive_s >= 0.0 ? request.adaptive_s : sweep.adaptive_s.value_or(0.0);
  plan.order =
      RunOrder{request.rounds > 0 ? request.rounds : sweep.rounds.value_or(1), request.order_seed};
  const std::map<std::string, std::set<std::string>> only_scenes =
      onlyScenes(sweep, inputs.scenes, err);
  std::vector<Combination> whole =
      planStudy(inputs.scenes, backends.settings, sweep, only_scenes, backends.abilities);
  plan.not_applicable =
      notApplicable(inputs.scenes, backends.settings, only_scenes, backends.abilities);
  for (Combination& c : whole) {
    const std::string& digest = inputs.digests.at(c.scene_path);
    const std::string identity = pluginIdentity(backends.found, c.backend);
    c = withInputs(std::move(c), digest, identity, plan.repetitions, inputs.protocol);
  }
  // Surfaces and FRep files: a single input per frame, timed by the repeated protocol whatever
  // the study's (docs/STUDY.md, "Timing protocols").
  for (std::vector<Combination> comparisons :
       {planComparisons(inputs.surface_files, InputKind::kSurfaces, backends.surface_settings,
                        sweep.surfaces.grid),
        planComparisons(inputs.frep_files, InputKind::kFrep, backends.frep_settings,
                        sweep.frep.grid)}) {
    for (Combination& c : comparisons) {
      const std::string identity =
          c.backend == kSeedMethod ? std::string() : pluginIdentity(backends.found, c.backend);
      const std::string& digest = inputs.digests.at(c.scene_path);
      whole.push_back(
          withInputs(std::move(c), digest, identity, plan.repetitions, TimingProtocol::kRepeated));
    }
  }
  if (inputs.shard_count > 1) plan.shard = request.shard;
  // A shard runs every round of its combinations, so that it can join them.
  plan.combinations =
      inRounds(shardOf(whole, inputs.shard_index, inputs.shard_count), plan.order.rounds);
  return plan;
}

}  // namespace collido::study
