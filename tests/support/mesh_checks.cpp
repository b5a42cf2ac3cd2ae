#include "support/mesh_checks.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace collido::test {

TriangleMesh build(const Result<TriangleMesh>& result) {
  if (result.ok()) return result.value();
  ADD_FAILURE() << result.status().toString();
  return {};
}

double enclosedVolume(const TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    six_volume += mesh.corner(t, 0).dot(mesh.corner(t, 1).cross(mesh.corner(t, 2)));
  }
  return six_volume / 6.0;
}

std::int64_t edgeKey(int a, int b) {
  return (static_cast<std::int64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

::testing::AssertionResult isClosedAndConsistentlyOriented(const TriangleMesh& mesh) {
  std::unordered_map<std::int64_t, int> uses;
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    for (int k = 0; k < 3; ++k) {
      ++uses[edgeKey(mesh.triangles(k, t), mesh.triangles((k + 1) % 3, t))];
    }
  }
  for (const auto& [key, count] : uses) {
    const int a = static_cast<int>(key >> 32);
    const int b = static_cast<int>(key & 0xffffffff);
    if (count != 1) {
      return ::testing::AssertionFailure()
             << "directed edge " << a << "->" << b << " used " << count << " times";
    }
    const auto reverse = uses.find(edgeKey(b, a));
    if (reverse == uses.end()) {
      return ::testing::AssertionFailure() << "edge " << a << "->" << b << " has no reverse";
    }
  }
  return ::testing::AssertionSuccess();
}

long eulerCharacteristic(const TriangleMesh& mesh) {
  std::unordered_map<std::int64_t, int> edges;
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(k, t);
      const int b = mesh.triangles((k + 1) % 3, t);
      ++edges[edgeKey(std::min(a, b), std::max(a, b))];
    }
  }
  return static_cast<long>(mesh.vertexCount()) - static_cast<long>(edges.size()) +
         static_cast<long>(mesh.triangleCount());
}

double smallestTriangleArea(const TriangleMesh& mesh) {
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Eigen::Vector3d a = mesh.corner(t, 0);
    const double area = 0.5 * (mesh.corner(t, 1) - a).cross(mesh.corner(t, 2) - a).norm();
    smallest = std::min(smallest, area);
  }
  return smallest;
}

// A sweep along x, so it stays fast.
double smallestVertexSeparation(const TriangleMesh& mesh) {
  std::vector<Eigen::Index> order(mesh.vertexCount());
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return mesh.vertices(0, a) < mesh.vertices(0, b);
  });
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      if (mesh.vertices(0, order[j]) - mesh.vertices(0, order[i]) >= smallest) break;
      smallest =
          std::min(smallest, (mesh.vertices.col(order[j]) - mesh.vertices.col(order[i])).norm());
    }
  }
  return smallest;
}

Box boundingBox(const TriangleMesh& mesh) {
  return {mesh.vertices.rowwise().minCoeff(), mesh.vertices.rowwise().maxCoeff()};
}

void expectBox(const TriangleMesh& mesh, const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  const Box box = boundingBox(mesh);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(box.min[k], min[k], 1e-12) << "axis " << k;
    EXPECT_NEAR(box.max[k], max[k], 1e-12) << "axis " << k;
  }
}

void expectWatertight(const TriangleMesh& mesh, long euler, double min_area) {
  const Status valid = validateMesh(mesh, "generated mesh");
  ASSERT_TRUE(valid.ok()) << valid.toString();
  EXPECT_TRUE(isClosedAndConsistentlyOriented(mesh));
  EXPECT_EQ(eulerCharacteristic(mesh), euler);
  EXPECT_GT(smallestTriangleArea(mesh), min_area);
  EXPECT_GT(smallestVertexSeparation(mesh), 1e-9);
  EXPECT_GT(enclosedVolume(mesh), 0.0) << "outward winding gives a positive volume";
}

void expectInvalid(const Result<TriangleMesh>& result, const std::string& generator,
                   const std::string& parameter) {
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), StatusCode::kInvalidArgument);
  const std::string& message = result.status().message();
  EXPECT_NE(message.find(generator), std::string::npos) << message;
  EXPECT_NE(message.find(parameter), std::string::npos) << message;
}

}  // namespace collido::test
