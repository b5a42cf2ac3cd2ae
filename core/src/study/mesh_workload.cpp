#include "mesh_workload.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <set>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/io/scene_pose.h>
#include <collido/mesh/mesh_io.h>
#include <collido/oracle/exact_oracle.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

constexpr int kFrames = 24;
// The approach crosses first contact: its centre distance, as a share of the two bounding radii,
// goes from this much beyond the contact's to this much within it.
constexpr double kApproachSpan = 0.08;
// Where the bounding spheres are apart, and the approach of parts that never touch on the way in
// (one nested in the other).
constexpr double kApart = 1.1;
constexpr double kNestedTo = 0.3;

struct Part {
  std::string name;
  std::string path;  // relative to the scenes' folder
  std::shared_ptr<const TriangleMesh> mesh;
  BoundingSphere sphere;  // what the scene's random motion places objects by
};

Json queriesOf(const std::vector<Part>& parts) {
  Json queries = Json::array();
  for (std::size_t i = 1; i < parts.size(); ++i) {
    for (const char* kind : {"boolean", "all_pairs", "distance"}) {
      queries.push_back({{"a", parts[0].name}, {"b", parts[i].name}, {"kind", kind}});
    }
  }
  return queries;
}

// Every part after the first comes in along its own axis (+x, -x, +y, ...), without turning,
// through first contact: the exact oracle finds where it is by bisection, so that half the
// frames ask at small clearances and half at shallow overlaps.
Json approachMotion(const Part& fixed, const Part& moving, std::size_t index) {
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  direction((index - 1) / 2 % 3) = (index - 1) % 2 == 0 ? 1.0 : -1.0;
  const double reach = fixed.sphere.radius + moving.sphere.radius;
  const auto translation = [&](double share) {
    return Eigen::Vector3d(fixed.sphere.centre + share * reach * direction - moving.sphere.centre);
  };
  const auto touching = [&](double share) {
    Pose pose = Pose::Identity();
    pose.translation() = translation(share);
    return exactIntersectingPairs(*fixed.mesh, Pose::Identity(), *moving.mesh, pose,
                                  OracleMode::kFirstPair)
        .intersecting;
  };
  double from = kApart;
  double to = kNestedTo;
  if (touching(0.0)) {
    double inside = 0.0;
    double apart = kApart;
    for (int step = 0; step < 40; ++step) {
      const double middle = 0.5 * (inside + apart);
      (touching(middle) ? inside : apart) = middle;
    }
    from = apart + kApproachSpan;
    to = std::max(0.0, inside - kApproachSpan);
  }
  return {{"linear",
           {{"from", io::scenePoseJson(Pose(Eigen::Translation3d(translation(from))))},
            {"to", io::scenePoseJson(Pose(Eigen::Translation3d(translation(to))))}}}};
}

Json sceneOf(const std::vector<Part>& parts, const std::string& name, bool approach) {
  Json objects = Json::array();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Json object = {{"name", parts[i].name}, {"shape", {{"mesh", parts[i].path}}}};
    if (i > 0) {
      object["motion"] = approach ? approachMotion(parts[0], parts[i], i)
                                  : Json{{"random",
                                          {{"seed", 2024 + static_cast<int>(i)},
                                           {"relative_to", parts[0].name},
                                           {"overlap", {0.3, 0.9}}}}};
    }
    objects.push_back(std::move(object));
  }
  const std::string what =
      approach ? "every other mesh approaching the first along an axis without turning, through "
                 "first contact (frames from 8 percent of the bounding radii apart to 8 percent "
                 "in)"
               : "every other mesh at seeded random rotations and positions whose bounding "
                 "spheres overlap the first's by 30 to 90 percent";
  return {{"name", name},
          {"description", "Written by collido study from mesh files: " + what + "."},
          {"frames", kFrames},
          {"objects", std::move(objects)},
          {"queries", queriesOf(parts)}};
}

}  // namespace

bool isMeshInput(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension != ".json";
}

Result<std::vector<MeshWorkloadScene>> writeMeshWorkload(const std::vector<std::string>& meshes,
                                                         const std::string& folder) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) {
    return Status(StatusCode::kInvalidArgument,
                  folder + ": cannot create the folder (" + error.message() + ")");
  }
  std::vector<std::string> files = meshes;
  if (files.size() == 1) files.push_back(files[0]);  // a mesh against a copy of itself
  std::vector<Part> parts;
  std::set<std::string> names;
  for (const std::string& file : files) {
    Result<TriangleMesh> mesh = loadMesh(file);
    if (!mesh.ok()) return mesh.status();
    const auto shared = std::make_shared<const TriangleMesh>(std::move(mesh).value());
    Part part;
    const std::string stem = fs::path(file).stem().string();
    part.name = stem;
    for (int copy = 2; names.count(part.name) != 0; ++copy)
      part.name = stem + "_" + std::to_string(copy);
    names.insert(part.name);
    part.path = fs::relative(fs::absolute(file), fs::absolute(folder)).generic_string();
    part.mesh = shared;
    part.sphere = boundingSphere(*shared);
    parts.push_back(std::move(part));
  }
  std::string name = parts[0].name + "_vs_" + parts[1].name;
  if (parts.size() > 2) name += "_and_" + std::to_string(parts.size() - 2) + "_more";
  std::vector<MeshWorkloadScene> written;
  for (const bool approach : {false, true}) {
    const std::string scene = name + (approach ? "_approach" : "_overlap");
    MeshWorkloadScene file{(fs::path(folder) / (scene + ".json")).string()};
    const std::string text = sceneOf(parts, scene, approach).dump(1) + "\n";
    // A file of other content is the user's edit of an earlier run's: theirs to keep.
    if (fs::exists(file.path)) {
      Result<std::string> existing = io::readTextFile(file.path);
      file.kept = existing.ok() && existing.value() != text;
    }
    if (!file.kept) {
      if (Status s = io::writeFileAtomically(file.path, text); !s.ok()) return s;
    }
    written.push_back(std::move(file));
  }
  return written;
}

}  // namespace collido::study
