#pragma once

// Private to core/src/mesh: the pieces of mesh import shared by its files.

#include <cstddef>
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

/// Any format assimp reads, in single precision (Debian's assimp uses 32-bit floats).
Result<Imported> readWithAssimp(const std::string& path);

/// A token quoted back in a message, made printable and short (a binary file may hold anything).
std::string printable(const std::string& token);

/// What CGAL's OBJ reader is given after checkObjText: every 'f' line reduced to its vertex
/// indices ("f 1/2/3\t4//6" -> "f 1 4"; after an index CGAL skips to the next space, so a tab
/// would swallow the rest of the face), and every 'l' (polyline) and 'p' (point) line blanked
/// out and counted: they are legal OBJ but not surfaces, and CGAL rejects 'l'.
struct ObjText {
  std::string text;
  std::size_t skipped_primitives = 0;
};

/// Checks an OBJ file's text before CGAL reads it; see text_format_checks.cpp.
Result<ObjText> checkObjText(const std::string& path);

/// Why CGAL's OFF reader refused a plain ASCII OFF file, or "" when no reason is found.
std::string diagnoseOff(const std::string& path);

}  // namespace collido::detail
