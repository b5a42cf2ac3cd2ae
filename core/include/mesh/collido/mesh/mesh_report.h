#pragma once

#include <cstddef>
#include <string>

#include <collido/mesh/triangle_mesh.h>

namespace collido {

/// What import found in a mesh: counts of the legitimate oddities that are kept, and how the
/// coordinates were read.
struct MeshReport {
  std::string source;             ///< file path or generator description
  std::string importer;           ///< which reader produced the mesh
  bool single_precision = false;  ///< coordinates passed through 32-bit floats on import
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t degenerate_triangles = 0;   ///< zero area (collinear or repeated corners), exact test
  std::size_t duplicate_vertices = 0;     ///< vertices at exactly the position of an earlier one
  std::size_t unreferenced_vertices = 0;  ///< vertices no triangle uses
  std::size_t polygons_triangulated = 0;  ///< faces with more than 3 corners, fan-triangulated
  std::size_t skipped_primitives = 0;     ///< points and lines in the file, not surfaces

  /// One line for people: "bunny.obj: 3674 triangles, 1839 vertices, 0 degenerate, ...".
  std::string summary() const;
};

/// Counts degenerate triangles (exactly, with exact predicates), duplicate and unreferenced
/// vertices of a valid mesh into `report` (other fields are left as they are).
void inspectMesh(const TriangleMesh& mesh, MeshReport& report);

}  // namespace collido
