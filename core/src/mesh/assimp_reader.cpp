// assimp, for the formats CGAL does not read (glTF/GLB, DAE, 3DS, FBX, ...).
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "mesh_import.h"

namespace collido::detail {

Result<Imported> readWithAssimp(const std::string& path) {
  Assimp::Importer importer;
  // No vertex joining or cleaning: duplicates and degenerate triangles are test input.
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_PreTransformVertices |
                                  aiProcess_ValidateDataStructure);
  if (scene == nullptr) {
    return readError(path, std::string("assimp cannot import it: ") + importer.GetErrorString());
  }
  Imported out;
  out.report.importer = "assimp";
  out.report.single_precision = true;
  std::size_t vertex_total = 0;
  std::size_t triangle_total = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    vertex_total += scene->mMeshes[m]->mNumVertices;
    for (unsigned f = 0; f < scene->mMeshes[m]->mNumFaces; ++f) {
      triangle_total += scene->mMeshes[m]->mFaces[f].mNumIndices == 3 ? 1 : 0;
    }
  }
  out.mesh.vertices.resize(3, static_cast<Eigen::Index>(vertex_total));
  out.mesh.triangles.resize(3, static_cast<Eigen::Index>(triangle_total));
  Eigen::Index v_base = 0;
  Eigen::Index t_next = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      out.mesh.vertices.col(v_base + v) << mesh.mVertices[v].x, mesh.mVertices[v].y,
          mesh.mVertices[v].z;
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) {
        ++out.report.skipped_primitives;
        continue;
      }
      for (int k = 0; k < 3; ++k) {
        out.mesh.triangles(k, t_next) = static_cast<int>(v_base + face.mIndices[k]);
      }
      ++t_next;
    }
    v_base += mesh.mNumVertices;
  }
  return out;
}

}  // namespace collido::detail
