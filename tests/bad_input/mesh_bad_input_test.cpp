// Bad mesh files, one test per case. Each asserts kInvalidArgument and a message that names the
// file and the problem; the comment above each test shows the message users get (paths
// shortened to <dir>).
#include <collido/mesh/mesh_io.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

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

// ---- binary files, byte by byte (little-endian, as binary STL and binary_little_endian PLY) ----

void appendUint32(std::string& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i)
    out.push_back(static_cast<char>((value >> (8 * i)) & 0xffu));
}

void appendFloat(std::string& out, float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  appendUint32(out, bits);
}

using Corner = std::array<float, 3>;
using Face = std::array<std::int32_t, 3>;

/// A binary STL of `triangles` whose header declares `declared` triangles (default: as many as
/// there are).
std::string binaryStl(const std::vector<std::array<Corner, 3>>& triangles,
                      std::uint32_t declared = std::numeric_limits<std::uint32_t>::max()) {
  std::string out(80, '\0');
  appendUint32(out, declared == std::numeric_limits<std::uint32_t>::max()
                        ? static_cast<std::uint32_t>(triangles.size())
                        : declared);
  for (const auto& triangle : triangles) {
    for (float n : {0.0f, 0.0f, 1.0f})
      appendFloat(out, n);
    for (const Corner& corner : triangle) {
      for (float c : corner)
        appendFloat(out, c);
    }
    out += std::string(2, '\0');  // attribute byte count
  }
  return out;
}

/// Two triangles, six corners: (0,0,0) (1,0,0) (0,1,0) and (0,0,1) (1,0,1) (0,1,1).
std::vector<std::array<Corner, 3>> twoTriangles() {
  return {{Corner{0, 0, 0}, Corner{1, 0, 0}, Corner{0, 1, 0}},
          {Corner{0, 0, 1}, Corner{1, 0, 1}, Corner{0, 1, 1}}};
}

/// A binary_little_endian PLY with float x, y, z and uchar-counted int vertex_indices.
std::string binaryPly(const std::vector<Corner>& vertices, const std::vector<Face>& faces) {
  std::string out =
      "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices.size()) +
      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
      std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Corner& v : vertices) {
    for (float c : v)
      appendFloat(out, c);
  }
  for (const Face& f : faces) {
    out.push_back(3);
    for (std::int32_t index : f)
      appendUint32(out, static_cast<std::uint32_t>(index));
  }
  return out;
}

/// A unit tetrahedron's corners, and two of its faces.
const std::vector<Corner> kTetCorners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<Face> kTwoFaces = {{0, 1, 2}, {0, 1, 3}};

/// The header of an ASCII PLY with `vertices` vertices (x, y, z) and `faces` faces.
std::string asciiPlyHeader(int vertices, int faces) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

