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

/// A sphere holding every vertex: the centre of the axis-aligned bounds and the farthest vertex
/// from it. Loose but stable; what a scene's random overlap motion places objects by.
struct BoundingSphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;
};
BoundingSphere boundingSphere(const TriangleMesh& mesh);

/// The largest coordinate magnitude a mesh (or a scene's translation) may have: |x| <= 1e18.
/// Far beyond any scene's size (the stress suite goes to 1e15 from the origin and scales to
/// 1e15), yet small enough that what backends compute from coordinates stays finite: squared
/// lengths and dot products of coordinate differences (below 5e37, also in world coordinates)
/// even in single precision, where Bullet, ODE and the OBB tree's float boxes overflow past
/// 3.4e38; and the degree-3 orientation determinants of exact predicates (about 1e57 at most)
/// deep inside the double range, whose overflow is the one thing that breaks them. Measured with
/// bunny_vs_bunny: scaled by 1e19 every bundled backend answered as scaled by 1e15; by 1e40 the
/// single-precision ones missed every contact, by 1e100 FCL lost half the pairs, and by 1e150
/// the run did not finish in 5 minutes (FCL's eigen solver looping).
constexpr double kMaxCoordinate = 1e18;

/// Checks what every consumer relies on: at least one triangle, finite coordinates within
/// kMaxCoordinate, indices in range. The message names `source` (a file or generator) and the
/// offending vertex/triangle.
Status validateMesh(const TriangleMesh& mesh, const std::string& source);

}  // namespace collido
