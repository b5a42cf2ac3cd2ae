// Polygonization of FRep solids with OpenVDB: the comparators of the FRep study run mesh
// backends on these meshes. OpenVDB itself sits in a module opened on first use
// (openvdb_mesher_api.h says why).
#include <collido/frep_mesh/polygonize.h>

#include <dlfcn.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "openvdb_mesher_api.h"

namespace collido::frep {
namespace {

// Where the module is looked for, first found wins: beside the running executable (the build
// tree's `collido`), the install's library folder relative to it, then where this library's
// own build put it and where its install puts it (programs linking the installed package).
std::vector<std::filesystem::path> mesherCandidates() {
  std::vector<std::filesystem::path> candidates;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back(exe.parent_path() / COLLIDO_OPENVDB_MESHER_FILE);
    candidates.push_back(exe.parent_path().parent_path() / "lib" / "collido" /
                         COLLIDO_OPENVDB_MESHER_FILE);
  }
  candidates.emplace_back(COLLIDO_OPENVDB_MESHER_BUILT);
  candidates.emplace_back(COLLIDO_OPENVDB_MESHER_INSTALLED);
  return candidates;
}

// The module's entry point, or why there is none.
struct Mesher {
  CollidoMesherRun run = nullptr;
  std::string why_missing;
};

// Opened once and kept for the process's life.
const Mesher& mesher() {
  static const Mesher found = [] {
    std::string tried;
    for (const std::filesystem::path& candidate : mesherCandidates()) {
      std::error_code ec;
      if (!std::filesystem::is_regular_file(candidate, ec)) {
        tried += "\n  " + candidate.string() + ": not found";
        continue;
      }
      void* module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (module == nullptr) {
        tried += "\n  " + candidate.string() + ": " + dlerror();
        continue;
      }
      // dlsym returns void*; converting it to a function pointer is what POSIX requires.
      auto* run = reinterpret_cast<CollidoMesherRun>(  // NOLINT
          dlsym(module, COLLIDO_OPENVDB_MESHER_ENTRY));
      if (run != nullptr) return Mesher{run, {}};
      tried += "\n  " + candidate.string() +
               ": no entry point " COLLIDO_OPENVDB_MESHER_ENTRY
               " (a module of another interface version)";
    }
    return Mesher{nullptr,
                  "polygonize: OpenVDB's mesher module could not be loaded; tried:" + tried};
  }();
  return found;
}

// The solid sampled for the module: OpenVDB's level sets are negative inside, ours positive.
struct Sampling {
  const Solid* solid;
  Eigen::Vector3d origin;
  double cell;
  bool inside_seen = false;
};

float sampleLevel(void* context, int32_t i, int32_t j, int32_t k) {
  auto& sampling = *static_cast<Sampling*>(context);
  const Eigen::Vector3d p = sampling.origin + sampling.cell * Eigen::Vector3d(i, j, k);
  const float value = static_cast<float>(-sampling.solid->value(p));
  if (value <= 0) sampling.inside_seen = true;
  return value;
}

struct MeshBuilder {
  Eigen::Vector3d origin;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  bool index_overflow = false;
};

void addVertex(void* context, double x, double y, double z) {
  auto& builder = *static_cast<MeshBuilder*>(context);
  // OpenVDB answers in the grid's frame: index times the cell, from `origin`.
  builder.vertices.push_back(builder.origin + Eigen::Vector3d(x, y, z));
}

void addPolygon(void* context, const uint32_t* corners, int32_t corner_count) {
  auto& builder = *static_cast<MeshBuilder*>(context);
  int index[4] = {0, 0, 0, 0};
  for (int32_t c = 0; c < corner_count && c < 4; ++c) {
    if (corners[c] > static_cast<uint32_t>(INT32_MAX)) builder.index_overflow = true;
    index[c] = static_cast<int>(corners[c]);
  }
  // A quad as two triangles about its first corner keeps OpenVDB's orientation (counter-clockwise
  // seen from outside; tested: positive signed volume).
  builder.triangles.emplace_back(index[0], index[1], index[2]);
  if (corner_count == 4) builder.triangles.emplace_back(index[0], index[2], index[3]);
}

}  // namespace

Result<TriangleMesh> polygonize(const Solid& solid, const Eigen::AlignedBox3d& region,
                                int resolution) {
  if (region.isEmpty() || !region.min().allFinite() || !region.max().allFinite())
    return Status(StatusCode::kInvalidArgument, "polygonize: the region is empty or unbounded");
  if (resolution < 2 || resolution > 1024) {
    return Status(StatusCode::kInvalidArgument,
                  "polygonize: resolution " + std::to_string(resolution) + " is outside [2, 1024]");
  }
  const double cell = region.sizes().maxCoeff() / resolution;
  if (!(cell > 0) || !std::isfinite(cell) || !region.sizes().allFinite())
    return Status(StatusCode::kInvalidArgument, "polygonize: the region is flat or too large");
  const Mesher& loaded = mesher();
  if (loaded.run == nullptr) return Status(StatusCode::kUnsupported, loaded.why_missing);

  // One padding cell on each side: the grid's border then lies outside the solid.
  const Eigen::Vector3d origin = region.min() - Eigen::Vector3d::Constant(cell);
  const Eigen::Vector3i counts = (region.sizes() / cell).array().ceil().cast<int>() + 3;
  Sampling sampling{&solid, origin, cell};
  MeshBuilder builder{origin, {}, {}};
  const CollidoMesherRequest request{cell,         {counts.x(), counts.y(), counts.z()},
                                     &sampleLevel, &sampling,
                                     &addVertex,   &addPolygon,
                                     &builder};
  char error[512] = {};
  if (loaded.run(&request, error, sizeof error) != 0)
    return Status(StatusCode::kEngineFailure, std::string("polygonize: ") + error);
  if (!sampling.inside_seen) {
    return Status(StatusCode::kInvalidArgument,
                  "polygonize: no grid point lies inside the solid at resolution " +
                      std::to_string(resolution));
  }
  if (builder.index_overflow)
    return Status(StatusCode::kInvalidArgument, "polygonize: the mesh has too many vertices");
  if (builder.triangles.empty()) {
    return Status(
        StatusCode::kInvalidArgument,
        "polygonize: no surface inside the region at resolution " + std::to_string(resolution));
  }
  TriangleMesh mesh;
  mesh.vertices.resize(3, static_cast<Eigen::Index>(builder.vertices.size()));
  for (std::size_t v = 0; v < builder.vertices.size(); ++v)
    mesh.vertices.col(static_cast<Eigen::Index>(v)) = builder.vertices[v];
  mesh.triangles.resize(3, static_cast<Eigen::Index>(builder.triangles.size()));
  for (std::size_t t = 0; t < builder.triangles.size(); ++t)
    mesh.triangles.col(static_cast<Eigen::Index>(t)) = builder.triangles[t];
  return mesh;
}

}  // namespace collido::frep