// The well-formed files the cases below break load, whole: what fails is the break.
TEST(MeshBadInput, TheUnbrokenBinaryFilesLoad) {
  const std::string stl = writeTemp("two.stl", binaryStl(twoTriangles()));
  Result<TriangleMesh> mesh = loadMesh(stl);
  ASSERT_TRUE(mesh.ok()) << mesh.status().toString();
  EXPECT_EQ(mesh.value().triangleCount(), 2u);
  const std::string ply = writeTemp("two.ply", binaryPly(kTetCorners, kTwoFaces));
  mesh = loadMesh(ply);
  ASSERT_TRUE(mesh.ok()) << mesh.status().toString();
  EXPECT_EQ(mesh.value().triangleCount(), 2u);
  EXPECT_EQ(mesh.value().triangles.col(1), Eigen::Vector3i(0, 1, 3));
  const std::string ascii =
      writeTemp("tri.ply", asciiPlyHeader(3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  mesh = loadMesh(ascii);
  ASSERT_TRUE(mesh.ok()) << mesh.status().toString();
  EXPECT_EQ(mesh.value().triangleCount(), 1u);
}

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

// An empty file of any format says so: "<dir>/empty.stl: the file is empty"
TEST(MeshBadInput, EmptyFileOfEveryFormat) {
  for (const char* name : {"empty.stl", "empty.ply", "empty.off", "empty.gltf"}) {
    const std::string path = writeTemp(name, "");
    EXPECT_TRUE(rejected(loadMesh(path), {path, "the file is empty"})) << name;
  }
}

// "<dir>/garbage.obj: byte 145 is 0x00: binary data, but OBJ is a text format"
TEST(MeshBadInput, BinaryGarbageWithObjExtension) {
  std::string garbage;
  for (int i = 0; i < 512; ++i)
    garbage.push_back(static_cast<char>((i * 37 + 11) % 256));
  const std::string path = writeTemp("garbage.obj", garbage);
  EXPECT_TRUE(rejected(loadMesh(path), {path, "binary", "OBJ is a text format"}));
}

// Binary bytes without a NUL start no OBJ statement; the message quotes them as printable ASCII,
// so it never carries raw bytes (which broke the XML test report before):
// "<dir>/noise.obj: line 2: '????????...' starts no OBJ statement"
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

// Binary STL has no magic number, so garbage reads as a header declaring some count of
// triangles that the file cannot hold:
// "<dir>/garbage.stl: binary STL cut short: its header declares 182829211 triangles (9141460634
//  bytes), but the file has 512 bytes, room for 8"
TEST(MeshBadInput, BinaryGarbageAsStl) {
  std::string garbage;
  for (int i = 0; i < 512; ++i)
    garbage.push_back(static_cast<char>((i * 37 + 11) % 256));
  const std::string path = writeTemp("garbage.stl", garbage);
  EXPECT_TRUE(rejected(loadMesh(path), {path, "binary STL cut short", "declares 182829211"}));
}

// "<dir>/garbage.ply: not a PLY file (it does not start with a 'ply' line)"
TEST(MeshBadInput, BinaryGarbageAsPly) {
  std::string garbage;
  for (int i = 0; i < 512; ++i)
    garbage.push_back(static_cast<char>((i * 37 + 11) % 256));
  const std::string path = writeTemp("garbage.ply", garbage);
  EXPECT_TRUE(rejected(loadMesh(path), {path, "not a PLY file"}));
}

// ---- truncated files -------------------------------------------------------------------------

// The second triangle lost its last 30 bytes:
// "<dir>/cut.stl: binary STL cut short: its header declares 2 triangles (184 bytes), but the
//  file has 154 bytes, room for 1"
TEST(MeshBadInput, TruncatedBinaryStl) {
  const std::string whole = binaryStl(twoTriangles());
  const std::string path = writeTemp("cut.stl", whole.substr(0, whole.size() - 30));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "binary STL cut short", "declares 2 triangles",
                                        "154 bytes", "room for 1"}));
}

// Cut inside the 84-byte header (not a valid file of no triangles):
// "<dir>/stub.stl: too short for a binary STL: 40 bytes, but its header and triangle count alone
//  take 84"
TEST(MeshBadInput, BinaryStlShorterThanItsHeader) {
  const std::string path = writeTemp("stub.stl", binaryStl(twoTriangles()).substr(0, 40));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "too short for a binary STL", "40 bytes", "84"}));
}

// "<dir>/cut_ascii.stl: ASCII STL without an 'endsolid' line: the file is truncated"
TEST(MeshBadInput, TruncatedAsciiStl) {
  const std::string path = writeTemp(
      "cut_ascii.stl",
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "ASCII STL", "'endsolid'", "truncated"}));
}

// The last face lost 7 of its 13 bytes (assimp's second opinion called it an index out of range):
// "<dir>/cut.ply: the file ends early: the data stops in 'face' 1 (0-based) of the 2 that the
//  header declares"
TEST(MeshBadInput, TruncatedBinaryPly) {
  const std::string whole = binaryPly(kTetCorners, kTwoFaces);
  const std::string path = writeTemp("cut.ply", whole.substr(0, whole.size() - 7));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "ends early", "'face' 1", "of the 2"}));
}

