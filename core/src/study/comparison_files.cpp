#include <collido/study/comparison_files.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

#include <collido/io/files.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;

// How a worker that left no answer ended, with the last line of its log: what the row shows.
std::string workerEnd(const WorkerOutcome& outcome) {
  std::string text = outcome.text();
  std::string tail = outcome.log_tail;
  while (!tail.empty() && (tail.back() == '\n' || tail.back() == ' '))
    tail.pop_back();
  if (const std::size_t line = tail.rfind('\n'); line != std::string::npos)
    tail = tail.substr(line + 1);
  if (!tail.empty()) text += ": " + tail;
  return text;
}

using Parts = std::vector<const CombinationResult*>;

// A surface file's run joined from its parts: the seed's figures and rows, the first reference a
// backend's part has, every backend's rows, and for a worker without rows one row saying how it
// ended. `problems` gets the seed's failure.
SurfaceRun joinSurfaces(const Parts& parts, std::vector<std::string>& problems) {
  const Combination& first = parts.front()->combination;
  SurfaceRun run;
  run.file = first.scene_path;
  for (const CombinationResult* part : parts) {
    if (!part->surfaces) continue;
    run = *part->surfaces;
    run.backends.clear();
    run.reference.reset();
    if (part->combination.backend != kSeedMethod) run.seed.clear();
    break;
  }
  for (const CombinationResult* part : parts) {
    const bool seed = part->combination.backend == kSeedMethod;
    if (part->surfaces) {
      if (!run.reference && !seed) run.reference = part->surfaces->reference;
      run.backends.insert(run.backends.end(), part->surfaces->backends.begin(),
                          part->surfaces->backends.end());
    }
    if (part->outcome.ok()) continue;
    if (seed) {
      problems.push_back("seed method: " + workerEnd(part->outcome));
    } else if (!part->surfaces || part->surfaces->backends.empty()) {
      SurfaceBackendRow row;
      row.backend = part->combination.backend;
      row.end = SurfaceRowEnd::kNotCreated;
      row.failure = workerEnd(part->outcome);
      run.backends.push_back(std::move(row));
    }
  }
  run.backends_asked = !run.backends.empty();
  return run;
}

// An FRep file's run joined likewise; a worker without rows gets one row per resolution of its
// grid.
FrepRun joinFrep(const Parts& parts, std::vector<std::string>& problems) {
  const Combination& first = parts.front()->combination;
  FrepRun run;
  run.file = first.scene_path;
  run.name = first.scene_name;
  for (const CombinationResult* part : parts) {
    if (!part->frep) continue;
    run = *part->frep;
    run.comparators.clear();
    if (part->combination.backend != kSeedMethod) {
      run.seed.clear();
      run.preview_png.clear();
    }
    break;
  }
  for (const CombinationResult* part : parts) {
    if (part->frep) {
      run.comparators.insert(run.comparators.end(), part->frep->comparators.begin(),
                             part->frep->comparators.end());
    }
    if (part->outcome.ok()) continue;
    if (part->combination.backend == kSeedMethod) {
      problems.push_back("seed method: " + workerEnd(part->outcome));
    } else if (!part->frep || part->frep->comparators.empty()) {
      for (const int resolution : part->combination.grid) {
        FrepBackendRow row;
        row.backend = part->combination.backend;
        row.resolution = resolution;
        row.created = false;
        row.failure = workerEnd(part->outcome);
        run.comparators.push_back(std::move(row));
      }
    }
  }
  return run;
}

}  // namespace

std::map<std::string, Json> comparisonDocuments(const std::vector<CombinationResult>& results) {
  // Per document, the seed combination first, then the backends in the order of their text.
  std::map<std::string, Parts> by_document;
  for (const CombinationResult& r : results) {
    const Combination& c = r.combination;
    if (c.kind == InputKind::kScene) continue;
    const std::string stem = std::filesystem::path(c.scene_path).stem().string();
    by_document[std::string(inputKindName(c.kind)) + "/" + stem].push_back(&r);
  }
  std::map<std::string, Json> documents;
  for (auto& [key, parts] : by_document) {
    std::sort(parts.begin(), parts.end(),
              [](const CombinationResult* x, const CombinationResult* y) {
                const bool x_seed = x->combination.backend == kSeedMethod;
                const bool y_seed = y->combination.backend == kSeedMethod;
                if (x_seed != y_seed) return x_seed;
                return x->combination.backend < y->combination.backend;
              });
    std::vector<std::string> problems;
    Json document = parts.front()->combination.kind == InputKind::kSurfaces
                        ? surfaceRunJson(joinSurfaces(parts, problems))
                        : frepRunJson(joinFrep(parts, problems));
    if (!problems.empty()) document["problems"] = problems;
    documents[key] = std::move(document);
  }
  return documents;
}

Status writeComparisonFiles(const std::string& directory,
                            const std::vector<CombinationResult>& results) {
  for (const auto& [key, document] : comparisonDocuments(results)) {
    const std::filesystem::path path = std::filesystem::path(directory) / (key + ".json");
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec) {
      return Status(StatusCode::kInvalidArgument,
                    path.parent_path().string() + ": cannot create the folder: " + ec.message());
    }
    if (Status s = io::writeFileAtomically(path.string(), document.dump(1) + "\n"); !s.ok())
      return s;
  }
  return Status();
}

}  // namespace collido::study
