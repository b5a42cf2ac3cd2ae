// The study's first stage: every input read and checked, so bad input stops the study before
// anything runs.
#include <algorithm>
#include <filesystem>
#include <optional>

#include <collido/mesh/input_file.h>
#include <collido/runner/digest.h>
#include <collido/scene/frep_file.h>
#include <collido/scene/scene.h>
#include <collido/scene/surface_file.h>

#include <collido/host/install_layout.h>

#include "mesh_workload.h"
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

// The scene files, and in place of mesh files the scenes written of them.
Result<std::vector<std::string>> sceneFiles(const StudyRequest& request, std::ostream& err) {
  std::vector<std::string> scenes;
  std::vector<std::string> meshes;
  for (const std::string& path : request.scenes)
    (isMeshInput(path) ? meshes : scenes).push_back(path);
  if (meshes.empty()) return scenes;
  Result<std::vector<MeshWorkloadScene>> written =
      writeMeshWorkload(meshes, request.out + "/scenes");
  if (!written.ok()) return written.status();
  for (const MeshWorkloadScene& scene : written.value()) {
    err << "scene of the meshes: " << scene.path
        << (scene.kept ? " (edited: kept as it is; delete it for the meshes' own)"
                       : " (edit it and study it again)")
        << "\n";
    scenes.push_back(scene.path);
  }
  return scenes;
}

// The bundled default sweep: an install's, else the source tree's this build came from.
std::string defaultSweepPath() {
  const std::string installed = installedDataDirectory();
  return (installed.empty() ? std::string(COLLIDO_SCENES_SOURCE_DIR) : installed + "/scenes") +
         "/sweeps/default.json";
}

Status loadScenes(const StudyRequest& request, const std::vector<std::string>& paths,
                  StudyInputs& inputs) {
  // Scenes placed by constraints are solved here once; the workers read the stored solve.
  SceneLoadOptions load;
  load.placement_store =
      (request.oracle_directory.empty() ? request.out + "/oracle" : request.oracle_directory) +
      "/placements";
  for (const std::string& path : paths) {
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

Result<StudyInputs> loadInputs(const StudyRequest& request, std::ostream& err) {
  StudyInputs inputs;
  const bool meshes = std::any_of(request.scenes.begin(), request.scenes.end(), isMeshInput);
  const std::string sweep_path =
      request.sweep_path.empty() && meshes ? defaultSweepPath() : request.sweep_path;
  if (!sweep_path.empty()) {
    Result<Sweep> sweep = loadSweep(sweep_path);
    if (!sweep.ok()) return sweep.status();
    inputs.sweep = std::move(sweep).value();
  }
  if (request.scenes.empty() && request.surface_files.empty() && request.frep_files.empty()) {
    return Status(StatusCode::kInvalidArgument, "no scene, surface or FRep file to study");
  }
  const Result<std::vector<std::string>> scenes = sceneFiles(request, err);
  if (!scenes.ok()) return scenes.status();
  if (Status s = loadScenes(request, scenes.value(), inputs); !s.ok()) return s;
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