// Regression: assimp's second opinion on this file aborted the whole process
// (ai_assert in TriangulateProcess.cpp):
// "<dir>/cut_ascii.ply: the file ends early: the data stops in 'vertex' 2 (0-based) of the 3 that
//  the header declares"
TEST(MeshBadInput, TruncatedAsciiPly) {
  const std::string path = writeTemp("cut_ascii.ply", asciiPlyHeader(3, 1) + "0 0 0\n1 0 0\n0 1\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "ends early", "'vertex' 2", "of the 3"}));
}

// Regression (found by mesh_import_fuzz): a list whose signed count reads -1 (CGAL's reader, used
// before, resized a vector to 2^64-1 elements and threw length_error out of loadMesh):
// "<dir>/negative_list.ply: 'face' 0: the list 'vertex_indices' has a negative length (-1)"
TEST(MeshBadInput, BinaryPlyNegativeListLength) {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list short int vertex_indices\nend_header\n";
  for (const Corner& v : {Corner{0, 0, 0}, Corner{1, 0, 0}, Corner{0, 1, 0}}) {
    for (float c : v)
      appendFloat(ply, c);
  }
  ply += std::string(2, '\xff');  // the short count: -1
  for (std::uint32_t index : {0u, 1u, 2u})
    appendUint32(ply, index);
  const std::string path = writeTemp("negative_list.ply", ply);
  EXPECT_TRUE(rejected(loadMesh(path), {path, "'face' 0", "'vertex_indices'", "negative length"}));
}

// Regression: assimp's second opinion on this file never returned (a header cut before its
// 'end_header' line):
// "<dir>/cut_header.ply: the header has no 'end_header' line (the file is truncated, or not PLY)"
TEST(MeshBadInput, PlyHeaderCutShort) {
  const std::string path =
      writeTemp("cut_header.ply", binaryPly(kTetCorners, kTwoFaces).substr(0, 60));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "no 'end_header' line", "truncated"}));
}

// "<dir>/cut.off: the file ends early: the header declares 2 faces, but the file ends after 1"
TEST(MeshBadInput, TruncatedOff) {
  const std::string path =
      writeTemp("cut.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "ends early", "2 faces", "ends after 1"}));
}

// Regression (found by mesh_import_fuzz): a few bytes declaring 225 million faces (CGAL's reader,
// used before, allocated 5 GB for them):
// "<dir>/huge_count.off: the file ends early: the header declares 0 vertices and 225525203 faces,
//  more than the 3 characters after it can hold"
TEST(MeshBadInput, OffCountsBeyondTheFile) {
  const std::string path = writeTemp("huge_count.off", "COFF\n#c\n 0 225525203 5 \x01");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "ends early", "225525203 faces", "characters"}));
  // The header's last count ends the file.
  const std::string header_only = writeTemp("header_only.off", "COFF\n# 4 \n50  11  21");
  EXPECT_TRUE(rejected(loadMesh(header_only),
                       {header_only, "ends early", "50 vertices", "11 faces", "the 0 characters"}));
}

// "<dir>/cut_face.off: line 8: face 1 lists 2 of its 3 vertex indices"
TEST(MeshBadInput, OffFaceCutShort) {
  const std::string path =
      writeTemp("cut_face.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 8", "face 1", "2 of its 3"}));
}

// The content is a valid OBJ triangle, which assimp would guess from the text; the name decides:
// "<dir>/mesh.unknownformat: unknown mesh format '.unknownformat' (neither our obj/off/ply/stl
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

// "<dir>/nan.stl: vertex 4 has a non-finite y coordinate (nan)"
TEST(MeshBadInput, BinaryStlNanCoordinate) {
  std::vector<std::array<Corner, 3>> triangles = twoTriangles();
  triangles[1][1][1] = std::numeric_limits<float>::quiet_NaN();
  const std::string path = writeTemp("nan.stl", binaryStl(triangles));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "vertex 4", "non-finite y"}));
}

// "<dir>/inf.stl: vertex 5 has a non-finite z coordinate (-inf)"
TEST(MeshBadInput, BinaryStlInfCoordinate) {
  std::vector<std::array<Corner, 3>> triangles = twoTriangles();
  triangles[1][2][2] = -std::numeric_limits<float>::infinity();
  const std::string path = writeTemp("inf.stl", binaryStl(triangles));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "vertex 5", "non-finite z", "inf"}));
}

