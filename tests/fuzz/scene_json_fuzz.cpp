// scene_json_fuzz: the scene loader (collido::parseScene) on arbitrary bytes.
//
// Why: scene files come from users and from generators; the loader is the one gate between them
// and every backend, and it promises "a scene that loads is a scene that runs".
// What it checks:
//  - whatever the bytes, parseScene returns (an error Result is a fine answer) without a crash,
//    an out-of-bounds access, undefined behaviour or a leak (ASan, UBSan, LeakSanitizer);
//  - a scene that loads keeps the promise: every object has a valid mesh (validateMesh: triangles,
//    finite coordinates, indices in range) and finite rigid poses, one for all frames or one per
//    frame; every query names existing objects (two different ones, or a sorted group of two or
//    more); an error message names the label.
// Resources: the load runs with SceneLoadOptions::max_triangles and max_frames far below their
// defaults, so an input asking for a 50-million-triangle torus or a million frames is refused
// by the loader's own limits (and an error naming the JSON path) instead of exhausting the
// fuzzer's memory; those limits are part of what is fuzzed.
// Mesh paths resolve against a temporary folder holding one tiny tetrahedron per format the
// loader reads directly (tet.obj, tet.off, tet.ply, tet.stl), a quad (quad.obj) and a marker
// tracks file (tracks.csv, object "m", markers 1 to 4, frames 0 to 2); the bundled
// meshes are not used, since reading a 70,000-triangle scan per input would slow fuzzing a
// hundredfold. The folder is removed at exit.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include <unistd.h>

#include <collido/mesh/triangle_mesh.h>
#include <collido/scene/scene.h>

