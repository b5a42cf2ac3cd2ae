// OpenVDB's volume-to-mesh behind a C entry point, loaded only by the processes that polygonize
// (core/src/frep_mesh/polygonize.cpp); see openvdb_mesher_api.h for why it is a module.
#include <cstdio>
#include <exception>
#include <mutex>
#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

#include "openvdb_mesher_api.h"

namespace {

int runMesher(const CollidoMesherRequest& request) {
  static std::once_flag initialised;
  std::call_once(initialised, [] { openvdb::initialize(); });

  // The background (the value of unset voxels) is "outside": one cell away from the surface.
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(static_cast<float>(request.cell));
  grid->setTransform(openvdb::math::Transform::createLinearTransform(request.cell));
  openvdb::FloatGrid::Accessor voxels = grid->getAccessor();
  for (int32_t i = 0; i < request.counts[0]; ++i) {
    for (int32_t j = 0; j < request.counts[1]; ++j) {
      for (int32_t k = 0; k < request.counts[2]; ++k)
        voxels.setValue(openvdb::Coord(i, j, k), request.level(request.level_context, i, j, k));
    }
  }
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.0, 0.0);

  for (const openvdb::Vec3s& p : points)
    request.vertex(request.mesh_context, p.x(), p.y(), p.z());
  for (const openvdb::Vec3I& tri : triangles) {
    const uint32_t corners[3] = {tri[0], tri[1], tri[2]};
    request.polygon(request.mesh_context, corners, 3);
  }
  for (const openvdb::Vec4I& quad : quads) {
    const uint32_t corners[4] = {quad[0], quad[1], quad[2], quad[3]};
    request.polygon(request.mesh_context, corners, 4);
  }
  return 0;
}

}  // namespace

extern "C" int collido_openvdb_mesher_v1(const CollidoMesherRequest* request, char* error,
                                         size_t error_size) {
  try {
    return runMesher(*request);
  } catch (const std::exception& e) {
    std::snprintf(error, error_size, "OpenVDB: %s", e.what());
  } catch (...) {
    std::snprintf(error, error_size, "OpenVDB threw an unknown exception");
  }
  return 1;
}