// "<dir>/nan.ply: vertex 2 has a non-finite y coordinate (nan)"
TEST(MeshBadInput, BinaryPlyNanCoordinate) {
  std::vector<Corner> corners = kTetCorners;
  corners[2][1] = std::numeric_limits<float>::quiet_NaN();
  const std::string path = writeTemp("nan.ply", binaryPly(corners, kTwoFaces));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "vertex 2", "non-finite y"}));
}

// "<dir>/nan_ascii.ply: line 11: vertex 1 has a non-finite y coordinate ('nan')"
TEST(MeshBadInput, AsciiPlyNanCoordinate) {
  const std::string path =
      writeTemp("nan_ascii.ply", asciiPlyHeader(3, 1) + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 11", "vertex 1", "non-finite y", "'nan'"}));
}

// ---- huge coordinates: the limit |x| <= 1e18 (kMaxCoordinate, scenes/README.md) ---------------

// Past it, comparators answer wrong or do not finish; the loader refuses, naming line and vertex:
// "<dir>/huge.obj: line 2: vertex 1 has y coordinate '2e18', beyond the coordinate limit
//  |y| <= 1e18 (scenes/README.md)"
TEST(MeshBadInput, CoordinateBeyondTheLimit) {
  const std::string path = writeTemp("huge.obj", "v 0 0 0\nv 1 2e18 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 2", "vertex 1", "y coordinate '2e18'",
                                        "coordinate limit", "1e18"}));
}

// Far past the double range of a float (what assimp reads in) and close to the double maximum:
// "<dir>/huger.obj: line 3: vertex 2 has z coordinate '1.7976931348623157e308', beyond ..."
TEST(MeshBadInput, CoordinateNearTheDoubleMaximum) {
  const std::string path =
      writeTemp("huger.obj", "v 0 0 0\nv 1 0 0\nv 0 1 1.7976931348623157e308\nf 1 2 3\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 3", "vertex 2", "z coordinate", "1e18"}));
}

// The limit holds in every format; a text format names the line and quotes the number:
// "<dir>/huge.off: line 4: vertex 1 has y coordinate '-1e19', beyond the coordinate limit
//  |y| <= 1e18 (scenes/README.md)"
TEST(MeshBadInput, OffCoordinateBeyondTheLimit) {
  const std::string path = writeTemp("huge.off", "OFF\n3 1 0\n0 0 0\n1 -1e19 0\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(
      rejected(loadMesh(path), {path, "line 4", "vertex 1", "y coordinate '-1e19'", "1e18"}));
}

// A binary format has no text to quote; the mesh's vertex is named with its value:
// "<dir>/huge.stl: vertex 3 has x coordinate 1.0000000200408773e+20, beyond the coordinate limit
//  |x| <= 1e18 (scenes/README.md)"
TEST(MeshBadInput, BinaryStlCoordinateBeyondTheLimit) {
  std::vector<std::array<Corner, 3>> triangles = twoTriangles();
  triangles[1][0][0] = 1e20f;
  const std::string path = writeTemp("huge.stl", binaryStl(triangles));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "vertex 3", "x coordinate 1.00000002", "1e18"}));
}

// Up to the limit itself, coordinates load exactly.
TEST(MeshBadInput, CoordinatesAtTheLimitAreAccepted) {
  const std::string path =
      writeTemp("limit.obj", "v 1e18 0 0\nv -1e18 1e18 0\nv 0 0 -999999999999999872\nf 1 2 3\n");
  Result<TriangleMesh> mesh = loadMesh(path);
  ASSERT_TRUE(mesh.ok()) << mesh.status().toString();
  EXPECT_EQ(mesh.value().vertices(0, 0), 1e18);
  EXPECT_EQ(mesh.value().vertices(0, 1), -1e18);
  EXPECT_EQ(mesh.value().vertices(2, 2), -999999999999999872.0);
}

// ---- faces -----------------------------------------------------------------------------------

