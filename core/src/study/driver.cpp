// The study driver: the stages of a study (stages.h) in order. collido study and collido merge
// only parse their arguments and call it.
#include <collido/study/driver.h>

#include <filesystem>

#include <collido/study/outputs.h>

#include "stages.h"

namespace collido::study {

Status publishResults(const StudyPlan& plan, const StudyFolder& folder, StudyEnd end,
                      std::ostream& out, std::ostream& err) {
  Result<std::vector<CombinationResult>> all = folder.store.readAll();
  if (!all.ok()) return all.status();
  if (Status s = writeStudyOutputs(folder.store.directory(), all.value()); !s.ok()) return s;
  if (end == StudyEnd::kInterrupted) {
    err << "\nstudy interrupted: " << all.value().size() << " of " << plan.combinations.size()
        << " combinations are stored; continue with the same command and --resume\n";
    return {};
  }
  out << studyTable(all.value(), plan.not_applicable, plan.field);
  const bool robustness =
      std::filesystem::exists(std::filesystem::path(folder.store.directory()) / "robustness.txt");
  err << "results: " << folder.store.directory() << "/{table.txt,records.jsonl,summary.json"
      << (robustness ? ",robustness.txt" : "") << "}\n";
  return {};
}

int runStudy(const StudyRequest& request, std::ostream& out, std::ostream& err) {
  const auto stopped = [&err](const Status& status) {
    err << "error: " << status.message() << "\n";
    return 2;
  };
  const Result<StudyInputs> inputs = loadInputs(request, err);
  if (!inputs.ok()) return stopped(inputs.status());
  const Result<StudyBackends> backends = probeBackends(request, inputs.value(), err);
  if (!backends.ok()) return stopped(backends.status());
  const StudyPlan plan = planCombinations(request, inputs.value(), backends.value(), err);
  const Result<StudyFolder> folder = reconcileFolder(request, plan);
  if (!folder.ok()) return stopped(folder.status());
  const Result<StudyEnd> end = executePlan(request, plan, backends.value(), folder.value(), err);
  if (!end.ok()) return stopped(end.status());
  if (Status s = publishResults(plan, folder.value(), end.value(), out, err); !s.ok())
    return stopped(s);
  return end.value() == StudyEnd::kInterrupted ? 130 : 0;
}

}  // namespace collido::study
