// Measurements and checks of generated meshes, shared by the generator tests.
#pragma once

#include <cstdint>
#include <string>

#include <collido/mesh/triangle_mesh.h>
#include <collido/status.h>
#include <gtest/gtest.h>

namespace collido::test {

/// The mesh, or an empty one (failing every later check) after reporting why there is none.
TriangleMesh build(const Result<TriangleMesh>& result);

/// Signed volume by the divergence theorem: the sum of the tetrahedra (origin, a, b, c).
double enclosedVolume(const TriangleMesh& mesh);

/// A map key for the directed edge a -> b.
std::int64_t edgeKey(int a, int b);

/// Each directed edge (a, b) must be used exactly once and its reverse (b, a) exactly once: the
/// surface is closed, every edge has two triangles, and neighbours wind the same way.
::testing::AssertionResult isClosedAndConsistentlyOriented(const TriangleMesh& mesh);

/// V - E + F with undirected edges; 2 for a sphere, 0 for a torus, 1 for a disk.
long eulerCharacteristic(const TriangleMesh& mesh);

double smallestTriangleArea(const TriangleMesh& mesh);

/// Smallest distance between two distinct vertices.
double smallestVertexSeparation(const TriangleMesh& mesh);

/// Axis-aligned bounds of the vertices.
struct Box {
  Eigen::Vector3d min;
  Eigen::Vector3d max;
};
Box boundingBox(const TriangleMesh& mesh);

/// The bounds are min and max to 1e-12.
void expectBox(const TriangleMesh& mesh, const Eigen::Vector3d& min, const Eigen::Vector3d& max);

/// The checks every closed generator must pass; `euler` is the expected V - E + F.
void expectWatertight(const TriangleMesh& mesh, long euler, double min_area);

/// The generator refused with kInvalidArgument, naming itself and the parameter.
void expectInvalid(const Result<TriangleMesh>& result, const std::string& generator,
                   const std::string& parameter);

}  // namespace collido::test
