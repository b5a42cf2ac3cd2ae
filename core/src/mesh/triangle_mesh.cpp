#include <collido/mesh/triangle_mesh.h>

#include <cmath>

namespace collido {

Status validateMesh(const TriangleMesh& mesh, const std::string& source) {
  if (mesh.triangleCount() == 0) {
    return {StatusCode::kInvalidArgument, source + ": the mesh has no triangles"};
  }
  static const char* const kAxis[] = {"x", "y", "z"};
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    for (int k = 0; k < 3; ++k) {
      const double value = mesh.vertices(k, v);
      if (!std::isfinite(value)) {
        return {StatusCode::kInvalidArgument, source + ": vertex " + std::to_string(v) +
                                                  " has a non-finite " + kAxis[k] +
                                                  " coordinate (" + std::to_string(value) + ")"};
      }
    }
  }
  const Eigen::Index vertex_count = mesh.vertices.cols();
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int index = mesh.triangles(k, t);
      if (index < 0 || index >= vertex_count) {
        return {StatusCode::kInvalidArgument,
                source + ": triangle " + std::to_string(t) + " references vertex " +
                    std::to_string(index) + ", but the mesh has " + std::to_string(vertex_count) +
                    " vertices (valid: 0.." + std::to_string(vertex_count - 1) + ")"};
      }
    }
  }
  return {};
}

}  // namespace collido
