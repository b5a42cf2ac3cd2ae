#pragma once

#include <cstddef>
#include <string>

#include <Eigen/Core>

#include <collido/geometry.h>
#include <collido/status.h>

namespace collido {

/// A triangle mesh in its model frame, owned. Degenerate triangles and duplicate vertices are
/// legitimate input and kept as they are.
struct TriangleMesh {
  Eigen::Matrix3Xd vertices;   ///< one column per vertex
  Eigen::Matrix3Xi triangles;  ///< one column of vertex indices per triangle, counter-clockwise
                               ///< seen from outside for closed meshes

  std::size_t vertexCount() const { return static_cast<std::size_t>(vertices.cols()); }
  std::size_t triangleCount() const { return static_cast<std::size_t>(triangles.cols()); }
  /// A borrowed view for backends.
  MeshView view() const {
    return MeshView{Eigen::Map<const Eigen::Matrix3Xd>(vertices.data(), 3, vertices.cols()),
                    Eigen::Map<const Eigen::Matrix3Xi>(triangles.data(), 3, triangles.cols())};
  }
  /// The three corners of triangle `t`.
  Eigen::Vector3d corner(std::size_t t, int k) const {
    return vertices.col(triangles(k, static_cast<Eigen::Index>(t)));
  }
};

/// Checks what every consumer relies on: at least one triangle, finite coordinates, indices in
/// range. The message names `source` (a file or generator) and the offending vertex/triangle.
Status validateMesh(const TriangleMesh& mesh, const std::string& source);

}  // namespace collido