// "<dir>/index.obj: line 4: face 0 uses index 4, but the file has 3 vertices (OBJ indices are
//  1-based)"
TEST(MeshBadInput, FaceIndexOutOfRange) {
  const std::string path = writeTemp("index.obj", std::string(kTriangleVertices) + "f 1 2 4\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 4", "face 0", "index 4", "3 vertices"}));
}

// A face index far past the end gets the same message:
// "<dir>/far.obj: line 4: face 0 uses index 99, but the file has 3 vertices (OBJ indices are
//  1-based)"
TEST(MeshBadInput, FaceIndexFarOutOfRange) {
  const std::string path = writeTemp("far.obj", std::string(kTriangleVertices) + "f 1 2 99\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "face 0", "99", "3 vertices"}));
}

// The same in OFF, whose indices are 0-based:
// "<dir>/index.off: line 6: face 0 references vertex 3, but the file has 3 vertices (OFF indices
//  are 0-based integers)"
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

// Index 0 with a vertex after the face: still invalid. (CGAL's reader, used before, took 0 as a
// relative reference, i.e. the next vertex, and loaded this file as the triangle (5,5,5) (0,0,0)
// (1,0,0).)
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

// A face must not end silently at a token that is no index (CGAL's reader, used before, stopped
// reading the face there and kept what it had):
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

// A binary PLY's face is named by its element index:
// "<dir>/index.ply: face 1 references vertex 4 (0-based), but the file has 4 vertices"
TEST(MeshBadInput, PlyFaceIndexOutOfRange) {
  const std::string path = writeTemp("index.ply", binaryPly(kTetCorners, {{0, 1, 2}, {0, 1, 4}}));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "face 1", "references vertex 4", "4 vertices"}));
}

// "<dir>/negative.ply: face 1 references vertex -1 (0-based), but the file has 4 vertices"
TEST(MeshBadInput, PlyNegativeFaceIndex) {
  const std::string path =
      writeTemp("negative.ply", binaryPly(kTetCorners, {{0, 1, 2}, {0, -1, 3}}));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "face 1", "references vertex -1"}));
}

// The same in ASCII PLY:
// "<dir>/index_ascii.ply: face 0 references vertex 7 (0-based), but the file has 3 vertices"
TEST(MeshBadInput, AsciiPlyFaceIndexOutOfRange) {
  const std::string path =
      writeTemp("index_ascii.ply", asciiPlyHeader(3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "face 0", "references vertex 7", "3 vertices"}));
}

// "<dir>/none.stl: the mesh has no triangles"
TEST(MeshBadInput, BinaryStlOfNoTriangles) {
  const std::string path = writeTemp("none.stl", binaryStl({}));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "no triangles"}));
}

// "<dir>/points.ply: the mesh has no triangles"
TEST(MeshBadInput, PlyWithVerticesButNoFaces) {
  const std::string path = writeTemp("points.ply", binaryPly(kTetCorners, {}));
  EXPECT_TRUE(rejected(loadMesh(path), {path, "no triangles"}));
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

// ---- OFF colours and counts (CGAL's scanner, used before, converted them unchecked) -----------

// An integer colour is a byte:
// "<dir>/colour.off: line 4: vertex 1 has colour value 65025 out of range [0, 255]"
TEST(MeshBadInput, OffColourOutOfRange) {
  const std::string path = writeTemp(
      "colour.off", "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 65025 0\n0 1 0 0 0 255\n3 0 1 2\n");
  EXPECT_TRUE(rejected(
      loadMesh(path), {path, "line 4", "vertex 1", "colour value 65025", "out of range [0, 255]"}));
}

// A colour with a fraction is read as fractions of 1:
// "<dir>/fraction.off: line 6: face 0 has colour value 255 out of range [0, 1] (a colour with a
//  fraction is read as fractions)"
TEST(MeshBadInput, CoffFloatColourOutOfRange) {
  const std::string path =
      writeTemp("fraction.off", "COFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0.5 0\n");
  EXPECT_TRUE(rejected(loadMesh(path),
                       {path, "line 6", "face 0", "colour value 255", "out of range [0, 1]"}));
}

// One number is an index into a colour map; a negative one is none:
// "<dir>/map.off: line 6: face 0 has colour-map index -1, out of range [0, 2147483647]"
TEST(MeshBadInput, OffColourMapIndexOutOfRange) {
  const std::string path = writeTemp("map.off", "COFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 -1\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 6", "face 0", "colour-map index -1"}));
}

