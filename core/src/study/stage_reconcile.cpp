// The study's fourth stage: this run's plan against what the study folder already holds, so a
// resumed study runs only what is missing and never mixes results of different inputs.
#include <set>

#include <collido/io/files.h>

#include "stages.h"

namespace collido::study {
namespace {

// Why the same combinations (by label) now have other ids: which scenes' files, plugins or
// repetitions changed; "" when the combinations themselves differ.
std::string changedInputs(const std::vector<Combination>& before,
                          const std::vector<Combination>& now) {
  std::map<std::string, const Combination*> earlier;
  for (const Combination& c : before)
    earlier[c.label()] = &c;
  if (earlier.size() != now.size()) return "";
  std::set<std::string> scenes;
  std::set<std::string> plugins;
  std::set<std::string> repetitions;
  std::set<std::string> protocols;
  for (const Combination& c : now) {
    const auto found = earlier.find(c.label());
    if (found == earlier.end()) return "";
    const Combination& old = *found->second;
    if (old.scene_digest != c.scene_digest) scenes.insert(c.scene_name);
    if (old.plugin_identity != c.plugin_identity) {
      plugins.insert("'" + (old.plugin_identity.empty() ? "?" : old.plugin_identity) + "' -> '" +
                     c.plugin_identity + "'");
    }
    if (old.protocol != c.protocol) {
      protocols.insert(std::string(timingProtocolName(old.protocol)) + " -> " +
                       timingProtocolName(c.protocol));
    }
    if (old.repetitions != c.repetitions) {
      repetitions.insert(std::to_string(old.repetitions) + " -> " + std::to_string(c.repetitions));
    }
  }
  std::string text;
  const auto add = [&text](const std::string& what, const std::set<std::string>& items) {
    if (items.empty()) return;
    text += (text.empty() ? "" : "; ") + what;
    bool first = true;
    for (const std::string& item : items) {
      text += (first ? " " : ", ") + item;
      first = false;
    }
  };
  add("the files (scene file or meshes) of", scenes);
  add("plugin", plugins);
  add("repetitions", repetitions);
  add("timing protocol", protocols);
  return text;
}

// Refuses a stored plan other than `plan`, saying why.
Status checkStoredPlan(const StudyRequest& request, const std::vector<Combination>& stored,
                       const std::vector<Combination>& plan) {
  if (stored.empty()) return {};
  if (!request.resume) {
    return Status(
        StatusCode::kInvalidArgument,
        request.out + " already holds a study; pass --resume to continue it, or another --out");
  }
  std::set<std::string> before;
  for (const Combination& c : stored)
    before.insert(c.id);
  std::set<std::string> now;
  for (const Combination& c : plan)
    now.insert(c.id);
  if (before == now) return {};
  const std::string changed = changedInputs(stored, plan);
  if (!changed.empty()) {
    return Status(StatusCode::kInvalidArgument,
                  request.out + ": the inputs changed since this study started (" + changed +
                      "); its stored results would mix with new ones. Start it afresh in "
                      "another --out, or remove the folder");
  }
  return Status(StatusCode::kInvalidArgument,
                request.out +
                    " holds a different study (other scenes, backends, sweep or shard); resume "
                    "with the same arguments, or choose another --out");
}

// Stored and readable with an ok outcome: a failed or unreadable result runs again.
bool storedOk(const ResultStore& store, const Combination& c) {
  const Result<nlohmann::json> json = io::readJsonFile(store.resultPath(c.id));
  if (!json.ok()) return false;
  const Result<CombinationResult> stored = resultFromJson(json.value(), store.resultPath(c.id));
  return stored.ok() && stored.value().outcome.ok();
}

}  // namespace

Result<StudyFolder> reconcileFolder(const StudyRequest& request, const StudyPlan& plan) {
  // One driver per folder: a second one on the same --out would delete the first one's scratch
  // files and store results under its plan. Held until the study ends.
  Result<FolderLock> lock = FolderLock::acquire(request.out);
  if (!lock.ok()) return lock.status();
  StudyFolder folder{std::move(lock).value(), ResultStore(request.out), {}};
  Result<std::vector<Combination>> stored_plan = folder.store.readPlan();
  if (!stored_plan.ok()) return stored_plan.status();
  if (Status s = checkStoredPlan(request, stored_plan.value(), plan.combinations); !s.ok())
    return s;
  if (Status s = folder.store.prepare(); !s.ok()) return s;
  if (Status s =
          folder.store.writePlan(plan.combinations, plan.not_applicable, plan.order, plan.field);
      !s.ok()) {
    return s;
  }
  for (const std::size_t index : runOrder(plan.combinations.size(), plan.order.seed)) {
    const Combination& c = plan.combinations[index];
    if (request.resume && folder.store.has(c.id) &&
        (!request.retry_failed || storedOk(folder.store, c))) {
      continue;
    }
    folder.todo.push_back(&c);
  }
  return folder;
}

}  // namespace collido::study
