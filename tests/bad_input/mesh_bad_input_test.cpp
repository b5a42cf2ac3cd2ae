// Bad mesh files, one test per case. Each asserts kInvalidArgument and a message that names the
// file and the problem; the comment above each test shows the message users get (paths
// shortened to <dir>).
#include <collido/mesh/mesh_io.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "bad_input/rejection.h"
#include "support/test_paths.h"

namespace collido {
namespace {

using test::rejected;

/// Writes `contents` as `name` into a fresh temporary folder and returns its path.
std::string writeTemp(const std::string& name, const std::string& contents) {
  std::string path = test::makeTempDirectory("bad_mesh") + "/" + name;
  test::writeFile(path, contents);
  return path;
}

constexpr const char* kTriangleVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

// ---- the file itself -------------------------------------------------------------------------

// "<dir>/absent.obj: file not found"
TEST(MeshBadInput, MissingFile) {
  const std::string path = test::makeTempDirectory("bad_mesh") + "/absent.obj";
  EXPECT_TRUE(rejected(loadMesh(path), {path, "not found"}));
}

// "<dir>/folder.obj: not a regular file"
TEST(MeshBadInput, DirectoryInsteadOfFile) {
  const std::string path = test::makeTempDirectory("bad_mesh") + "/folder.obj";
  std::filesystem::create_directory(path);
  EXPECT_TRUE(rejected(loadMesh(path), {path, "not a regular file"}));
}

// "<dir>/empty.obj: the file is empty"
TEST(MeshBadInput, EmptyFile) {
  const std::string path = writeTemp("empty.obj", "");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "empty"}));
}

// Blank lines only count as empty too.
TEST(MeshBadInput, BlankFile) {
  const std::string path = writeTemp("blank.obj", "\n  \n\t\r\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "empty"}));
}

// "<dir>/garbage.obj: byte 145 is 0x00: binary data, but OBJ is a text format"
TEST(MeshBadInput, BinaryGarbageWithObjExtension) {
  std::string garbage;
  for (int i = 0; i < 512; ++i)
    garbage.push_back(static_cast<char>((i * 37 + 11) % 256));
  const std::string path = writeTemp("garbage.obj", garbage);
  EXPECT_TRUE(rejected(loadMesh(path), {path, "binary", "OBJ is a text format"}));
}

// Binary bytes without a NUL reach CGAL's reader, which quotes the line it cannot read; the
// quote comes back as printable ASCII, so a message never carries raw bytes (which broke the
// XML test report before):
// "<dir>/noise.obj: cannot read it as OBJ (CGAL's reader: error: unrecognized line: ???...)"
TEST(MeshBadInput, BinaryNoiseWithoutNulIsQuotedPrintably) {
  std::string noise = "v 0 0 0\n";
  for (int i = 0; i < 600; ++i)
    noise.push_back(static_cast<char>(0x80 + (i * 7) % 0x80));
  const std::string path = writeTemp("noise.obj", noise);
  const Result<TriangleMesh> mesh = loadMesh(path);
  ASSERT_TRUE(rejected(mesh, {path, "OBJ"}));
  const std::string& message = mesh.status().message();
  EXPECT_TRUE(std::all_of(message.begin(), message.end(), [](char c) {
    return c >= ' ' && c <= '~';
  })) << message;
  EXPECT_LT(message.size(), path.size() + 300);
}

// The content is a valid OBJ triangle, which assimp would guess from the text; the name decides:
// "<dir>/mesh.unknownformat: unknown mesh format '.unknownformat' (neither CGAL's obj/off/ply/stl
//  readers nor assimp read this extension)"
TEST(MeshBadInput, UnknownExtension) {
  const std::string path =
      writeTemp("mesh.unknownformat", std::string(kTriangleVertices) + "f 1 2 3\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "unknown mesh format '.unknownformat'"}));
}

// "<dir>/mesh: no file extension, so no known mesh format"
TEST(MeshBadInput, NoExtension) {
  const std::string path = writeTemp("mesh", std::string(kTriangleVertices) + "f 1 2 3\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "no file extension"}));
}

// ---- coordinates -----------------------------------------------------------------------------

// "<dir>/nan.obj: line 2: vertex 1 has a non-finite y coordinate ('nan')"
TEST(MeshBadInput, NanCoordinate) {
  const std::string path = writeTemp("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 2", "vertex 1", "non-finite y", "nan"}));
}

// "<dir>/inf.obj: line 3: vertex 2 has a non-finite z coordinate ('inf')"
TEST(MeshBadInput, InfCoordinate) {
  const std::string path = writeTemp("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 inf\nf 1 2 3\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 3", "vertex 2", "non-finite z", "inf"}));
}

