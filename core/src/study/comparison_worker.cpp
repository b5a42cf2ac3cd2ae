#include "comparison_worker.h"

#include <collido/io/html_page.h>
#include <collido/runner/frep_run.h>
#include <collido/runner/surface_run.h>

namespace collido::study {
namespace {

// The dashboard's preview picture of an FRep file.
constexpr int kPreviewWidth = 480;
constexpr int kPreviewHeight = 360;

Status runSurfaceCombination(const WorkerRequest& request, std::vector<BackendSpec> backends,
                             CombinationResult& result) {
  const Combination& c = request.combination;
  SurfaceRunRequest run;
  run.file = c.scene_path;
  run.repetitions = request.repetitions;
  run.seed_rows = backends.empty();
  run.backends = std::move(backends);
  run.tessellations = c.grid;
  Result<SurfaceRun> done = runSurfaces(run);
  if (!done.ok()) return done.status();
  if (!done.value().reference) result.problems.push_back("no bound converged");
  result.surfaces = std::move(done).value();
  return Status();
}

Status runFrepCombination(const WorkerRequest& request, std::vector<BackendSpec> backends,
                          CombinationResult& result) {
  const Combination& c = request.combination;
  const Result<FrepFile> file = loadFrepFile(c.scene_path);
  if (!file.ok()) return file.status();
  FrepRunRequest run;
  run.repetitions = request.repetitions;
  run.seed_rows = backends.empty();
  run.backends = std::move(backends);
  run.resolutions = c.grid;
  Result<FrepRun> done = runFrep(file.value(), c.scene_path, run);
  if (!done.ok()) return done.status();
  result.frep = std::move(done).value();
  if (result.frep->unexpected > 0) {
    result.problems.push_back(std::to_string(result.frep->unexpected) +
                              " answers differ from the file's expected ones");
  }
  if (!run.seed_rows) return Status();
  const Result<std::string> png =
      frepPreviewPng(file.value(), *result.frep, std::nullopt, kPreviewWidth, kPreviewHeight);
  if (!png.ok()) return png.status();
  result.frep->preview_png = "data:image/png;base64," + io::base64(png.value());
  return Status();
}

}  // namespace

Result<CombinationResult> runComparisonCombination(const WorkerRequest& request,
                                                   std::vector<BackendSpec> backends) {
  CombinationResult result;
  result.combination = request.combination;
  const Status run = request.combination.kind == InputKind::kSurfaces
                         ? runSurfaceCombination(request, std::move(backends), result)
                         : runFrepCombination(request, std::move(backends), result);
  if (!run.ok()) return run;
  return result;
}

}  // namespace collido::study
