// Mesh import: file order, exact coordinates, every format we read, and the oddities that are
// counted and kept. Small files are written by hand into a temporary folder, so each test states
// its input literally.
#include <collido/mesh/mesh_io.h>

#include <cstdint>
#include <cstring>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace collido {
namespace {

/// Writes `contents` as `name` into a fresh temporary folder and returns its path.
std::string writeTemp(const std::string& name, const std::string& contents) {
  std::string path = test::makeTempDirectory("mesh_io") + "/" + name;
  test::writeFile(path, contents);
  return path;
}

/// The mesh, or an empty one (failing every later check) after reporting why there is none.
TriangleMesh load(const std::string& path, MeshReport* report = nullptr) {
  Result<TriangleMesh> mesh = loadMesh(path, report);
  if (mesh.ok()) return std::move(mesh).value();
  ADD_FAILURE() << mesh.status().toString();
  return {};
}

// ---- the bunny: file order -------------------------------------------------------------------

TEST(MeshIo, BunnyObjLoadsInFileOrder) {
  MeshReport report;
  const TriangleMesh mesh = load(test::sourcePath("scenes/meshes/bunny.obj"), &report);
  ASSERT_EQ(mesh.vertexCount(), 1839u);
  ASSERT_EQ(mesh.triangleCount(), 3674u);
  // The file's first lines: "v 1.301895 0.122622 2.550061" and "f 3 1662 4" (1-based).
  EXPECT_EQ(mesh.vertices(0, 0), 1.301895);
  EXPECT_EQ(mesh.vertices(1, 0), 0.122622);
  EXPECT_EQ(mesh.vertices(2, 0), 2.550061);
  EXPECT_EQ(mesh.triangles(0, 0), 2);
  EXPECT_EQ(mesh.triangles(1, 0), 1661);
  EXPECT_EQ(mesh.triangles(2, 0), 3);
  EXPECT_EQ(report.vertices, 1839u);
  EXPECT_EQ(report.triangles, 3674u);
  EXPECT_FALSE(report.single_precision);
  EXPECT_EQ(report.importer, "OBJ reader");
  EXPECT_EQ(report.polygons_triangulated, 0u);
  EXPECT_EQ(report.skipped_primitives, 0u);
  EXPECT_NE(report.summary().find("3674 triangles, 1839 vertices"), std::string::npos)
      << report.summary();
}

// ---- exact coordinates -----------------------------------------------------------------------

// 0.1, 0.2 and 0.3 are not floats: a path through 32-bit floats gives 0.100000001490116...
TEST(MeshIo, ObjCoordinatesAreTheDoublesOfTheText) {
  MeshReport report;
  const TriangleMesh mesh = load(writeTemp("exact.obj",
                                           "v 0.1 0.2 0.3\n"
                                           "v 1e-300 -123456789.123456789 2.718281828459045\n"
                                           "v 0 1 0\n"
                                           "f 1 2 3\n"),
                                 &report);
  ASSERT_EQ(mesh.vertexCount(), 3u);
  EXPECT_EQ(mesh.vertices(0, 0), 0.1);
  EXPECT_EQ(mesh.vertices(1, 0), 0.2);
  EXPECT_EQ(mesh.vertices(2, 0), 0.3);
  EXPECT_NE(mesh.vertices(0, 0), static_cast<double>(0.1f));
  EXPECT_EQ(mesh.vertices(0, 1), 1e-300);
  EXPECT_EQ(mesh.vertices(1, 1), -123456789.123456789);
  EXPECT_EQ(mesh.vertices(2, 1), 2.718281828459045);
  EXPECT_FALSE(report.single_precision);
}

// ---- the other double-precision formats ------------------------------------------------------

TEST(MeshIo, OffFileLoads) {
  MeshReport report;
  const TriangleMesh mesh = load(writeTemp("tetra.off",
                                           "OFF\n"
                                           "4 4 0\n"
                                           "0 0 0\n"
                                           "0.1 0 0\n"
                                           "0 1 0\n"
                                           "0 0 1\n"
                                           "3 0 2 1\n"
                                           "3 0 1 3\n"
                                           "3 0 3 2\n"
                                           "3 1 2 3\n"),
                                 &report);
  ASSERT_EQ(mesh.vertexCount(), 4u);
  ASSERT_EQ(mesh.triangleCount(), 4u);
  EXPECT_EQ(mesh.vertices(0, 1), 0.1);
  EXPECT_EQ(mesh.triangles.col(0), Eigen::Vector3i(0, 2, 1));
  EXPECT_EQ(mesh.triangles.col(3), Eigen::Vector3i(1, 2, 3));
  EXPECT_FALSE(report.single_precision);
  EXPECT_NE(report.importer.find("OFF"), std::string::npos) << report.importer;
}

TEST(MeshIo, AsciiPlyFileLoads) {
  MeshReport report;
  const TriangleMesh mesh = load(writeTemp("triangle.ply",
                                           "ply\n"
                                           "format ascii 1.0\n"
                                           "element vertex 3\n"
                                           "property double x\n"
                                           "property double y\n"
                                           "property double z\n"
                                           "element face 1\n"
                                           "property list uchar int vertex_indices\n"
                                           "end_header\n"
                                           "0.1 0.2 0.3\n"
                                           "1 0 0\n"
                                           "0 1 0\n"
                                           "3 0 1 2\n"),
                                 &report);
  ASSERT_EQ(mesh.vertexCount(), 3u);
  ASSERT_EQ(mesh.triangleCount(), 1u);
  EXPECT_EQ(mesh.vertices(0, 0), 0.1);
  EXPECT_EQ(mesh.vertices(2, 0), 0.3);
  EXPECT_EQ(mesh.triangles.col(0), Eigen::Vector3i(0, 1, 2));
  EXPECT_FALSE(report.single_precision);
  EXPECT_NE(report.importer.find("PLY"), std::string::npos) << report.importer;
}

// STL stores corners per facet; the reader joins corners at the same position, so two facets
// sharing an edge give 4 vertices.
TEST(MeshIo, AsciiStlFileLoads) {
  MeshReport report;
  const TriangleMesh mesh = load(writeTemp("square.stl",
                                           "solid square\n"
                                           "facet normal 0 0 1\n"
                                           " outer loop\n"
                                           "  vertex 0 0 0\n"
                                           "  vertex 0.1 0 0\n"
                                           "  vertex 0.1 1 0\n"
                                           " endloop\n"
                                           "endfacet\n"
                                           "facet normal 0 0 1\n"
                                           " outer loop\n"
                                           "  vertex 0 0 0\n"
                                           "  vertex 0.1 1 0\n"
                                           "  vertex 0 1 0\n"
                                           " endloop\n"
                                           "endfacet\n"
                                           "endsolid square\n"),
                                 &report);
  ASSERT_EQ(mesh.triangleCount(), 2u);
  EXPECT_EQ(mesh.vertexCount(), 4u);
  EXPECT_EQ(mesh.corner(0, 1), Eigen::Vector3d(0.1, 0.0, 0.0));
  EXPECT_EQ(mesh.corner(1, 2), Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_EQ(mesh.triangles(0, 0), mesh.triangles(0, 1));  // the shared corner (0, 0, 0)
  EXPECT_FALSE(report.single_precision);
  EXPECT_NE(report.importer.find("STL"), std::string::npos) << report.importer;
}

// Geomview's variants: NOFF (a normal after the point), 4OFF (divided by w), nOFF (the dimension
// first), comments anywhere, and a file without the keyword.
TEST(MeshIo, OffVariantsLoad) {
  const Eigen::Vector3d second(0.1, 0, 0);
  for (const std::string& text :
       {std::string("NOFF # normals\n3 1 0\n0 0 0 0 0 1\n0.1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"),
        std::string("4OFF\n3 1 0\n0 0 0 2\n0.2 0 0 2\n0 2 0 2\n3 0 1 2\n"),
        std::string("nOFF\n3\n3 1\n0 0 0\n0.1 0 0\n# a comment line\n0 1 0\n3 0 1 2\n"),
        std::string("3 1 0\n0 0 0\n0.1 0 0\n0 1 0\n3 0 1 2 # no keyword\n")}) {
    const TriangleMesh mesh = load(writeTemp("variant.off", text));
    ASSERT_EQ(mesh.triangleCount(), 1u) << text;
    EXPECT_EQ(mesh.corner(0, 1), second) << text;
    EXPECT_EQ(mesh.corner(0, 2), Eigen::Vector3d(0, 1, 0)) << text;
  }
}

// ---- binary files ----------------------------------------------------------------------------

/// `value`'s bytes, most significant first (binary OFF, binary_big_endian PLY).
template <typename T>
std::string bigEndian(T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  return std::string(std::rbegin(bytes), std::rend(bytes));
}

// Binary OFF: big-endian counts and floats, and after each face's indices a count of colour
// components and that many floats. (CGAL 5.5's read_OFF, used before, skipped no colour count and
// read every second face of such a file as empty.)
TEST(MeshIo, BinaryOffLoads) {
  std::string off = "OFF BINARY\n";
  for (std::int32_t count : {4, 2, 0})
    off += bigEndian(count);
  for (float c : {0.0f, 0.0f, 0.0f, 0.5f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f})
    off += bigEndian(c);
  for (std::int32_t value : {3, 0, 1, 2, 3})  // face 0, then three colour components
    off += bigEndian(value);
  for (float c : {1.0f, 0.5f, 0.0f})
    off += bigEndian(c);
  for (std::int32_t value : {3, 0, 1, 3, 0})  // face 1, no colour
    off += bigEndian(value);
  MeshReport report;
  const TriangleMesh mesh = load(writeTemp("binary.off", off), &report);
  ASSERT_EQ(mesh.triangleCount(), 2u);
  EXPECT_EQ(mesh.corner(0, 1), Eigen::Vector3d(0.5, 0, 0));
  EXPECT_EQ(mesh.triangles.col(1), Eigen::Vector3i(0, 1, 3));
  EXPECT_EQ(report.importer, "OFF reader (binary)");
}

// binary_big_endian PLY with double coordinates, an unused property and element (read past, not
// used) and uint indices: the coordinates are the file's doubles, bit for bit.
TEST(MeshIo, BigEndianPlyWithOtherElementsLoads) {
  std::string ply =
      "ply\nformat binary_big_endian 1.0\ncomment written by hand\nelement vertex 3\n"
      "property double x\nproperty double y\nproperty double z\nproperty uchar red\n"
      "element edge 1\nproperty int vertex1\nproperty list ushort int more\n"
      "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
  const double corners[3][3] = {{0.1, 0.2, 0.3}, {1, 0, 0}, {0, 1, 0}};
  for (const auto& corner : corners) {
    for (double c : corner)
      ply += bigEndian(c);
    ply += '\x07';  // red
  }
  ply += bigEndian(std::int32_t{5}) + bigEndian(std::uint16_t{2}) + bigEndian(std::int32_t{-1}) +
         bigEndian(std::int32_t{9});
  ply += '\x03' + bigEndian(std::uint32_t{0}) + bigEndian(std::uint32_t{1}) +
         bigEndian(std::uint32_t{2});
  MeshReport report;
  const TriangleMesh mesh = load(writeTemp("big.ply", ply), &report);
  ASSERT_EQ(mesh.triangleCount(), 1u);
  EXPECT_EQ(mesh.corner(0, 0), Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_EQ(mesh.triangles.col(0), Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(report.importer, "PLY reader (binary_big_endian)");
}

// A float property holds a float, in ASCII as in binary: 0.1 reads as 0.1f.
TEST(MeshIo, AsciiPlyFloatPropertyReadsAsAFloat) {
  const TriangleMesh mesh = load(writeTemp("float.ply",
                                           "ply\nformat ascii 1.0\nelement vertex 3\n"
                                           "property float x\nproperty float y\n"
                                           "property float z\nelement face 1\n"
                                           "property list uchar int vertex_indices\n"
                                           "end_header\n0.1 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  ASSERT_EQ(mesh.triangleCount(), 1u);
  EXPECT_EQ(mesh.vertices(0, 0), static_cast<double>(0.1f));
}

// ---- glTF through assimp ---------------------------------------------------------------------

// One triangle (0,0,0), (0.1f,0,0), (0,1,0) as little-endian float32, then the indices 0 1 2 as
// uint16 and two bytes of padding, base64-encoded into the file itself.
TEST(MeshIo, GltfLoadsThroughAssimpInSinglePrecision) {
  const std::string gltf = R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
  "buffers": [{"byteLength": 44,
    "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAzczMPQAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [0.1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]
})";
  MeshReport report;
  const TriangleMesh mesh = load(writeTemp("triangle.gltf", gltf), &report);
  ASSERT_EQ(mesh.vertexCount(), 3u);
  ASSERT_EQ(mesh.triangleCount(), 1u);
  EXPECT_TRUE(report.single_precision);
  EXPECT_EQ(report.importer, "assimp");
  EXPECT_EQ(mesh.vertices(0, 1), static_cast<double>(0.1f));  // the float, as the file holds it
  EXPECT_EQ(mesh.vertices(1, 2), 1.0);
  // The triangle's corners, whatever order assimp keeps the vertices in.
  EXPECT_EQ(mesh.corner(0, 0), Eigen::Vector3d(0.0, 0.0, 0.0));
  EXPECT_EQ(mesh.corner(0, 1), Eigen::Vector3d(static_cast<double>(0.1f), 0.0, 0.0));
  EXPECT_EQ(mesh.corner(0, 2), Eigen::Vector3d(0.0, 1.0, 0.0));
}

// ---- polygons --------------------------------------------------------------------------------

// A quad and a pentagon become fans from their first corner: (0 1 2) (0 2 3), (4 5 6) (4 6 7)
// (4 7 8), counted as two polygons triangulated.
TEST(MeshIo, PolygonsAreFanTriangulatedAndCounted) {
  MeshReport report;
  const TriangleMesh mesh = load(writeTemp("polygons.obj",
                                           "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                           "v 0 0 1\nv 2 0 1\nv 3 1 1\nv 1 2 1\nv -1 1 1\n"
                                           "f 1 2 3 4\n"
                                           "f 5 6 7 8 9\n"),
                                 &report);
  ASSERT_EQ(mesh.triangleCount(), 5u);
  EXPECT_EQ(mesh.triangles.col(0), Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(mesh.triangles.col(1), Eigen::Vector3i(0, 2, 3));
  EXPECT_EQ(mesh.triangles.col(2), Eigen::Vector3i(4, 5, 6));
  EXPECT_EQ(mesh.triangles.col(3), Eigen::Vector3i(4, 6, 7));
  EXPECT_EQ(mesh.triangles.col(4), Eigen::Vector3i(4, 7, 8));
  EXPECT_EQ(report.polygons_triangulated, 2u);
  EXPECT_EQ(report.triangles, 5u);
  EXPECT_EQ(report.degenerate_triangles, 0u);
}

// Face corners may carry texture and normal indices ("v/vt/vn", "v//vn") and be separated by
// tabs; only the vertex index counts. (CGAL's reader, used before, skipped to the next space after
// an index, so a tab-separated face lost its last corners.)
TEST(MeshIo, ObjFaceCornersWithSlashesAndTabs) {
  MeshReport report;
  const TriangleMesh mesh = load(writeTemp("corners.obj",
                                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                           "vt 0 0\nvn 0 0 1\n"
                                           "f 1/1/1\t2/1/1\t3/1/1\n"
                                           "f 2//1 4//1 3//1 # a comment\n"),
                                 &report);
  ASSERT_EQ(mesh.triangleCount(), 2u);
  EXPECT_EQ(mesh.triangles.col(0), Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(mesh.triangles.col(1), Eigen::Vector3i(1, 3, 2));
  EXPECT_EQ(report.skipped_primitives, 0u);
}

// ---- oddities that are counted and kept ------------------------------------------------------

// In the file's 1-based numbering: vertex 4 repeats vertex 2's position (a duplicate), vertex 5 is
// used by no face (unreferenced), the third face has collinear corners and the fourth a repeated
// corner (both degenerate).
TEST(MeshIo, DegenerateTrianglesDuplicateAndUnreferencedVerticesAreCountedAndKept) {
  MeshReport report;
  const TriangleMesh mesh = load(writeTemp("odd.obj",
                                           "v 0 0 0\n"
                                           "v 1 0 0\n"
                                           "v 0 1 0\n"
                                           "v 1 0 0\n"
                                           "v 5 5 5\n"
                                           "v 2 0 0\n"
                                           "f 1 2 3\n"
                                           "f 4 3 1\n"
                                           "f 1 2 6\n"
                                           "f 1 3 3\n"),
                                 &report);
  ASSERT_EQ(mesh.vertexCount(), 6u);
  ASSERT_EQ(mesh.triangleCount(), 4u);
  EXPECT_EQ(mesh.triangles.col(1), Eigen::Vector3i(3, 2, 0));  // the duplicate is kept, not merged
  EXPECT_EQ(mesh.triangles.col(2), Eigen::Vector3i(0, 1, 5));
  EXPECT_EQ(mesh.triangles.col(3), Eigen::Vector3i(0, 2, 2));
  EXPECT_EQ(report.triangles, 4u);
  EXPECT_EQ(report.vertices, 6u);
  EXPECT_EQ(report.degenerate_triangles, 2u);
  EXPECT_EQ(report.duplicate_vertices, 1u);
  EXPECT_EQ(report.unreferenced_vertices, 1u);
  EXPECT_EQ(report.skipped_primitives, 0u);
  const std::string summary = report.summary();
  EXPECT_NE(summary.find("2 degenerate"), std::string::npos) << summary;
  EXPECT_NE(summary.find("1 duplicate vertices"), std::string::npos) << summary;
  EXPECT_NE(summary.find("1 unreferenced"), std::string::npos) << summary;
}

}  // namespace
}  // namespace collido
