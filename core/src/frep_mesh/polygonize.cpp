// Polygonization of FRep solids with OpenVDB: the comparators of the FRep study run mesh
// backends on these meshes.
#include <collido/frep_mesh/polygonize.h>

#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

namespace collido::frep {

Result<TriangleMesh> polygonize(const Solid& solid, const Eigen::AlignedBox3d& region,
                                int resolution) {
  if (region.isEmpty() || !region.min().allFinite() || !region.max().allFinite())
    return Status(StatusCode::kInvalidArgument, "polygonize: the region is empty or unbounded");
  if (resolution < 2 || resolution > 1024) {
    return Status(StatusCode::kInvalidArgument,
                  "polygonize: resolution " + std::to_string(resolution) + " is outside [2, 1024]");
  }
  static std::once_flag initialised;
  std::call_once(initialised, [] { openvdb::initialize(); });

  const double cell = region.sizes().maxCoeff() / resolution;
  if (!(cell > 0) || !std::isfinite(cell) || !region.sizes().allFinite())
    return Status(StatusCode::kInvalidArgument, "polygonize: the region is flat or too large");
  // One padding cell on each side: the grid's border then lies outside the solid.
  const Eigen::Vector3d origin = region.min() - Eigen::Vector3d::Constant(cell);
  const Eigen::Vector3i counts = (region.sizes() / cell).array().ceil().cast<int>() + 3;

  // OpenVDB's level sets are negative inside; ours are positive inside. The background (the
  // value of unset voxels) is "outside".
  const float outside = static_cast<float>(cell);
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(outside);
  grid->setTransform(openvdb::math::Transform::createLinearTransform(cell));
  openvdb::FloatGrid::Accessor voxels = grid->getAccessor();
  bool inside_seen = false;
  for (int i = 0; i < counts.x(); ++i) {
    for (int j = 0; j < counts.y(); ++j) {
      for (int k = 0; k < counts.z(); ++k) {
        const Eigen::Vector3d p = origin + cell * Eigen::Vector3d(i, j, k);
        const float value = static_cast<float>(-solid.value(p));
        if (value <= 0) inside_seen = true;
        voxels.setValue(openvdb::Coord(i, j, k), value);
      }
    }
  }
  if (!inside_seen) {
    return Status(StatusCode::kInvalidArgument,
                  "polygonize: no grid point lies inside the solid at resolution " +
                      std::to_string(resolution));
  }
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.0, 0.0);

  TriangleMesh mesh;
  mesh.vertices.resize(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t v = 0; v < points.size(); ++v) {
    // OpenVDB answers in the grid's world frame: index times the cell, from `origin`.
    mesh.vertices.col(static_cast<Eigen::Index>(v)) =
        origin + Eigen::Vector3d(points[v].x(), points[v].y(), points[v].z());
  }
  mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles.size() + 2 * quads.size()));
  Eigen::Index t = 0;
  // OpenVDB's order is counter-clockwise seen from outside (tested: positive signed volume).
  const auto index = [](unsigned int i) { return static_cast<int>(i); };
  for (const openvdb::Vec3I& tri : triangles)
    mesh.triangles.col(t++) << index(tri[0]), index(tri[1]), index(tri[2]);
  for (const openvdb::Vec4I& quad : quads) {
    mesh.triangles.col(t++) << index(quad[0]), index(quad[1]), index(quad[2]);
    mesh.triangles.col(t++) << index(quad[0]), index(quad[2]), index(quad[3]);
  }
  if (mesh.triangleCount() == 0) {
    return Status(
        StatusCode::kInvalidArgument,
        "polygonize: no surface inside the region at resolution " + std::to_string(resolution));
  }
  return mesh;
}

}  // namespace collido::frep