// A number too large for a double is infinite, not silently clamped:
// "<dir>/overflow.obj: line 1: vertex 0 has a non-finite x coordinate ('1e400')"
TEST(MeshBadInput, CoordinateOverflowingDouble) {
  const std::string path = writeTemp("overflow.obj", "v 1e400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 1", "vertex 0", "non-finite x", "1e400"}));
}

// The bad number is named even when another coordinate would overflow a float (assimp, which
// reads in float32, would blame the 1e300 instead):
// "<dir>/mixed.obj: line 1: vertex 0 has a non-finite y coordinate ('nan')"
TEST(MeshBadInput, NanBesideAHugeCoordinate) {
  const std::string path = writeTemp("mixed.obj", "v 1e300 nan 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "vertex 0", "non-finite y", "nan"}));
}

// "<dir>/nan.off: line 4: vertex 1 has a non-finite y coordinate ('nan')"
TEST(MeshBadInput, OffNanCoordinate) {
  const std::string path = writeTemp("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "vertex 1", "non-finite y"}));
}

// Huge but finite coordinates are valid geometry: they load, exactly.
TEST(MeshBadInput, HugeFiniteCoordinatesAreAccepted) {
  const std::string path = writeTemp(
      "huge.obj", "v 1e300 0 0\nv -1e300 1e300 0\nv 0 0 1.7976931348623157e308\nf 1 2 3\n");
  Result<TriangleMesh> mesh = loadMesh(path);
  ASSERT_TRUE(mesh.ok()) << mesh.status().toString();
  EXPECT_EQ(mesh.value().vertices(0, 0), 1e300);
  EXPECT_EQ(mesh.value().vertices(1, 1), 1e300);
  EXPECT_EQ(mesh.value().vertices(2, 2), 1.7976931348623157e308);
}

// ---- faces -----------------------------------------------------------------------------------

// "<dir>/index.obj: line 4: face 0 uses index 4, but the file has 3 vertices (OBJ indices are
//  1-based)"
TEST(MeshBadInput, FaceIndexOutOfRange) {
  const std::string path = writeTemp("index.obj", std::string(kTriangleVertices) + "f 1 2 4\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 4", "face 0", "index 4", "3 vertices"}));
}

// A face index far past the end gets the same message (CGAL's reader has no face or line to
// offer for it: "error: invalid face index"):
// "<dir>/far.obj: line 4: face 0 uses index 99, but the file has 3 vertices (OBJ indices are
//  1-based)"
TEST(MeshBadInput, FaceIndexFarOutOfRange) {
  const std::string path = writeTemp("far.obj", std::string(kTriangleVertices) + "f 1 2 99\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "face 0", "99", "3 vertices"}));
}

// The same in OFF, whose indices are 0-based (CGAL's OFF reader gives no reason at all):
// "<dir>/index.off: line 6: face 0 references vertex 3, but the file has 3 vertices (OFF indices
//  are 0-based)"
TEST(MeshBadInput, OffFaceIndexOutOfRange) {
  const std::string path = writeTemp("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  EXPECT_TRUE(
      rejected(loadMesh(path), {path, "line 6", "face 0", "references vertex 3", "3 vertices"}));
}

// OBJ indices start at 1; 0 is no vertex:
// "<dir>/zero.obj: line 4: face 0 uses index 0, but OBJ indices start at 1"
TEST(MeshBadInput, ObjIndexZero) {
  const std::string path = writeTemp("zero.obj", std::string(kTriangleVertices) + "f 0 1 2\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 4", "face 0", "index 0", "start at 1"}));
}

