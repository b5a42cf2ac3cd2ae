#include <collido/mesh/triangle_mesh.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <string>

namespace collido {

namespace {

static_assert(kMaxCoordinate == 1e18, "the messages below say 1e18");

// A coordinate as written in a message: the shortest text that reads back as the same double
// ("-1e+19", "1000000000000000001"), not std::to_string's fixed six decimals.
std::string coordinateText(double value) {
  for (int digits = 1;; ++digits) {
    std::ostringstream text;
    text << std::setprecision(digits) << value;
    // strtod, not stod: a short rounding of a value near the double maximum ("2e+308") is out
    // of range, which stod reports by throwing; strtod returns infinity, which is not `value`.
    if (digits == 17 || std::strtod(text.str().c_str(), nullptr) == value) return text.str();
  }
}

}  // namespace

Status validateMesh(const TriangleMesh& mesh, const std::string& source) {
  if (mesh.triangleCount() == 0) {
    return {StatusCode::kInvalidArgument, source + ": the mesh has no triangles"};
  }
  static const char* const kAxis[] = {"x", "y", "z"};
  // Per vertex, a non-finite coordinate is named before one out of range: it is the worse news.
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    for (int k = 0; k < 3; ++k) {
      const double value = mesh.vertices(k, v);
      if (!std::isfinite(value)) {
        return {StatusCode::kInvalidArgument, source + ": vertex " + std::to_string(v) +
                                                  " has a non-finite " + kAxis[k] +
                                                  " coordinate (" + std::to_string(value) + ")"};
      }
    }
    for (int k = 0; k < 3; ++k) {
      const double value = mesh.vertices(k, v);
      if (std::abs(value) > kMaxCoordinate) {
        return {StatusCode::kInvalidArgument,
                source + ": vertex " + std::to_string(v) + " has " + kAxis[k] + " coordinate " +
                    coordinateText(value) + ", beyond the coordinate limit |" + kAxis[k] +
                    "| <= 1e18 (scenes/README.md)"};
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

BoundingSphere boundingSphere(const TriangleMesh& mesh) {
  const Eigen::Vector3d low = mesh.vertices.rowwise().minCoeff();
  const Eigen::Vector3d high = mesh.vertices.rowwise().maxCoeff();
  BoundingSphere sphere;
  sphere.centre = 0.5 * (low + high);
  sphere.radius = (mesh.vertices.colwise() - sphere.centre).colwise().norm().maxCoeff();
  return sphere;
}

}  // namespace collido