namespace {

constexpr const char* kLabel = "fuzz.json";

// The tiny meshes scene inputs may name (the seeds in corpus/scene_json_fuzz/ do).
constexpr const char* kTetObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
constexpr const char* kTetOff =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n"
    "3 0 3 2\n3 1 2 3\n";
constexpr const char* kTetPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\n"
    "property double y\nproperty double z\nelement face 4\n"
    "property list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
constexpr const char* kTetStl =
    "solid tet\n"
    "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\n"
    "endfacet\n"
    "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\n"
    "endfacet\n"
    "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\n"
    "endfacet\n"
    "facet normal 1 1 1\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\n"
    "endfacet\n"
    "endsolid tet\n";
constexpr const char* kQuadObj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
// Marker tracks of an object "m" with markers 1 to 4 over frames 0 to 2 (frame 1 sees three).
constexpr const char* kTracksCsv =
    "frame,object,marker,x,y,z\n0,m,1,0,0,0\n0,m,2,1,0,0\n0,m,3,0,1,0\n0,m,4,0,0,1\n"
    "1,m,1,0.5,0,0\n1,m,2,1.5,0,0\n1,m,3,0.5,1,0\n"
    "2,m,1,1,0,0\n2,m,2,2,0,0\n2,m,3,1,1,0\n2,m,4,1,0,1\n";

/// The folder of the tiny meshes, made on first use and removed at exit.
class MeshFolder {
 public:
  MeshFolder()
      : path_(std::filesystem::temp_directory_path() /
              ("collido_scene_fuzz." + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
    const std::pair<const char*, const char*> files[] = {
        {"tet.obj", kTetObj}, {"tet.off", kTetOff},   {"tet.ply", kTetPly},
        {"tet.stl", kTetStl}, {"quad.obj", kQuadObj}, {"tracks.csv", kTracksCsv}};
    for (const auto& [name, text] : files)
      std::ofstream(path_ / name) << text;
  }
  ~MeshFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  MeshFolder(const MeshFolder&) = delete;
  MeshFolder& operator=(const MeshFolder&) = delete;
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

const std::string& meshFolder() {
  static const MeshFolder folder;
  static const std::string path = folder.path();
  return path;
}

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "scene_json_fuzz: the loader broke its promise: %s\n", what.c_str());
  std::abort();
}

/// Rigid within the loader's own tolerance, with room for the rounding of composed motions.
bool rigid(const collido::Pose& pose) {
  if (!pose.matrix().allFinite()) return false;
  const Eigen::Matrix3d r = pose.linear();
  const double drift = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  return drift <= 1e-6 && r.determinant() > 0.0;
}

void checkScene(const collido::Scene& scene, const collido::SceneLoadOptions& options) {
  if (scene.frames < 1 || scene.frames > options.max_frames) broken("frame count out of range");
  if (scene.objects.empty() || scene.queries.empty()) broken("no objects or no queries");
  std::size_t triangles = 0;
  for (const collido::SceneObject& object : scene.objects) {
    if (!object.mesh) broken("object '" + object.name + "' has no mesh");
    if (collido::Status s = collido::validateMesh(*object.mesh, object.name); !s.ok())
      broken(s.message());
    triangles += object.mesh->triangleCount();
    if (object.poses.size() != 1 && object.poses.size() != scene.frames)
      broken("object '" + object.name + "' has " + std::to_string(object.poses.size()) +
             " poses for " + std::to_string(scene.frames) + " frames");
    for (const collido::Pose& pose : object.poses) {
      if (!rigid(pose)) broken("object '" + object.name + "' has a pose that is not rigid");
    }
    // Deformable objects: valid states, a schedule naming them, and deformed frames that keep
    // the topology and stay valid (the first and the last, which the loader checked among all).
    for (const collido::ObjectState& state : object.states) {
      if (!state.mesh) broken("object '" + object.name + "' has a state without a mesh");
      if (collido::Status s = collido::validateMesh(*state.mesh, object.name); !s.ok())
        broken(s.message());
    }
    if (!object.schedule.empty() && object.schedule.size() != scene.frames)
      broken("object '" + object.name + "' has a schedule of the wrong length");
    for (std::size_t state : object.schedule) {
      if (state >= object.stateCount())
        broken("object '" + object.name + "' schedules a state that does not exist");
    }
    // Tracked objects: a true and a recovered pose per frame, the recovered ones rigid (above).
    if (object.tracking) {
      if (object.tracking->true_poses.size() != scene.frames ||
          object.tracking->frames.size() != scene.frames || object.poses.size() != scene.frames)
        broken("tracked object '" + object.name + "' lacks a pose for some frame");
      for (const collido::Pose& pose : object.tracking->true_poses) {
        if (!rigid(pose)) broken("tracked object '" + object.name + "' has a non-rigid truth");
      }
    }
    if (object.deformation) {
      for (std::size_t frame : {std::size_t{0}, scene.frames - 1}) {
        const auto shape = object.shapeAt(frame);
        if (shape->triangles != object.stateMesh(object.stateAt(frame))->triangles)
          broken("object '" + object.name + "' changes topology when it deforms");
        if (collido::Status s = collido::validateMesh(*shape, object.name); !s.ok())
          broken("deformed frame " + std::to_string(frame) + ": " + s.message());
      }
    }
  }
  if (triangles > options.max_triangles) broken("more triangles than max_triangles");
  const std::size_t n = scene.objects.size();
  for (const collido::SceneObject& object : scene.objects) {
    if (object.parent && *object.parent >= n) broken("object '" + object.name + "' has no parent");
  }
  for (const collido::SceneQuery& query : scene.queries) {
    if (query.isGroup()) {
      if (query.among.size() < 2) broken("group query '" + query.name + "' of fewer than two");
      for (std::size_t i = 0; i < query.among.size(); ++i) {
        if (query.among[i] >= n || (i > 0 && query.among[i - 1] >= query.among[i]))
          broken("group query '" + query.name + "' is not a sorted list of objects");
      }
      // Two sides: the second a sorted proper subset of the group, so both sides hold objects.
      if (!query.side_b.empty() && (query.side_b.size() >= query.among.size() ||
                                    !std::is_sorted(query.side_b.begin(), query.side_b.end()) ||
                                    !std::includes(query.among.begin(), query.among.end(),
                                                   query.side_b.begin(), query.side_b.end()))) {
        broken("group query '" + query.name + "' has a second side outside its objects");
      }
    } else if (query.a >= n || query.b >= n || query.a == query.b) {
      broken("query '" + query.name + "' does not name two different objects");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  collido::SceneLoadOptions options;
  options.max_triangles = 200000;
  options.max_frames = 1000;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const collido::Result<collido::Scene> scene =
      collido::parseScene(text, kLabel, meshFolder(), options);
  if (scene.ok()) {
    checkScene(scene.value(), options);
  } else if (scene.status().message().find(kLabel) == std::string::npos) {
    broken("an error that does not name the file: " + scene.status().message());
  }
  return 0;
}