// Index 0 with a vertex after the face: still invalid. (CGAL's reader takes 0 as a relative
// reference, i.e. the next vertex, and loaded this file as the triangle (5,5,5) (0,0,0) (1,0,0).)
TEST(MeshBadInput, ObjIndexZeroBeforeLaterVertices) {
  const std::string path =
      writeTemp("zero_later.obj", std::string(kTriangleVertices) + "f 0 1 2\nv 5 5 5\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 4", "face 0", "index 0", "start at 1"}));
}

// -4 reaches before the first of the 3 vertices that precede the face:
// "<dir>/negative.obj: line 4: face 0 uses relative index -4, but only 3 vertices precede it"
TEST(MeshBadInput, ObjNegativeIndexBeforeTheStart) {
  const std::string path =
      writeTemp("negative.obj", std::string(kTriangleVertices) + "f -1 -2 -4\n");
  EXPECT_TRUE(rejected(loadMesh(path),
                       {path, "line 4", "face 0", "relative index -4", "only 3 vertices precede"}));
}

// Relative indices count the vertices before the face, not the whole file: -4 is out of range
// here although the file has 4 vertices.
TEST(MeshBadInput, ObjNegativeIndexCountsOnlyEarlierVertices) {
  const std::string path =
      writeTemp("negative_later.obj", std::string(kTriangleVertices) + "f -1 -2 -4\nv 5 5 5\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "face 0", "relative index -4"}));
}

// A face must not end silently at a token that is no index (CGAL's reader stops reading the face
// there and keeps what it has):
// "<dir>/malformed.obj: line 4: face 0 has a malformed vertex index 'x'"
TEST(MeshBadInput, ObjMalformedFaceIndex) {
  const std::string path =
      writeTemp("malformed.obj", std::string(kTriangleVertices) + "f 1 2 x 3\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 4", "face 0", "malformed", "'x'"}));
}

// Negative indices within range are relative references, and valid: -1 is the last vertex so far.
TEST(MeshBadInput, ObjNegativeIndicesWithinRangeAreAccepted) {
  const std::string path =
      writeTemp("relative.obj", std::string(kTriangleVertices) + "f -3 -2 -1\nv 5 5 5\n");
  Result<TriangleMesh> mesh = loadMesh(path);
  ASSERT_TRUE(mesh.ok()) << mesh.status().toString();
  EXPECT_EQ(mesh.value().triangles.col(0), Eigen::Vector3i(0, 1, 2));
}

// "<dir>/points.obj: no faces ('f' lines) in the file, so no triangles (3 vertices)"
TEST(MeshBadInput, VerticesButNoFaces) {
  const std::string path = writeTemp("points.obj", kTriangleVertices);
  EXPECT_TRUE(rejected(loadMesh(path), {path, "no faces", "3 vertices"}));
}

// A face with two indices is a line: skipped and counted, the triangles load.
TEST(MeshBadInput, TwoIndexFaceIsSkippedAndCounted) {
  const std::string path =
      writeTemp("line.obj", std::string(kTriangleVertices) + "f 1 2\nf 1 2 3\n");
  MeshReport report;
  Result<TriangleMesh> mesh = loadMesh(path, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.status().toString();
  EXPECT_EQ(mesh.value().triangleCount(), 1u);
  EXPECT_EQ(mesh.value().triangles.col(0), Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(report.skipped_primitives, 1u);
}

// OBJ's own line ('l') and point ('p') elements are not surfaces either: skipped and counted.
TEST(MeshBadInput, ObjLineAndPointElementsAreSkippedAndCounted) {
  const std::string path =
      writeTemp("polyline.obj", std::string(kTriangleVertices) + "l 1 2 3\np 1\nf 1 2 3\n");
  MeshReport report;
  Result<TriangleMesh> mesh = loadMesh(path, &report);
  ASSERT_TRUE(mesh.ok()) << mesh.status().toString();
  EXPECT_EQ(mesh.value().triangleCount(), 1u);
  EXPECT_EQ(report.skipped_primitives, 2u);
}

// "<dir>/lines.obj: the mesh has no triangles"
TEST(MeshBadInput, OnlyTwoIndexFacesIsAnError) {
  const std::string path =
      writeTemp("lines.obj", std::string(kTriangleVertices) + "f 1 2\nf 2 3\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "no triangles"}));
}

}  // namespace
}  // namespace collido
