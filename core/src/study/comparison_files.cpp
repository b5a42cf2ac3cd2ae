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

// The rows of one kind's documents: "backends" (surfaces) or "comparators" (FRep).
const char* rowsKey(InputKind kind) {
  return kind == InputKind::kSurfaces ? "backends" : "comparators";
}

// A document with no answer to start from: the format marker, the file and empty rows.
Json emptyDocument(const Combination& c) {
  const char* marker =
      c.kind == InputKind::kSurfaces ? "collidoscope_surface_distance" : "collidoscope_frep";
  return Json{{marker, 1},
              {"file", c.scene_path},
              {"name", c.scene_name},
              {"seed", Json::array()},
              {rowsKey(c.kind), Json::array()}};
}

}  // namespace

std::map<std::string, Json> comparisonDocuments(const std::vector<CombinationResult>& results) {
  // Per document, the seed combination first, then the backends in the order of their text.
  std::map<std::string, std::vector<const CombinationResult*>> by_document;
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
    const InputKind kind = parts.front()->combination.kind;
    const char* rows = rowsKey(kind);
    // The file's figures (model size, precision, surface names) from the first answer there is,
    // the seed's when it has one; every part's rows are added below.
    Json document = emptyDocument(parts.front()->combination);
    for (const CombinationResult* part : parts) {
      if (!part->comparison.is_object()) continue;
      document = part->comparison;
      document[rows] = Json::array();
      if (part->combination.backend != kSeedMethod) document["seed"] = Json::array();
      break;
    }
    Json problems = Json::array();
    for (const CombinationResult* part : parts) {
      const Combination& c = part->combination;
      const bool seed = c.backend == kSeedMethod;
      const Json& answer = part->comparison;
      if (answer.is_object()) {
        if (!document.contains("reference") && answer.contains("reference"))
          document["reference"] = answer["reference"];
        for (const Json& row : answer.value(rows, Json::array()))
          document[rows].push_back(row);
      }
      if (!part->outcome.ok()) {
        const std::string ended = workerEnd(part->outcome);
        if (seed) {
          problems.push_back("seed method: " + ended);
        } else if (!answer.is_object() || answer.value(rows, Json::array()).empty()) {
          Json row = {{"backend", c.backend}, {"status", ended}};
          if (kind == InputKind::kSurfaces) {
            row["segments"] = 0;
          } else {
            row["resolution"] = c.gridText();
          }
          document[rows].push_back(row);
        }
      }
    }
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
