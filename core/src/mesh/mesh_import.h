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

/// What must hold before CGAL's OFF reader may see a file, or "" when nothing is found: counts
/// the file holds, colours within the range CGAL converts them to, face sizes and indices that
/// are non-negative integers in range (CGAL's scanner meets undefined behaviour otherwise), no
/// binary colour data and no texture coordinates without colours (which it misreads).
std::string checkOffBeforeReading(const std::string& path);

/// What must hold before CGAL's PLY reader may see a file (a PLY header that is whole and known,
/// data that holds every declared element, non-negative list lengths, finite in-range coordinates
/// and indices in ASCII data), or "" when nothing is found. CGAL's reader crashes or throws on
/// such files, and gives no reason when it refuses one; assimp's PLY reader aborts or hangs on
/// them, so it is never asked for a second opinion.
std::string checkPlyBeforeReading(const std::string& path);

/// What is wrong with the layout of an STL file before any reader sees it: a binary file shorter
/// than its header or than the triangles its header declares, an ASCII file without 'endsolid';
/// "" when nothing is found (CGAL's reader then has the last word).
std::string diagnoseStl(const std::string& path);

/// The problem with coordinate `axis` (0, 1, 2) of vertex `vertex`, read as `value` from the text
/// `token`: non-finite, or beyond kMaxCoordinate; "" when it is fine.
std::string coordinateProblem(long long vertex, int axis, double value, const std::string& token);

}  // namespace collido::detail
