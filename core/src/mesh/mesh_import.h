#pragma once

// Private to core/src/mesh: the pieces of mesh import shared by its files.

#include <string>

#include <collido/mesh/mesh_report.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/status.h>

namespace collido::detail {

/// A mesh as read, with what the reader found.
struct Imported {
  TriangleMesh mesh;
  MeshReport report;
};

/// kInvalidArgument with "<path>: <problem>".
inline Status readError(const std::string& path, const std::string& problem) {
  return {StatusCode::kInvalidArgument, path + ": " + problem};
}

/// The strict readers, one file each: errors name the file, the line (text formats) and the
/// vertex or face with the text as written.
Result<Imported> readObj(const std::string& path);
Result<Imported> readOff(const std::string& path);
Result<Imported> readPly(const std::string& path);
Result<Imported> readStl(const std::string& path);

/// Any format assimp reads, in single precision (Debian's assimp uses 32-bit floats).
Result<Imported> readWithAssimp(const std::string& path);

/// A token quoted back in a message, made printable and short (a binary file may hold anything).
std::string printable(const std::string& token);

/// The problem with coordinate `axis` (0, 1, 2) of vertex `vertex`, read as `value` from the text
/// `token`: non-finite, or beyond kMaxCoordinate; "" when it is fine.
std::string coordinateProblem(long long vertex, int axis, double value, const std::string& token);

}  // namespace collido::detail
