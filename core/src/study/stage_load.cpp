// The study's first stage: every input read and checked, so bad input stops the study before
// anything runs.
#include <filesystem>
#include <optional>

#include <collido/mesh/input_file.h>
#include <collido/runner/digest.h>
#include <collido/scene/frep_file.h>
#include <collido/scene/scene.h>
#include <collido/scene/surface_file.h>

#include "stages.h"

namespace collido::study {
namespace {

// A digest of the content of `files`, in order (a scene's: every file it was read from).
Result<std::string> filesDigest(const std::vector<std::string>& files, const char* what) {
  Digest digest;
  for (const std::string& file : files) {
    Result<std::string> bytes = readInputFile(file, what);
    if (!bytes.ok()) return bytes.status();
    digest.text(bytes.value());
  }
  return digest.hex();
}

std::string plannedPath(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

Status loadScenes(const StudyRequest& request, StudyInputs& inputs) {
  // Scenes placed by constraints are solved here once; the workers read the stored solve.
  SceneLoadOptions load;
  load.placement_store =
      (request.oracle_directory.empty() ? request.out + "/oracle" : request.oracle_directory) +
      "/placements";
  for (const std::string& path : request.scenes) {
    Result<Scene> scene = loadScene(path, load);
    if (!scene.ok()) return scene.status();
    QueryKindSet asked;
    for (const SceneQuery& query : scene.value().queries)
      asked |= query.request.kind;
    inputs.scenes.push_back({plannedPath(path), scene.value().name,
                             scene.value().hasGeneratedShapes(), scene.value().category, asked});
    Result<std::string> digest = filesDigest(scene.value().input_files, "input file");
    if (!digest.ok()) return digest.status();
    inputs.digests[inputs.scenes.back().path] = digest.value();
  }
  return {};
}

// NURBS surface and FRep files.
Status loadComparisonFiles(const StudyRequest& request, StudyInputs& inputs) {
  for (const auto& [paths, kind] : {std::make_pair(&request.surface_files, InputKind::kSurfaces),
                                    std::make_pair(&request.frep_files, InputKind::kFrep)}) {
    const bool surfaces = kind == InputKind::kSurfaces;
    for (const std::string& path : *paths) {
      if (surfaces) {
        if (Result<std::vector<NamedSurface>> file = loadSurfaces(path); !file.ok())
          return file.status();
      } else if (Result<FrepFile> file = loadFrepFile(path); !file.ok()) {
        return file.status();
      }
      Result<std::string> digest = filesDigest({path}, surfaces ? "surface file" : "FRep file");
      if (!digest.ok()) return digest.status();
      const std::string planned = plannedPath(path);
      (surfaces ? inputs.surface_files : inputs.frep_files)
          .push_back({planned, std::filesystem::path(path).stem().string()});
      inputs.digests[planned] = digest.value();
    }
  }
  return {};
}

}  // namespace

Result<StudyInputs> loadInputs(const StudyRequest& request) {
  StudyInputs inputs;
  if (!request.sweep_path.empty()) {
    Result<Sweep> sweep = loadSweep(request.sweep_path);
    if (!sweep.ok()) return sweep.status();
    inputs.sweep = std::move(sweep).value();
  }
  if (request.scenes.empty() && request.surface_files.empty() && request.frep_files.empty()) {
    return Status(StatusCode::kInvalidArgument, "no scene, surface or FRep file to study");
  }
  if (Status s = loadScenes(request, inputs); !s.ok()) return s;
  if (Status s = loadComparisonFiles(request, inputs); !s.ok()) return s;
  if (!request.shard.empty()) {
    Result<std::pair<std::size_t, std::size_t>> shard = parseShard(request.shard);
    if (!shard.ok()) return shard.status();
    std::tie(inputs.shard_index, inputs.shard_count) = shard.value();
  }
  // Cycled by default: each timed call on another frame than the last, as an independent
  // harness and a simulation step meet them (docs/STUDY.md, "Timing protocols").
  if (!request.protocol.empty()) {
    const std::optional<TimingProtocol> protocol = parseTimingProtocol(request.protocol);
    if (!protocol) {
      return Status(StatusCode::kInvalidArgument,
                    "--protocol: '" + request.protocol + "' is not repeated or cycled");
    }
    inputs.protocol = *protocol;
  } else if (inputs.sweep.protocol) {
    inputs.protocol = *parseTimingProtocol(*inputs.sweep.protocol);  // checked by loadSweep
  }
  return inputs;
}

}  // namespace collido::study
