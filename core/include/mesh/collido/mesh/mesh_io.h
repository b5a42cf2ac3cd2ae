#pragma once

#include <string>

#include <collido/mesh/mesh_report.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/status.h>

namespace collido {

/// Reads a mesh file into one triangle mesh, in file order (vertex i and triangle j of the file
/// are column i and j), validates it and fills `report` when given.
///
/// OBJ, OFF, PLY and STL go through our own strict readers, which keep the file's precision;
/// every other format assimp reads (glTF/GLB, DAE, 3DS, FBX, ...) goes through assimp, whose
/// Debian build stores coordinates as 32-bit floats (report->single_precision says so). Faces
/// with more than three corners are fan-triangulated and counted; points and lines are skipped
/// and counted. Errors (missing or empty file, parse failure, a file cut short, NaN/Inf or a
/// coordinate beyond kMaxCoordinate, out-of-range index, no triangles) name the file and the
/// problem, and the line, vertex or face where the format has them.
Result<TriangleMesh> loadMesh(const std::string& path, MeshReport* report = nullptr);

}  // namespace collido