// Two numbers are no colour (the fuzzer's reproducer; CGAL's scanner read a third past the line):
// "<dir>/two.off: line 3: vertex 0 has 2 colour numbers; a colour is 1 (a colour-map index), 3 or
//  4 (RGB, RGBA)"
TEST(MeshBadInput, OffColourOfTwoNumbers) {
  const std::string path =
      writeTemp("two.off", "COFF\n3 1 0\n0 0 0 255 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 3", "vertex 0", "2 colour numbers"}));
}

// Binary vertex colours are laid out differently by different writers, so they are refused:
// "<dir>/binary.off: COFF BINARY: binary colour data is not read (writers disagree on its
//  layout); write the file as text, or without colours"
TEST(MeshBadInput, BinaryOffWithColoursIsRefused) {
  const std::string path =
      writeTemp("binary.off", std::string("COFF BINARY\n") + std::string(12, '\0') + "rest");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "COFF BINARY", "binary colour data"}));
}

// A face's vertex count is a non-negative integer:
// "<dir>/negative.off: line 6: face 0 has vertex count -3, not a non-negative integer"
TEST(MeshBadInput, OffNegativeFaceSize) {
  const std::string path = writeTemp("negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 6", "face 0", "vertex count -3"}));
}

// "<dir>/negative_index.off: line 6: face 0 references vertex -1, but the file has 3 vertices
//  (OFF indices are 0-based integers)"
TEST(MeshBadInput, OffNegativeFaceIndex) {
  const std::string path =
      writeTemp("negative_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 6", "face 0", "references vertex -1"}));
}

// 4OFF divides by the homogeneous w, which must not be 0:
// "<dir>/w.off: line 3: vertex 0 has homogeneous coordinate w = 0"
TEST(MeshBadInput, OffHomogeneousZero) {
  const std::string path = writeTemp("w.off", "4OFF\n3 1 0\n0 0 0 0\n1 0 0 1\n0 1 0 1\n3 0 1 2\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 3", "vertex 0", "w = 0"}));
}

// A coloured OFF file within the ranges loads (colours are ignored):
TEST(MeshBadInput, OffColoursInRangeAreAccepted) {
  const std::string path =
      writeTemp("colours.off",
                "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 1 0 0.5\n0 1 0 7\n3 0 1 2 0.5 0.25 1 1\n");
  Result<TriangleMesh> mesh = loadMesh(path);
  ASSERT_TRUE(mesh.ok()) << mesh.status().message();
  EXPECT_EQ(mesh.value().triangles.cols(), 1);
}

// Coordinates may have any numeric type (CGAL's PLY reader, used before, read only float and
// double and failed an assertion on "property int32 z", the fuzzer's reproducer); an integer
// reads exactly.
TEST(MeshBadInput, PlyIntegerCoordinateLoads) {
  const std::string path = writeTemp(
      "int_z.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property int32 z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 -2147483648\n1 0 0\n0 1 2147483647\n3 0 1 2\n");
  Result<TriangleMesh> mesh = loadMesh(path);
  ASSERT_TRUE(mesh.ok()) << mesh.status().message();
  EXPECT_EQ(mesh.value().vertices(2, 0), -2147483648.0);
  EXPECT_EQ(mesh.value().vertices(2, 2), 2147483647.0);
}

// A value that does not fit its declared type is refused, naming the line and the property:
// "<dir>/range.ply: line 13: 'face' 0: the list 'vertex_indices' has no valid length ('300')"
TEST(MeshBadInput, PlyValueOutsideItsType) {
  const std::string path =
      writeTemp("range.ply", asciiPlyHeader(3, 1) + "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n");
  EXPECT_TRUE(rejected(loadMesh(path), {path, "line 13", "'face' 0", "no valid length ('300')"}));
}

}  // namespace
}  // namespace collido
